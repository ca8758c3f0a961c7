"""conescope/__init__.pyi against the module: every public name typed, every signature the real one."""

import ast
import inspect
from pathlib import Path

import pytest

import conescope

STUB = Path(__file__).resolve().parent.parent / "conescope" / "__init__.pyi"


def stub_definitions():
    tree = ast.parse(STUB.read_text())
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            names[node.target.id] = node
    return names


def stub_parameters(function):
    """(name, kind, default as text) of a stubbed function, in order."""
    arguments = function.args
    positional = arguments.posonlyargs + arguments.args
    defaults = [None] * (len(positional) - len(arguments.defaults)) + arguments.defaults
    result = [(a.arg, "POSITIONAL_OR_KEYWORD", None if d is None else ast.literal_eval(d))
              for a, d in zip(positional, defaults)]
    if arguments.vararg:
        result.append((arguments.vararg.arg, "VAR_POSITIONAL", None))
    result += [(a.arg, "KEYWORD_ONLY", None if d is None else ast.literal_eval(d))
               for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)]
    if arguments.kwarg:
        result.append((arguments.kwarg.arg, "VAR_KEYWORD", None))
    return result


def real_parameters(function):
    return [(p.name, p.kind.name, None if p.default is inspect.Parameter.empty else p.default)
            for p in inspect.signature(function).parameters.values()]


def test_every_public_name_is_in_the_stub():
    missing = [name for name in conescope.__all__ if name not in stub_definitions()]
    assert not missing, f"not in {STUB.name}: {missing}"


@pytest.mark.parametrize("name", [n for n in conescope.__all__ if inspect.isfunction(getattr(conescope, n))])
def test_stubbed_signature_matches_the_function(name):
    assert stub_parameters(stub_definitions()[name]) == real_parameters(getattr(conescope, name))


@pytest.mark.parametrize("name", [n for n in conescope.__all__ if inspect.isclass(getattr(conescope, n))])
def test_stubbed_exception_has_the_real_bases(name):
    stubbed = [base.id for base in stub_definitions()[name].bases]
    assert stubbed == [base.__name__ for base in getattr(conescope, name).__bases__]


def test_the_stub_is_valid_python_with_its_annotations():
    compile(STUB.read_text(), str(STUB), "exec")
