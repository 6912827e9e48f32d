"""A dataset made by `phongrast batch`, checked without trusting the renderer:
a 50-view sphere layout of one mesh with its masks and id images, the job's
camera file and its transforms.json. Every mesh vertex is projected with the
written K and world_to_camera in numpy (OpenCV: pixel centres at whole
numbers) and must land on the rendered silhouette, whose bounding box must
match the projected one to a pixel (4 x 4 samples per pixel, so a thin
tip still covers a sample of the pixel its vertex is in); transforms.json must hold the same
cameras in OpenGL axes and name the images relative to itself.
"""
import json
import os
import pathlib
import subprocess

import numpy as np

import phongrast

EXE = os.environ["PHONGRAST_EXE"]
SOURCE = pathlib.Path(os.environ["PHONGRAST_SOURCE_DIR"])
SHARED = pathlib.Path(os.environ.get("PHONGRAST_SHARED_ASSETS_DIR", ""))
VIEWS = 50
SIZE = 96


def mesh_file():
    """spot.obj from ../shared/assets when it is there, else the project's generated knot."""
    spot = SHARED / "spot.obj"
    if spot.is_file():
        return spot
    print("../shared/assets/spot.obj not found: using assets/default.obj (the generated knot)")
    return SOURCE / "assets" / "default.obj"


def used_vertices(path):
    """The OBJ's vertex positions that some face uses (n x 3)."""
    positions, used = [], set()
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            positions.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            for corner in parts[1:]:
                index = int(corner.split("/")[0])
                used.add(index - 1 if index > 0 else len(positions) + index)
    return np.array(positions)[sorted(used)]


def project(K, world_to_camera, points):
    """OpenCV pixel coordinates (column, row) and depth of world points."""
    camera = (np.asarray(world_to_camera)[:3, :3] @ points.T).T + np.asarray(world_to_camera)[:3, 3]
    pixels = (np.asarray(K) @ camera.T).T
    return pixels[:, 0] / pixels[:, 2], pixels[:, 1] / pixels[:, 2], camera[:, 2]


def test_a_sphere_layout_with_masks_ids_and_cameras_reprojects_onto_its_silhouettes(tmp_path):
    mesh = mesh_file()
    job = {"mesh": str(mesh), "layout": "sphere", "views": VIEWS, "size": f"{SIZE}x{SIZE}", "samples": 4,
           "output": "set/{view}.png", "aov_files": "mask,id",
           "camera_out": "set/cameras.json", "transforms_out": "set/transforms.json"}
    (tmp_path / "jobs.jsonl").write_text(json.dumps(job) + "\n")
    run = subprocess.run([EXE, "batch", "jobs.jsonl", "-o", "out", "-q"], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    folder = tmp_path / "out" / "set"
    cameras = json.loads((folder / "cameras.json").read_text())
    transforms = json.loads((folder / "transforms.json").read_text())
    assert len(cameras["images"]) == VIEWS
    assert len(transforms["frames"]) == VIEWS
    vertices = used_vertices(mesh)

    for view, (image, frame) in enumerate(zip(cameras["images"], transforms["frames"])):
        name = f"{view:02d}.png"
        assert image["file_path"] == name  # relative to the camera file
        assert frame["file_path"] == name  # relative to transforms.json
        assert (image["width"], image["height"]) == (SIZE, SIZE)
        K = np.array(image["K"])
        world_to_camera = np.array(image["world_to_camera"])

        # transforms.json: the same camera, OpenGL axes (y up, z backward), centres at +0.5.
        assert frame.get("fl_x", transforms["fl_x"]) == K[0][0]
        assert transforms["cx"] == K[0][2] + 0.5 and transforms["cy"] == K[1][2] + 0.5
        opencv_to_opengl = np.diag([1.0, -1.0, -1.0, 1.0])
        np.testing.assert_allclose(np.array(frame["transform_matrix"]) @ opencv_to_opengl,
                                   np.linalg.inv(world_to_camera), atol=1e-9)
        np.testing.assert_allclose(np.array(image["camera_to_world_opengl"]), frame["transform_matrix"], atol=0)

        mask = phongrast.read_image(str(folder / f"{view:02d}.mask.png"))[:, :, 0]
        ids = np.rint(phongrast.read_image(str(folder / f"{view:02d}.id.png"))[:, :, 0] * 65535).astype(int)
        covered = mask > 0  # some of the pixel's 16 samples
        assert np.array_equal(covered, ids > 0)  # the id of the nearest covered sample: the same pixels
        assert covered.any()

        column, row, depth = project(K, world_to_camera, vertices)
        assert (depth > 0).all()
        # Every vertex on the silhouette: its pixel, or a neighbour for a vertex on the outline
        # (a pixel is covered only when the surface covers one of its samples).
        grown = covered.copy()
        grown[1:, :] |= covered[:-1, :]
        grown[:-1, :] |= covered[1:, :]
        grown[:, 1:] |= covered[:, :-1]
        grown[:, :-1] |= covered[:, 1:]
        c = np.clip(np.rint(column).astype(int), 0, SIZE - 1)
        r = np.clip(np.rint(row).astype(int), 0, SIZE - 1)
        inside = (column > -0.5) & (column < SIZE - 0.5) & (row > -0.5) & (row < SIZE - 0.5)
        assert inside.all(), f"view {view}: a vertex projects outside the image"
        assert grown[r, c].all(), f"view {view}: {np.count_nonzero(~grown[r, c])} vertices off the silhouette"
        # The silhouette's bounding box is the projected one, to a pixel.
        rows, columns = np.nonzero(covered)
        assert abs(columns.min() - column.min()) <= 1.0 and abs(columns.max() - column.max()) <= 1.0, view
        assert abs(rows.min() - row.min()) <= 1.0 and abs(rows.max() - row.max()) <= 1.0, view


def test_job_camera_files_refuse_what_they_cannot_hold(tmp_path):
    (tmp_path / "bad.jsonl").write_text(json.dumps({"mesh": str(SOURCE / "assets" / "default.obj"),
                                                    "camera_out": "{name}-{view}.json"}) + "\n")
    run = subprocess.run([EXE, "batch", "bad.jsonl", "-o", "out"], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 2
    assert "bad.jsonl:1: /camera_out: one file per job holds every view's camera" in run.stderr
    (tmp_path / "ext.jsonl").write_text(json.dumps({"mesh": str(SOURCE / "assets" / "default.obj"),
                                                    "transforms_out": "t.txt"}) + "\n")
    run = subprocess.run([EXE, "batch", "ext.jsonl", "-o", "out"], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 2
    assert "/transforms_out: expected a .json file name" in run.stderr
    assert not (tmp_path / "out").exists()
