"""A dataset made by `phongrast batch`, checked without trusting the renderer:
a 50-view sphere layout of one mesh with its masks and id images, the job's
camera file and its transforms.json. Every mesh vertex is projected with the
written K and world_to_camera in numpy (OpenCV: pixel centres at whole
numbers) and must land on the rendered silhouette, whose bounding box must
match the projected one to a pixel (4 x 4 samples per pixel, so a thin
tip still covers a sample of the pixel its vertex is in); transforms.json must hold the same
cameras in OpenGL axes and name the images relative to itself.

The same batch writes depth and distance (EXR), checked against the same
projection: where a vertex is seen, the depth there is its z_c and the
distance |camera centre - vertex|, and everywhere on the silhouette
distance / depth is the length of K^-1 (u, v, 1) at one of the pixel's samples.
"""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import phongrast

EXE = os.environ["PHONGRAST_EXE"]
SOURCE = pathlib.Path(os.environ["PHONGRAST_SOURCE_DIR"])
SHARED = pathlib.Path(os.environ.get("PHONGRAST_SHARED_ASSETS_DIR", ""))
VIEWS = 50
SIZE = 96
SAMPLES = 4  # per axis: 16 samples per pixel, on the ordered grid


def mesh_file():
    """spot.obj from ../shared/assets when it is there, else the project's generated knot."""
    spot = SHARED / "spot.obj"
    if spot.is_file():
        return spot
    print("../shared/assets/spot.obj not found: using assets/default.obj (the generated knot)")
    return SOURCE / "assets" / "default.obj"


