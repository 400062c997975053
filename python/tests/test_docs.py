"""Every public name of the module says what it is where a user looks: a docstring (help(), an
IDE), a signature inspect can read, and for each class a repr that is not pybind11's default.
CutReport has an attribute for every field of the engine's CutReport (engine/include/tetcut/
cut.hpp): a field added there without its documented binding fails here."""
import inspect
import re

import pytest

import tetcut
from conftest import CORPUS, PLATE_CUT, SOURCE, box_arrays, plate_arrays

# What a name gives that pybind11 fills in by itself: no text, or its own signature line.
PYBIND_SIGNATURE = re.compile(r"^\w*\(.*\) -> ")
PYBIND_REPR = re.compile(r"^<tetcut\.\w+ object at 0x[0-9a-f]+>$")
# pybind11's own machinery on every class, documented by Python itself.
INHERITED = {"__init__"}


def public_members():
    """(qualified name, object, kind) for every public function, class, method and property."""
    for name, value in vars(tetcut).items():
        if name.startswith("_"):
            continue
        if inspect.isclass(value):
            yield f"tetcut.{name}", value, "class"
            for attr, member in vars(value).items():
                if attr.startswith("_") and attr not in INHERITED:
                    continue
                kind = "property" if isinstance(member, property) else "method"
                yield f"tetcut.{name}.{attr}", member, kind
        elif callable(value):
            yield f"tetcut.{name}", value, "function"


MEMBERS = list(public_members())
MADE_BY_THE_MODULE = {"CutReport", "Changes", "Fragment", "Violation"}  # no constructor: __init__ refuses


def test_the_module_has_what_the_docs_list():
    names = {name for name, _, _ in MEMBERS}
    for expected in ["tetcut.read", "tetcut.Mesh.copy", "tetcut.Cutter.sweep", "tetcut.Cutter.cut_segment",
                     "tetcut.CutReport.end", "tetcut.CutReport.left_in_tool",
                     "tetcut.CutReport.kept_pieces_requested", "tetcut.Changes.removed", "tetcut.check",
                     "tetcut.CutReport.fragments", "tetcut.CutReport.detached", "tetcut.Fragment.tets",
                     "tetcut.Cutter.last_fragments", "tetcut.Cutter.pieces"]:
        assert expected in names
    assert len(MEMBERS) > 80  # every class, method and field, not a few


@pytest.mark.parametrize("name, member, kind", MEMBERS, ids=[m[0] for m in MEMBERS])
def test_every_public_name_has_a_docstring(name, member, kind):
    if name.split(".")[-1] == "__init__" and name.split(".")[1] in MADE_BY_THE_MODULE:
        pytest.skip("no constructor: the class says it is made by tetcut")
    doc = inspect.getdoc(member)
    assert doc and len(doc.split()) >= 3, f"{name} ({kind}) has no docstring"
    assert not PYBIND_SIGNATURE.match(doc), f"{name}: pybind11's signature line instead of a docstring: {doc!r}"


@pytest.mark.parametrize("name, member, kind", [m for m in MEMBERS if m[2] in ("function", "method")],
                         ids=[m[0] for m in MEMBERS if m[2] in ("function", "method")])
def test_every_function_and_method_has_a_signature_inspect_reads(name, member, kind):
    if name.split(".")[-1] == "__init__" and name.split(".")[1] in MADE_BY_THE_MODULE:
        pytest.skip("no constructor")
    parameters = inspect.signature(member).parameters
    assert all(not p.name.startswith("arg") for p in parameters.values()), f"{name}: {parameters}"


def test_class_signatures_name_their_arguments():
    assert list(inspect.signature(tetcut.Mesh).parameters) == ["points", "tets", "labels", "drop_unused_points"]
    cutter = inspect.signature(tetcut.Cutter).parameters
    assert list(cutter)[:2] == ["mesh", "tool_diameter"]
    assert cutter["tool_diameter"].default is inspect.Parameter.empty  # required
    assert cutter["strategy"].default == "combined" and cutter["keep_labels"].default == ()
    assert cutter["debris_volume"].default == 0.0 and cutter["fragment_search_bound"].default == 65536
    assert str(inspect.signature(tetcut.Cutter.sweep)) in ("(self, /, start, end, step, swept=False)",
                                                           "(start, end, step, swept=False)")
    mesh = tetcut.read(str(CORPUS / "cylinder.msh"))
    assert str(inspect.signature(tetcut.Cutter(mesh, tool_diameter=0.5).cut)) == "(centre)"
    assert str(inspect.signature(tetcut.Cutter(mesh, tool_diameter=0.5).cut_segment)) == "(a, b)"
    assert str(inspect.signature(mesh.write)) == "(path, *, binary=False, compression='none')"


