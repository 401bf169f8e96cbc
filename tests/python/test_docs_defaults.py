"""docs/python.md's signatures of trace(), pathlines() and prepare() state the defaults the module has
(which it takes from the library's settings)."""
import ast
import pathlib
import re

import amrstream

DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"


def documented_defaults(call):
    """{keyword: default} of `call(...)` as docs/python.md writes it in backticks."""
    text = DOCS.read_text()
    start = text.index("`" + call + "(")
    signature = text[start + 1:text.index(")`", start)]
    defaults = {}
    for name, value in re.findall(r"(\w+)=([^,\n)]+)", signature):
        defaults[name] = ast.literal_eval(value)
    return defaults


def bound_defaults(function):
    """{keyword: default} of a pybind11 function, from its signature line."""
    first = function.__doc__.splitlines()[0]
    defaults = {}
    # A type may hold commas inside brackets: Optional[Dict[str, str]].
    for name, value in re.findall(r"(\w+): (?:[^=,\[]|\[[^\]]*\])+ = ('[^']*'|[^,)]+)", first):
        defaults[name] = ast.literal_eval(value)
    return defaults


def check(call, function):
    documented, bound = documented_defaults(call), bound_defaults(function)
    assert documented, f"docs/python.md has no signature of {call}"
    for name, value in documented.items():
        assert name in bound, f"{call}: docs/python.md names {name}, the module does not"
        if isinstance(value, float) or isinstance(bound[name], float):
            assert abs(float(bound[name]) - float(value)) <= 1e-6 * abs(float(value)), name
        else:
            assert bound[name] == value, f"{call}: {name} is {bound[name]!r}, the docs say {value!r}"


def test_trace_defaults_are_documented():
    check("trace", amrstream._amrstream.trace)


def test_pathlines_defaults_are_documented():
    check("pathlines", amrstream._amrstream.pathlines)


def test_prepare_defaults_are_documented():
    check("prepare", amrstream._amrstream.prepare)
