"""One declaration per configuration field: the Python properties, the stub and the docs' table
of Slam2DConfig all follow the library's declaration (metricmap.slam2d_parameters())."""
import ast
import importlib.util
import math
import pathlib

import pytest

import metricmap as mm

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUB = pathlib.Path(mm.__file__).with_name("__init__.pyi")
KINDS = {"float": float, "int": int, "bool": bool}


def declared():
    return mm.slam2d_parameters()


def test_every_declared_field_is_a_typed_property():
    c = mm.Slam2DConfig()
    names = [p["name"] for p in declared()]
    assert len(names) == len(set(names))
    assert "bicubic" in names and "map_resolution" in names
    for p in declared():
        value = getattr(c, p["name"])
        assert type(value) is KINDS[p["kind"]], p
        assert p["name"] in type(c).__dict__, p
        assert p["rule"] in type(c).__dict__[p["name"]].__doc__, p


def test_the_stub_lists_every_declared_field_with_its_type():
    tree = ast.parse(STUB.read_text())
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Slam2DConfig")
    stub = {n.target.id: ast.unparse(n.annotation) for n in cls.body if isinstance(n, ast.AnnAssign)}
    assert stub == {p["name"]: p["kind"] for p in declared()}


@pytest.mark.parametrize("name", ["slam2d", "localize2d", "slam3d"])
def test_the_docs_table_is_the_declaration(name):
    spec = importlib.util.spec_from_file_location("table", ROOT / "tools" / "parameter_tables.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    page = tool.PAGES[name].read_text()
    assert tool.documented(name, page) == tool.table(tool.declared(name)), (
        f"{tool.PAGES[name].name}'s parameter table differs from the library: run "
        "tools/parameter_tables.py --write"
    )


@pytest.mark.parametrize("p", declared(), ids=lambda p: p["name"])
def test_each_declared_range_is_what_validation_accepts(p):
    """Just outside the declared range is refused naming the field, the ends of a closed range
    are accepted: the validator and the declaration cannot drift apart."""
    if p["kind"] == "bool":
        return
    whole = p["kind"] == "int"
    step = 1 if whole else 1e-6

    def refused(v):
        c = mm.Slam2DConfig()
        setattr(c, p["name"], int(v) if whole else v)
        with pytest.raises(ValueError, match=p["name"]):
            c.validate()

    def accepted(v):
        c = mm.Slam2DConfig()
        if p["name"] == "min_range":
            c.max_range = max(c.max_range, v + 1)
        setattr(c, p["name"], int(v) if whole else v)
        try:
            c.validate()
        except ValueError as e:  # only another field's rule may refuse it (e.g. clamp order)
            assert not str(e).startswith(p["name"] + " "), e

    lo, hi = p["min"], p["max"]
    if not (whole and lo - step < 0):
        refused(lo if p["min_open"] else lo - step * max(1.0, abs(lo)))
    if not p["min_open"]:
        accepted(lo)
    if math.isfinite(hi):
        refused(hi if p["max_open"] else hi + step * max(1.0, abs(hi)))
        if not p["max_open"]:
            accepted(hi)
