"""The package's types: the stubs of the compiled module (_amrstream.pyi) against the module.

mypy's stubtest checks that every public name, class, method and property exists on both sides
(and type-checks the pure-Python files); for compiled functions it cannot read the parameters,
so they are compared here with the signature line pybind11 writes: names, order, keyword-only
and defaults. Every public function, class, method and property has a docstring that says more
than its signature.
"""
import ast
import inspect
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import amrstream
from amrstream import _amrstream

HERE = Path(__file__).parent
STUB = Path(_amrstream.__file__).with_name("_amrstream.pyi")


def test_stubs_and_type_marker_ship_with_the_package():
    assert STUB.is_file()
    assert STUB.with_name("py.typed").is_file()


def test_stubtest_finds_no_difference():
    env = dict(os.environ)
    package_dir = Path(amrstream.__file__).parent.parent
    if package_dir.name != "site-packages":  # the build tree's: mypy is told where it is
        env.update(MYPYPATH=str(package_dir), PYTHONPATH=str(package_dir))
    result = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "amrstream", "--mypy-config-file",
         str(HERE.parent.parent / "pyproject.toml"), "--allowlist",
         str(HERE / "stubtest_allowlist.txt")],
        env=env, capture_output=True, text=True, cwd="/")
    assert result.returncode == 0, result.stdout + result.stderr


def runtime_parameters(function):
    """[(name, keyword_only, default or NO_DEFAULT)] from pybind11's signature line."""
    line = function.__doc__.splitlines()[0]
    inside = line[line.index("(") + 1:line.rindex(") ->")]
    parameters, keyword_only = [], False
    for part in top_level_parts(inside):
        if part == "*":
            keyword_only = True
            continue
        name = part.split(":")[0].strip()
        if name in ("self", "**kwargs"):
            continue
        default = part.split(" = ", 1)[1] if " = " in part else None
        parameters.append((name, keyword_only, literal(default)))
    return parameters


NO_DEFAULT = object()


def top_level_parts(text):
    """`text` split at the commas outside brackets and parentheses."""
    parts, depth, start = [], 0, 0
    for i, c in enumerate(text):
        depth += c in "([{"
        depth -= c in ")]}"
        if c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    parts.append(text[start:].strip())
    return [p for p in parts if p]


def literal(text):
    if text is None:
        return NO_DEFAULT
    try:
        return ast.literal_eval(text)
    except ValueError:
        return text


def stub_functions():
    """{qualified name: ast.FunctionDef} of the stub's functions and methods."""
    tree = ast.parse(STUB.read_text())
    found = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            found[node.name] = node
        elif isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, ast.FunctionDef) and not any(
                        isinstance(d, ast.Name) and d.id == "property" for d in item.decorator_list):
                    found[f"{node.name}.{item.name}"] = item
    return found


def stub_parameters(node):
    args = node.args
    positional = args.posonlyargs + args.args
    defaults = [NO_DEFAULT] * (len(positional) - len(args.defaults)) + [
        ast.literal_eval(d) for d in args.defaults]
    parameters = [(a.arg, False, d) for a, d in zip(positional, defaults) if a.arg != "self"]
    parameters += [(a.arg, True, NO_DEFAULT if d is None else ast.literal_eval(d))
                   for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    return parameters


def compiled_functions():
    for name, value in vars(_amrstream).items():
        if name.startswith("_"):
            continue
        if inspect.isclass(value):
            for member, attribute in vars(value).items():
                if callable(attribute) and (not member.startswith("_") or member in (
                        "__len__", "__getitem__")) and not isinstance(attribute, property):
                    yield f"{name}.{member}", attribute
        elif callable(value):
            yield name, value


@pytest.mark.parametrize("name, function", list(compiled_functions()))
def test_stub_parameters_are_the_module_s(name, function):
    stubs = stub_functions()
    assert name in stubs, f"{name} has no stub"
    if name == "Traces.render":  # **look: the settings the docstring lists
        return
    assert stub_parameters(stubs[name]) == runtime_parameters(function), name


def public_objects():
    for name in amrstream.__all__:
        value = getattr(amrstream, name)
        yield name, value
        if inspect.isclass(value) and value.__module__.startswith("amrstream"):
            for member, attribute in vars(value).items():
                if not member.startswith("_"):
                    yield f"{name}.{member}", attribute


def described(doc):
    """The docstring without pybind11's signature lines."""
    lines = [line for line in (doc or "").splitlines()
             if not re.match(r"^\w+\(.*\) -> ", line) and line.strip()]
    return " ".join(lines)


@pytest.mark.parametrize("name, value", list(public_objects()))
def test_every_public_name_has_a_docstring(name, value):
    doc = value.__doc__ if not isinstance(value, property) else (value.__doc__ or
                                                                 value.fget.__doc__)
    assert len(described(doc)) >= 10, f"{name} has no docstring beyond its signature: {doc!r}"
