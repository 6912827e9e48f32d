"""The README's "From Python" examples run as written (with an exercise data
file made from the test scene) and write what they say."""
import os
import re

import numpy as np

import phongrast
from conftest import SOURCE_DIR, SeedScene


def readme_python_blocks():
    text = (SOURCE_DIR / "README.md").read_text()
    section = text.split("## From Python", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", section, re.S)


def run_in(folder, code, monkeypatch):
    monkeypatch.chdir(folder)
    exec(compile(code, "README.md", "exec"), {"__name__": "readme"})


def test_the_readme_demo_writes_the_eight_figures(tmp_path, monkeypatch):
    demo = readme_python_blocks()[0]
    s = SeedScene(M=40, N=48)
    np.savez(tmp_path / "exercise_data.npz", verts=s.verts, vert_colors=s.colors, faces=s.faces, focal=s.focal,
             eye=s.eye, lookat=s.lookat, up=s.up, bg_color=s.bg, M=s.M, N=s.N, H=s.H, W=s.W,
             ka=s.mat.ka, kd=s.mat.kd, ks=s.mat.ks, n_phong=s.mat.n_phong, light_amb=s.ambient,
             light_pos=[l.pos for l in s.lights], light_intensity=[l.intensity for l in s.lights])
    run_in(tmp_path, demo, monkeypatch)
    for shader in ["gouraud", "phong"]:
        for lighting in ["ambient", "diffusion", "specular", "full"]:
            written = phongrast.read_image(str(tmp_path / f"{shader}-{lighting}.png"))
            expected = np.clip(s.render(shader, lighting), 0, 1)
            assert np.abs(written - expected).max() <= 0.5 / 255 + 1e-6


def test_the_readme_pythonic_example_runs(tmp_path, monkeypatch):
    os.symlink(SOURCE_DIR / "assets", tmp_path / "assets")
    run_in(tmp_path, readme_python_blocks()[1], monkeypatch)
    image = phongrast.read_image(str(tmp_path / "default-2x2.exr"))
    assert image.shape == (512, 512, 3) and image.std() > 0.05


def test_the_readme_python_section_starts_with_the_pip_commands_the_install_test_runs():
    text = (SOURCE_DIR / "README.md").read_text()
    section = text.split("## From Python", 1)[1].split("\n## ", 1)[0]
    first_block = re.search(r"```sh\n(.*?)```", section, re.S)
    assert first_block and section.index("```sh") < section.index("```python")
    commands = first_block.group(1).splitlines()
    assert commands[:2] == ["python3 -m venv --system-site-packages .venv",
                            ".venv/bin/pip install --no-build-isolation ."]
    install_test = (SOURCE_DIR / "tests" / "python" / "pip_install.cmake").read_text()
    assert "-m venv --system-site-packages" in install_test
    assert "install --no-build-isolation" in install_test
