"""unyt and yt quantities where amrstream asks for a length or a position (seeds, boxes, max_length,
the camera's look_at and view_box, ...): converted to the dataset's coordinates, in the unit its
length_unit names ('cm', 'm'), or by length_unit_cm where the file states the centimetres in one
code unit. Plain numbers are taken as they are, in those coordinates."""

from typing import Any

import numpy


def has_units(value: Any) -> bool:
    """A unyt array or quantity (yt's included), or a sequence holding one."""
    if hasattr(value, "units") and hasattr(value, "to"):
        return True
    if isinstance(value, (list, tuple)):
        return any(has_units(item) for item in value)
    return False


def in_coordinates(value: Any, target: Any, what: str) -> Any:
    """`value` in the coordinates of `target` (a Dataset, Field or Traces): numbers as they are,
    quantities converted by its length_unit_cm, else by its length_unit."""
    if not has_units(value):
        return value
    if _dimensionless(value):
        return in_unit(value, "", what)
    length_unit = getattr(target, "length_unit", "")
    centimetres = getattr(target, "length_unit_cm", None)
    if centimetres:
        return in_unit(value, "cm", what, length_unit) / centimetres
    if not length_unit or length_unit.startswith("code units"):
        raise ValueError(
            f"{what} is given in {first_unit(value)}, but the dataset does not state the size "
            "of its length unit: load it with length_unit= (e.g. 'cm'), or give plain numbers "
            "in its coordinates")
    return in_unit(value, length_unit, what, length_unit)


def _dimensionless(value: Any) -> bool:
    if isinstance(value, (list, tuple)) and not hasattr(value, "units"):
        return all(_dimensionless(item) for item in value if has_units(item))
    return bool(value.units.is_dimensionless)


def in_unit(value: Any, unit: Any, what: str, length_unit: str = "") -> numpy.ndarray:
    """The numbers of a quantity, or of a sequence of quantities and numbers, in `unit`;
    dimensionless quantities and plain numbers as they are."""
    if isinstance(value, (list, tuple)):
        return numpy.array([in_unit(item, unit, what, length_unit) for item in value],
                           dtype=numpy.float64)
    if not has_units(value):
        return numpy.asarray(value, dtype=numpy.float64)
    if value.units.is_dimensionless:
        return numpy.asarray(value.d, dtype=numpy.float64)
    try:
        return numpy.asarray(value.to(unit).d, dtype=numpy.float64)
    except Exception as error:  # unyt's UnitConversionError and UnitParseError
        raise ValueError(f"{what} is given in {value.units}, which is not a length in "
                         f"{length_unit or unit!r}: {error}") from None


def first_unit(value: Any) -> Any:
    """The unit (unyt's Unit, with its registry) of the first quantity in `value`."""
    if hasattr(value, "units"):
        return value.units
    return next(first_unit(item) for item in value if has_units(item))


def with_unit(numbers: Any, unit: Any) -> Any:
    """`numbers` as a unyt array in `unit`."""
    import unyt

    return unyt.unyt_array(numbers, unit)