def read_obj(path):
    """The OBJ's vertex positions (n x 3) and its triangles (m x 3 indices into them; polygons as fans,
    in file order: the id output's numbering)."""
    positions, triangles = [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            positions.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            corners = []
            for corner in parts[1:]:
                index = int(corner.split("/")[0])
                corners.append(index - 1 if index > 0 else len(positions) + index)
            triangles += [[corners[0], corners[k], corners[k + 1]] for k in range(1, len(corners) - 1)]
    return np.array(positions), np.array(triangles)


def used_vertices(path):
    """The OBJ's vertex positions that some face uses (n x 3)."""
    positions, triangles = read_obj(path)
    return positions[np.unique(triangles)]


def project(K, world_to_camera, points):
    """OpenCV pixel coordinates (column, row) and depth of world points."""
    camera = (np.asarray(world_to_camera)[:3, :3] @ points.T).T + np.asarray(world_to_camera)[:3, 3]
    pixels = (np.asarray(K) @ camera.T).T
    return pixels[:, 0] / pixels[:, 2], pixels[:, 1] / pixels[:, 2], camera[:, 2]


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    """One batch for every test here: the 50 views with their files, and the folder they are in."""
    mesh = mesh_file()
    work = tmp_path_factory.mktemp("dataset")
    job = {"mesh": str(mesh), "layout": "sphere", "views": VIEWS, "size": f"{SIZE}x{SIZE}", "samples": SAMPLES,
           "output": "set/{view}.png", "aov_files": "mask,id,depth,distance",
           "camera_out": "set/cameras.json", "transforms_out": "set/transforms.json"}
    (work / "jobs.jsonl").write_text(json.dumps(job) + "\n")
    run = subprocess.run([EXE, "batch", "jobs.jsonl", "-o", "out", "-q"], cwd=work, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return mesh, work / "out" / "set"


def test_a_sphere_layout_with_masks_ids_and_cameras_reprojects_onto_its_silhouettes(dataset):
    mesh, folder = dataset
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


def read_float_exr(path):
    """A one-channel float EXR (the depth and distance files: channel Z) as an M x N float64 array."""
    return phongrast.read_image(str(path))[:, :, 0].astype(np.float64)


def sample_ray_lengths(K):
    """|K^-1 (u, v, 1)| at each sample of each pixel (SIZE x SIZE x SAMPLES^2): the ordered grid puts
    sample (i, j) of pixel (r, c) at (c + (j + 0.5) / SAMPLES, r + (i + 0.5) / SAMPLES) in this
    contract's pixel coordinates (centres at +0.5), so u = c + (j + 0.5) / SAMPLES - 0.5 in OpenCV's."""
    offsets = (np.arange(SAMPLES) + 0.5) / SAMPLES - 0.5
    dy, dx = np.meshgrid(offsets, offsets, indexing="ij")
    rows, columns = np.meshgrid(np.arange(SIZE, dtype=float), np.arange(SIZE, dtype=float), indexing="ij")
    u = columns[:, :, None] + dx.ravel()
    v = rows[:, :, None] + dy.ravel()
    rays = np.stack([u, v, np.ones_like(u)], axis=-1) @ np.linalg.inv(K).T
    return np.linalg.norm(rays, axis=-1)


def inverse_depth_gradients(column, row, depth, triangles):
    """Per triangle, the gradient (d/du, d/dv) of 1/z_c over the image in pixels: 1/z_c is affine in
    screen space on a triangle, so this is exact. Infinite for a triangle seen edge-on."""
    A = np.stack([column[triangles], row[triangles], np.ones(triangles.shape)], axis=-1)  # m x 3 x 3
    w = 1.0 / depth[triangles]
    gradients = np.full((len(triangles), 2), np.inf)
    solvable = np.abs(np.linalg.det(A)) > 1e-9
    gradients[solvable] = np.linalg.solve(A[solvable], w[solvable])[:, :2]
    return gradients


def test_depth_and_distance_files_hold_the_projected_vertices_z_and_distance(dataset):
    """Where a vertex lands, and a triangle of that vertex paints its pixel (the id file), the depth
    there is the vertex's z_c and the distance |camera centre - vertex|, within what the surface's
    slope allows between the vertex and the pixel's nearest sample:

      the vertex lies in its pixel (|du|, |dv| <= 1/2 from the centre), the sample within 3/8 of it
      (4 x 4 samples), and the rasterizer snaps corners to 1/256 sample (1/2048 pixel); 1/z_c is
      affine on the triangle with gradient g, so |1/depth - 1/z_v| <= (|g_u| + |g_v|) (7/8 + 1/2048)
      + 1e-5 / z_v (float rounding). For the distance d = depth f_s (f_s = |K^-1 (u, v, 1)| at the
      sample, one of the pixel's 16) against z_v f_v:
      |distance - |C - X_v|| <= |depth - z_v| max f_s + z_v max |f_s - f_v| + 1e-6 |C - X_v|.

    Every view must check at least a tenth of the mesh's vertices, so the selection cannot leave the
    test nothing to check. Everywhere on the silhouette distance / depth is, to float rounding, the
    ray length at one of the pixel's samples (the nearest covered one), computed from K alone."""
    mesh, folder = dataset
    cameras = json.loads((folder / "cameras.json").read_text())
    positions, triangles = read_obj(mesh)
    worst_depth = worst_distance = 0.0  # the largest error as a fraction of its tolerance
    fewest = len(positions)
    for view, image in enumerate(cameras["images"]):
        K = np.array(image["K"])
        world_to_camera = np.array(image["world_to_camera"])
        depth = read_float_exr(folder / f"{view:02d}.depth.exr")
        distance = read_float_exr(folder / f"{view:02d}.distance.exr")
        mask = phongrast.read_image(str(folder / f"{view:02d}.mask.png"))[:, :, 0]
        ids = np.rint(phongrast.read_image(str(folder / f"{view:02d}.id.png"))[:, :, 0] * 65535).astype(int)
        assert depth.shape == distance.shape == (SIZE, SIZE)

        # The silhouette: finite depth and distance exactly where the mask is not zero, +inf elsewhere.
        covered = mask > 0
        assert np.array_equal(np.isfinite(depth), covered) and np.array_equal(np.isfinite(distance), covered)
        assert np.all(np.isposinf(depth[~covered])) and np.all(np.isposinf(distance[~covered]))
        # distance / depth: the ray length of one of the pixel's samples, to float rounding.
        lengths = sample_ray_lengths(K)[covered]  # pixels x 16
        ratio = distance[covered] / depth[covered]
        mismatch = np.min(np.abs(lengths - ratio[:, None]), axis=1) / ratio
        assert mismatch.max() <= 1e-6, f"view {view}: distance / depth off every sample's ray by {mismatch.max()}"

        # The vertices seen at their own pixel.
        column, row, z = project(K, world_to_camera, positions)
        c, r = np.rint(column).astype(int), np.rint(row).astype(int)
        inside = (c >= 0) & (c < SIZE) & (r >= 0) & (r < SIZE) & (z > 0)
        vertex = np.nonzero(inside)[0]
        c, r = c[vertex], r[vertex]
        painter = ids[r, c] - 1
        gradients = inverse_depth_gradients(column, row, z, triangles)
        own = (painter >= 0) & (triangles[np.maximum(painter, 0)] == vertex[:, None]).any(axis=1)
        own &= np.isfinite(gradients[np.maximum(painter, 0)]).all(axis=1)
        vertex, c, r, g = vertex[own], c[own], r[own], gradients[painter[own]]
        assert len(vertex) >= len(np.unique(triangles)) // 10, f"view {view}: only {len(vertex)} vertices checked"
        fewest = min(fewest, len(vertex))

        z_v = z[vertex]
        tolerance = np.abs(g).sum(axis=1) * (7 / 8 + 1 / 2048) + 1e-5 / z_v
        error = np.abs(1.0 / depth[r, c] - 1.0 / z_v)
        assert (error <= tolerance).all(), f"view {view}: depth off at {np.count_nonzero(error > tolerance)} vertices"
        worst_depth = max(worst_depth, (error / tolerance).max())

        centre = -world_to_camera[:3, :3].T @ world_to_camera[:3, 3]
        euclidean = np.linalg.norm(positions[vertex] - centre, axis=1)
        f_v = euclidean / z_v  # |K^-1 (u, v, 1)| at the vertex
        f_s = sample_ray_lengths(K)[r, c]  # vertices x 16
        depth_bound = depth[r, c] * z_v * tolerance
        allowed = (depth_bound * f_s.max(axis=1) + z_v * np.abs(f_s - f_v[:, None]).max(axis=1) +
                   1e-6 * euclidean)
        error = np.abs(distance[r, c] - euclidean)
        assert (error <= allowed).all(), f"view {view}: distance off at {np.count_nonzero(error > allowed)} vertices"
        worst_distance = max(worst_distance, (error / allowed).max())
    print(f"fewest vertices checked in a view: {fewest}; "
          f"largest error / tolerance: depth {worst_depth:.3f}, distance {worst_distance:.3f}")


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