def test_every_class_has_a_repr_that_says_what_it_holds():
    points, tets = box_arrays(4, 4.0)
    mesh = tetcut.Mesh(points, tets)
    cutter = tetcut.Cutter(mesh, tool_diameter=1.5)
    report = cutter.cut((2, 2, 4))
    violation = tetcut.check(mesh, radius_ratio_floor=0.99)[0]
    fragment = tetcut.Cutter(tetcut.Mesh(*plate_arrays()), tool_diameter=0.5).cut_segment(**PLATE_CUT).detached[0]
    expected = {
        mesh: "<tetcut.Mesh ",
        cutter: "<tetcut.Cutter tool_diameter=1.5 strategy=combined on <tetcut.Mesh ",
        report: "<tetcut.CutReport at (2, 2, 4): ok, ",
        report.changes: f"<tetcut.Changes {len(report.changes.removed)} removed, {len(report.changes.created)} created",
        violation: "I7 ",
        fragment: "<tetcut.Fragment ",
    }
    assert {type(o).__name__ for o in expected} == {n for n, v in vars(tetcut).items()
                                                   if inspect.isclass(v) and not n.startswith("_")}
    for obj, start in expected.items():
        assert not PYBIND_REPR.match(repr(obj)), repr(obj)
        assert repr(obj).startswith(start), repr(obj)


def struct_fields(name, headers):
    """The data members of `struct name` (and of the structs it derives from) in `headers`, by
    name: member functions, nested types and static members left out."""
    for header in headers:
        text = re.sub(r"//[^\n]*", "", header.read_text())
        found = re.search(r"^struct " + name + r"\b\s*(?::\s*([\w:, ]+?))?\s*\{(.*?)^\};", text, re.M | re.S)
        if found:
            break
    else:
        raise AssertionError(f"struct {name} is in none of {len(headers)} headers")
    bases, body = found.group(1), found.group(2)
    fields = [f for base in (bases or "").split(",") if base.strip()
              for f in struct_fields(base.replace("public", "").strip().split("::")[-1], headers)]
    while re.search(r"\{[^{}]*\}", body):  # brace initialisers and function bodies: gone
        body = re.sub(r"\{[^{}]*\}", ";", body)
    for statement in body.split(";"):
        statement = " ".join(statement.replace("[[nodiscard]]", "").split())
        if not statement or re.match(r"^(static|using|enum|friend|struct|class|template)\b", statement):
            continue
        declared = re.match(r"^[\w:<>, ]+?\s+(\w+\s*(?:=[^,]*)?(?:,\s*\w+\s*(?:=[^,]*)?)*)$", statement)
        if not declared or "operator" in statement or "(" in statement.split(" = ")[0]:  # a member function
            continue
        fields += [re.match(r"\s*(\w+)", d).group(1) for d in declared.group(1).split(",")]
    return fields


def cut_report_fields():
    """The data members of the engine's CutReport (engine/include/tetcut/cut.hpp), its bases' too."""
    headers = sorted((SOURCE / "engine" / "include" / "tetcut").glob("*.hpp"))
    return struct_fields("CutReport", [SOURCE / "engine" / "include" / "tetcut" / "cut.hpp"] + headers)


def test_the_report_has_every_field_of_the_engines_cut_report_documented():
    fields = cut_report_fields()
    assert {"ok", "tets_removed", "left_in_tool", "kept_pieces_requested", "time"} <= set(fields)
    python_name = {"time": "time_us"}  # the stage timings, in a dict
    for field in fields:
        attribute = getattr(tetcut.CutReport, python_name.get(field, field), None)
        assert attribute is not None, f"CutReport.{field} (cut.hpp) is not in Python: one report_field line in " \
                                      "python/src/cutter_binding.cpp, one line in python/tetcut.pyi"
        assert inspect.getdoc(attribute), f"CutReport.{field} has no docstring"
