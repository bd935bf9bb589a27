# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""The documentation: help() renders, every public name has a docstring, the type stubs exist
and agree with the module."""

import ast
import inspect
import io
import pydoc
from pathlib import Path

import pytest

import cgal_ext_geodesics as geo

PACKAGE_DIR = Path(geo.__file__).resolve().parent

MESH_MEMBERS = ["read", "vertices", "faces", "n_vertices", "n_faces", "repairs", "distances", "distance_matrix",
                "voronoi", "farthest_point_sampling", "detect_patterns"]
PATHS_MEMBERS = ["n_sources", "mesh", "distance", "nearest_source", "distances", "nearest_sources", "path",
                 "path_locations"]


def test_help_renders():
    out = io.StringIO()
    pydoc.Helper(output=out).help(geo)
    text = out.getvalue()
    assert "cgal_ext_geodesics" in text and len(text) > 2000
    for name in geo.__all__:
        assert name in text, f"help(cgal_ext_geodesics) does not mention {name}"
    for member in ("distances", "GeodesicError", "farthest_point_sampling"):
        assert member in text


@pytest.mark.parametrize("name", ["Mesh", "GeodesicPaths", "Mesh.distances", "VoronoiDiagram"])
def test_help_of_a_name_renders(name):
    out = io.StringIO()
    obj = geo
    for part in name.split("."):
        obj = getattr(obj, part)
    pydoc.Helper(output=out).help(obj)
    assert len(out.getvalue()) > 200


def test_module_docstring():
    assert geo.__doc__ and "Mesh" in geo.__doc__ and "GeodesicError" in geo.__doc__


@pytest.mark.parametrize("name", geo.__all__)
def test_public_name_has_a_docstring(name):
    obj = getattr(geo, name)
    doc = inspect.getdoc(obj)
    assert doc and len(doc.strip()) > 20, f"cgal_ext_geodesics.{name} has no docstring worth the name: {doc!r}"


@pytest.mark.parametrize("cls,member", [("Mesh", m) for m in MESH_MEMBERS] +
                         [("GeodesicPaths", m) for m in PATHS_MEMBERS] + [("PatternInstances", "centers")])
def test_public_member_has_a_docstring(cls, member):
    attr = inspect.getattr_static(getattr(geo, cls), member)
    if isinstance(attr, (staticmethod, classmethod)):
        attr = attr.__func__
    doc = attr.__doc__
    assert doc and len(doc.strip()) > 15, f"{cls}.{member} has no docstring: {doc!r}"


def test_every_public_member_is_documented():
    missing = []
    for cls in (geo.Mesh, geo.GeodesicPaths):
        for member, attr in vars(cls).items():
            if member.startswith("_"):
                continue
            doc = getattr(attr, "__doc__", None)
            if not doc or not doc.strip():
                missing.append(f"{cls.__name__}.{member}")
    assert not missing, f"undocumented: {missing}"


def test_distances_docstring_names_every_parameter():
    doc = geo.Mesh.distances.__doc__
    for parameter in ("sources", "algorithm", "threads", "max_distance", "stop_vertices", "lam", "return_sources",
                      "progress"):
        assert parameter in doc, f"Mesh.distances' docstring does not mention {parameter}"
    for parameter in ("sources", "targets", "max_distance", "threads", "progress"):
        assert parameter in geo.Mesh.distance_matrix.__doc__, f"distance_matrix's docstring: {parameter}"


# ----------------------------------------------------------------------------------------------
# the type stubs


def stub_text():
    path = PACKAGE_DIR / "__init__.pyi"
    assert path.is_file(), f"no type stubs: {path} does not exist"
    return path.read_text()


def is_placeholder(text):
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return all(line.startswith("#") for line in lines)


def test_stub_files_exist():
    stub_text()
    assert (PACKAGE_DIR / "py.typed").is_file(), "no py.typed marker next to the package"


@pytest.fixture(scope="module")
def stubs():
    text = stub_text()
    if is_placeholder(text):
        pytest.skip("__init__.pyi holds only a placeholder comment: its contents are not checked yet")
    return ast.parse(text)


def top_level(tree):
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.Assign):
            for t in node.targets:
                if isinstance(t, ast.Name):
                    names[t.id] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names[node.target.id] = node
    return names


def test_stubs_define_every_public_name(stubs):
    names = top_level(stubs)
    missing = [n for n in geo.__all__ if n not in names]
    assert not missing, f"__init__.pyi does not define {missing}"


@pytest.mark.parametrize("cls,members", [("Mesh", MESH_MEMBERS), ("GeodesicPaths", PATHS_MEMBERS)])
def test_stub_classes_have_every_member(stubs, cls, members):
    node = top_level(stubs)[cls]
    defined = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
    missing = [m for m in members if m not in defined]
    assert not missing, f"the stub of {cls} lacks {missing}"


def stub_parameters(node):
    a = node.args
    return [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs if x.arg != "self"]


@pytest.mark.parametrize("name", ["read_mesh", "distances", "distance_matrix", "voronoi", "farthest_point_sampling",
                                  "detect_patterns", "Mesh.distance_matrix", "Mesh.voronoi",
                                  "Mesh.farthest_point_sampling", "Mesh.detect_patterns"])
def test_stub_parameters_match_the_functions(stubs, name):
    names = top_level(stubs)
    if "." in name:
        cls, member = name.split(".")
        node = next(n for n in names[cls].body if isinstance(n, ast.FunctionDef) and n.name == member)
        function = getattr(getattr(geo, cls), member)
    else:
        node, function = names[name], getattr(geo, name)
    runtime = [p.name for p in inspect.signature(function).parameters.values()
               if p.name != "self" and p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL)]
    assert stub_parameters(node) == runtime, f"{name}: the stub's parameters and the function's differ"
