"""Help texts and the type stub come from the engine's one description of the options (wrc.operations(), i.e.
api::operations()): every option of every call is in its docstring with unit and default, and in the stub."""
import ast
import io
import pathlib
import contextlib

import wrc
from wrc import _wrc

from conftest import BUILD


def resolve(name):
    obj = wrc
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


def test_docstrings_list_every_option():
    ops = {op["name"]: op for op in wrc.operations()}
    entries = _wrc._entries()
    assert {e[0] for e in entries} >= {"contact", "wheel", "equilibrium", "rigid", "sweep", "geometry_table",
                                       "wheelset_conicity", "conicity", "flange_measures", "trajectory",
                                       "trajectory_contact", "trajectory_wheel", "profile_load", "wheelset"}
    for op_name, python in entries:
        doc = resolve(python).__doc__
        assert ops[op_name]["lua"] in doc, python
        for o in ops[op_name]["options"]:
            assert f"  {o['key']} : " in doc, (python, o["key"])
            line = doc.split(f"  {o['key']} : ", 1)[1].split("\n", 2)
            if o["unit"] not in ("", "-"):
                assert f"[{o['unit']}]" in line[0], (python, o["key"])
            if o["required"]:
                assert "required" in line[0]
            elif o["default"]:
                assert f"default {o['default']}" in line[0], (python, o["key"])
            assert o["help"] and o["help"] in line[1], (python, o["key"])


def test_help_of_wheelset_shows_units_and_defaults():
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        help(wrc.wheelset)
    text = out.getvalue()
    assert "radius : number [m], default 0.45" in text
    assert "E : number [Pa]" in text and "solver : Literal[" in text


def test_stub_is_generated_and_complete():
    path = BUILD / "python" / "wrc" / "__init__.pyi"
    text = path.read_text()
    assert text == _wrc._stub()
    tree = ast.parse(text)
    top = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    top |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    top |= {a.asname or a.name for n in tree.body if isinstance(n, ast.ImportFrom) for a in n.names}
    assert set(wrc.__all__) <= top, set(wrc.__all__) - top
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    for cls in (wrc.Profile, wrc.Wheelset, wrc.Trajectory):
        stubbed = {m.name for m in classes[cls.__name__].body if isinstance(m, ast.FunctionDef)}
        stubbed |= {m.target.id for m in classes[cls.__name__].body if isinstance(m, ast.AnnAssign)}
        public = {n for n in dir(cls) if not n.startswith("_")}
        assert public <= stubbed, (cls.__name__, public - stubbed)
    module = {m.name for m in classes["_ProfileModule"].body if isinstance(m, ast.FunctionDef)}
    assert {n for n in dir(wrc.profile) if not n.startswith("_") and callable(getattr(wrc.profile, n))} <= module
    # Each option of Wheelset.contact is a keyword of its stub, typed.
    contact = next(m for m in classes["Wheelset"].body if isinstance(m, ast.FunctionDef) and m.name == "contact")
    keywords = {a.arg for a in contact.args.kwonlyargs}
    ops = {op["name"]: op for op in wrc.operations()}
    assert keywords == {o["key"] for o in ops["contact"]["options"] if "." not in o["key"]}
