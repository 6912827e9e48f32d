"""The type stubs (src/python/phongrast.pyi) match the module: every public
name has a stub and every stub a name; inspect.signature works on the
functions and methods; the typed example runs; mypy --strict accepts it
(when python3-mypy is installed: cmake/debian-packages.txt lists it)."""
import ast
import importlib.util
import inspect
import os
import pathlib
import subprocess
import sys

import pytest

import phongrast
from conftest import SOURCE_DIR

STUBS = SOURCE_DIR / "src" / "python" / "phongrast.pyi"
EXAMPLE = pathlib.Path(__file__).with_name("typed_example.py")


def stub_names():
    tree = ast.parse(STUBS.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return {n for n in names if not n.startswith("_") or n == "__version__"}


def test_every_public_name_has_a_stub_and_every_stub_a_name():
    public = {n for n in dir(phongrast) if not n.startswith("_")} | {"__version__"}
    assert stub_names() == public


@pytest.mark.parametrize("name", ["render", "read_image", "write_image", "read_aovs", "light", "calculate_normals",
                                  "render_object", "shade_gouraud", "shade_phong"])
def test_inspect_signature_works_on_functions(name):
    signature = inspect.signature(getattr(phongrast, name))
    assert len(signature.parameters) >= 1


def test_inspect_signature_works_on_classes_and_methods():
    assert list(inspect.signature(phongrast.Mesh).parameters) == ["vertices", "faces", "colors", "texcoords", "normals",
                                                                  "material", "materials", "face_materials"]
    assert list(inspect.signature(phongrast.Scene.from_mesh).parameters) == ["mesh", "rows", "columns"]
    assert list(inspect.signature(phongrast.Mesh.load).parameters) == ["path"]
    assert "scene" in inspect.signature(phongrast.Renderer.render).parameters
    assert "scene" in inspect.signature(phongrast.render).parameters
    assert inspect.signature(phongrast.Scene.from_mesh).parameters["rows"].default == 512


def test_the_typed_example_runs(tmp_path):
    spec = importlib.util.spec_from_file_location("typed_example", EXAMPLE)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    example.main(str(tmp_path))


def test_mypy_strict_accepts_the_typed_example(tmp_path):
    if importlib.util.find_spec("mypy") is None:
        pytest.skip("skipped: mypy is not installed (Debian: apt-get install python3-mypy)")
    stubs = tmp_path / "stubs"
    stubs.mkdir()
    (stubs / "phongrast.pyi").write_text(STUBS.read_text())
    environment = dict(os.environ, MYPYPATH=str(stubs))
    result = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                             "--cache-dir", str(tmp_path / "cache"), str(EXAMPLE)],
                            capture_output=True, text=True, env=environment)
    assert result.returncode == 0, result.stdout + result.stderr
    # And mypy does catch a mistake against the stubs.
    wrong = tmp_path / "wrong.py"
    wrong.write_text("import phongrast\nimage, stats = phongrast.render(3)\n")
    result = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                             "--cache-dir", str(tmp_path / "cache"), str(wrong)],
                            capture_output=True, text=True, env=environment)
    assert result.returncode != 0 and "render" in result.stdout
