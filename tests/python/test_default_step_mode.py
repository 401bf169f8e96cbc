"""The default step mode works for any units: the same rotation with its speed scaled by 100 or
1e5 (as cgs or code units would give) traces the same lines in the default `arc` mode, while
the paper's `cell` mode, whose step grows with the speed, spirals off the circles (x100) or
leaves the domain at the first step (x1e5)."""

import numpy as np

import amrstream


def _scaled_rotation(scale):
    ds = amrstream.load("builtin:rotation", levels=3, target_cells=50000)
    fields = {name: np.array(ds.field(name)) * (scale if name.startswith("vel") else 1.0)
              for name in ds.field_names}
    return amrstream.from_arrays(np.array(ds.corners), np.array(ds.levels), fields,
                                 origin=ds.origin, finest_width=ds.finest_width,
                                 source=f"rotation x{scale:g}")


SEEDS = np.array([[0.75, 0.5, 0.5], [0.5, 0.3, 0.45], [0.35, 0.6, 0.55]])


def _trace(dataset, **kwargs):
    return amrstream.trace(dataset, SEEDS, steps=400, direction="forward", backend="cpu",
                           point_data="none", **kwargs)


def test_default_arc_mode_traces_the_same_lines_whatever_the_units():
    reference = _trace(_scaled_rotation(1.0))
    assert (reference.steps == 400).all()  # circles: every line takes all its steps
    for scale in (100.0, 1e5):
        scaled = _trace(_scaled_rotation(scale))
        assert np.array_equal(scaled.steps, reference.steps)
        assert np.abs(scaled.points - reference.points).max() < 1e-5


def _radius_drift(traces):
    """The largest change of a line's distance to the rotation axis along it."""
    radius = np.linalg.norm(traces.points[:, :2] - 0.5, axis=1)
    off = traces.offsets
    return max(np.abs(radius[off[i]:off[i + 1]] - radius[off[i]]).max()
               for i in range(len(off) - 1))


def test_cell_mode_depends_on_the_units():
    arc = _radius_drift(_trace(_scaled_rotation(100.0)))
    cell = _trace(_scaled_rotation(100.0), step_mode="cell")
    assert _radius_drift(cell) > 10 * arc  # steps of 100 times the length spiral off the circles
    off = _trace(_scaled_rotation(1e5), step_mode="cell")
    assert (off.reasons == 1).all() and (off.steps == 0).all()  # the first step leaves the box
