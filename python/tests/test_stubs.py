"""The shipped .pyi stubs agree with the compiled module: every public name has a stub and
every stub a name; functions and methods have the same parameters in the same order (read from
the signatures pybind11 writes into each docstring)."""

import ast
import enum
import inspect
import pathlib

import pytest

import metricmap as mm
from metricmap import _metricmap

STUB = pathlib.Path(mm.__file__).with_name("__init__.pyi")


def split_top(text):
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur)
    return parts


def doc_params(obj, name):
    """Parameter names of the first docstring line `name(a: T, b: T = 1) -> R`."""
    line = (obj.__doc__ or "").lstrip().splitlines()[0]
    assert line.startswith(name + "("), f"{name}: no signature in its docstring: {line!r}"
    inner = line[len(name) + 1 : line.rindex(") ->")]
    return [p.split(":")[0].strip() for p in split_top(inner)]


def stub_params(fn):
    args = fn.args
    names = [a.arg for a in args.posonlyargs + args.args]
    if args.vararg:
        names.append("*" + args.vararg.arg)
    elif args.kwonlyargs:
        names.append("*")  # keyword-only from here: pybind11 writes a bare `*`
    names += [a.arg for a in args.kwonlyargs]
    if args.kwarg:
        names.append("**" + args.kwarg.arg)
    return names


def stub_defaults(fn):
    """{parameter: default} of a stub function (literals only)."""
    args = fn.args.posonlyargs + fn.args.args
    out = {}
    for a, d in zip(args[len(args) - len(fn.args.defaults) :], fn.args.defaults):
        out[a.arg] = ast.literal_eval(d)
    for a, d in zip(fn.args.kwonlyargs, fn.args.kw_defaults):
        if d is not None:
            out[a.arg] = ast.literal_eval(d)
    return out


def doc_defaults(obj, name):
    """{parameter: default} of the docstring signature, where the default is a literal."""
    line = (obj.__doc__ or "").lstrip().splitlines()[0]
    inner = line[len(name) + 1 : line.rindex(") ->")]
    out = {}
    for p in split_top(inner):
        if "=" in p:
            key, value = p.split(":")[0].strip(), p.split("=", 1)[1].strip()
            try:
                out[key] = ast.literal_eval(value)
            except (ValueError, SyntaxError):
                pass
    return out


DEFAULTS = {}


def parse_stub():
    tree = ast.parse(STUB.read_text())
    functions, classes, variables = {}, {}, set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions[node.name] = stub_params(node)
            DEFAULTS[node.name] = stub_defaults(node)
        elif isinstance(node, ast.AnnAssign):
            variables.add(node.target.id)
        elif isinstance(node, ast.ClassDef):
            members = {}
            for item in node.body:
                if isinstance(item, ast.Assign):  # `NAME = value`: an enum member
                    members[item.targets[0].id] = ("member", [])
                elif isinstance(item, ast.AnnAssign):  # `name: T`: a writable attribute
                    members[item.target.id] = ("attribute", [])
                elif isinstance(item, ast.FunctionDef):
                    decorators = {d.id for d in item.decorator_list if isinstance(d, ast.Name)}
                    kind = "property" if "property" in decorators else "static" if "staticmethod" in decorators else "method"
                    members[item.name] = (kind, stub_params(item))
                    DEFAULTS[f"{node.name}.{item.name}"] = stub_defaults(item)
            bases = [b.id if isinstance(b, ast.Name) else b.attr for b in node.bases]
            classes[node.name] = (bases, members)
    return functions, classes, variables


FUNCTIONS, CLASSES, VARIABLES = parse_stub()
PUBLIC = sorted(n for n in dir(_metricmap) if not n.startswith("_")) + ["__version__"]


def test_every_public_name_has_a_stub_and_back():
    stubbed = set(FUNCTIONS) | set(CLASSES) | VARIABLES
    assert set(mm.__all__) == stubbed
    assert set(PUBLIC) <= stubbed  # the compiled module's names, all exported
    assert {n for n in dir(mm) if not n.startswith("_")} - {"STUDY_CONFIGS"} <= stubbed | {"_study"}


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_function_signatures(name):
    fn = getattr(mm, name)
    fn = getattr(fn, "__wrapped__", fn)  # the compiled function behind metricmap/_arguments.py
    if inspect.isbuiltin(fn):  # compiled: the signature pybind11 writes in the docstring
        assert doc_params(fn, name) == FUNCTIONS[name]
        assert doc_defaults(fn, name) == DEFAULTS[name]
    else:
        assert list(inspect.signature(fn).parameters) == FUNCTIONS[name]


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_classes(name):
    bases, members = CLASSES[name]
    if not hasattr(_metricmap, name):  # written in Python: an enum
        cls = getattr(mm, name)
        assert [b.__name__ for b in cls.__bases__] == bases and issubclass(cls, enum.Enum)
        assert {m.name for m in cls} == {k for k, v in members.items() if v[0] == "member"}
        return
    cls = getattr(_metricmap, name)
    if issubclass(cls, BaseException):
        assert [b.__name__ for b in cls.__bases__] == bases
        return
    public = {
        k: v
        for k, v in vars(cls).items()
        if not k.startswith("_") or k in ("__init__", "__len__", "__getitem__")
    }
    if not (public.get("__init__").__doc__ or "").startswith("__init__("):
        public.pop("__init__", None)  # pybind11's placeholder of a class without constructor
    assert set(public) == set(members), name
    for attr, (kind, params) in members.items():
        value = public[attr]
        if kind == "property":
            assert isinstance(value, property), f"{name}.{attr}"
            continue
        if kind == "attribute":  # read and written: a property with a setter
            assert isinstance(value, property) and value.fset is not None, f"{name}.{attr}"
            continue
        if kind == "static":
            assert isinstance(value, staticmethod), f"{name}.{attr}"
            value = value.__func__
        value = getattr(value, "__wrapped__", value)  # a constructor behind _arguments.py
        if inspect.isfunction(value):  # a method written in Python (metricmap/_open3d.py)
            assert list(inspect.signature(value).parameters) == params, f"{name}.{attr}"
            continue
        got = doc_params(value, attr)
        assert doc_defaults(value, attr) == DEFAULTS[f"{name}.{attr}"], f"{name}.{attr}"
        if kind == "static":
            assert got == params, f"{name}.{attr}"
        else:
            assert got[0] == "self" and got[1:] == params[1:], f"{name}.{attr}"
