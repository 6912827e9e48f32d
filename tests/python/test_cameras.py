"""phongrast.Camera: OpenCV cameras from numpy K and world_to_camera, the
matrices read back as numpy arrays, orthographic cameras, Scene.camera; the
projection checked against numpy's own K [R | t], not the renderer's."""
import numpy as np
import pytest

import phongrast


def rotation(axis, angle):
    """Rodrigues: a rotation about `axis` by `angle` radians."""
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def opencv_pose():
    pose = np.eye(4)
    pose[:3, :3] = rotation([1.0, -0.5, 0.3], 0.8)
    pose[:3, 3] = [0.2, -0.1, 5.0]
    return pose


K = np.array([[90.0, 4.0, 29.0], [0.0, 80.0, 21.0], [0.0, 0.0, 1.0]])


def test_from_opencv_takes_numpy_and_gives_the_matrices_back():
    pose = opencv_pose()
    camera = phongrast.Camera.from_opencv(K, pose)
    assert camera.model == "opencv"
    assert isinstance(camera.K, np.ndarray) and camera.K.dtype == np.float64 and camera.K.shape == (3, 3)
    np.testing.assert_array_equal(camera.K, K)
    np.testing.assert_array_equal(camera.world_to_camera, pose)
    np.testing.assert_allclose(camera.camera_to_world, np.linalg.inv(pose), atol=1e-12)
    np.testing.assert_allclose(camera.eye, -pose[:3, :3].T @ pose[:3, 3], atol=1e-12)
    # 3 x 4, float32 and lists are read too; camera_to_world is the inverse form of the same camera.
    again = phongrast.Camera.from_opencv(K.astype(np.float32).tolist(), pose[:3].astype(np.float32))
    np.testing.assert_allclose(again.world_to_camera, pose, atol=1e-6)
    inverse = phongrast.Camera.from_opencv_camera_to_world(K, np.linalg.inv(pose))
    np.testing.assert_allclose(inverse.world_to_camera, pose, atol=1e-12)


def test_project_is_numpys_K_R_t_plus_half_a_pixel():
    camera = phongrast.Camera.from_opencv(K, opencv_pose())
    points = np.random.default_rng(5).uniform(-1, 1, size=(20, 3))
    camera_points = points @ opencv_pose()[:3, :3].T + opencv_pose()[:3, 3]
    uvw = camera_points @ K.T
    expected_column = uvw[:, 0] / uvw[:, 2] + 0.5
    expected_row = uvw[:, 1] / uvw[:, 2] + 0.5
    projected = camera.project(points, 42, 58)
    np.testing.assert_allclose(projected[:, 0], expected_column, atol=1e-9)
    np.testing.assert_allclose(projected[:, 1], expected_row, atol=1e-9)
    np.testing.assert_allclose(projected[:, 2], camera_points[:, 2], atol=1e-12)


def test_a_tiny_triangle_at_an_opencv_pixel_covers_that_pixel():
    # Corners 0.2 pixels around OpenCV (u, v) = (40, 11), built by inverting K [R | t] in numpy.
    pose = opencv_pose()
    u, v, depth = 40, 11, 4.0
    corners = []
    for du, dv in [(-0.2, -0.2), (0.25, -0.1), (-0.05, 0.22)]:
        ray = np.linalg.solve(K, [u + du, v + dv, 1.0]) * depth
        corners.append(pose[:3, :3].T @ (ray - pose[:3, 3]))
    mesh = phongrast.Mesh(np.array(corners), np.array([[0, 1, 2]]))
    scene = phongrast.Scene.from_mesh(mesh, 42, 58)
    scene.camera = phongrast.Camera.from_opencv(K, pose)
    assert scene.camera.model == "opencv"
    _, _, planes = phongrast.render(scene, aovs="alpha")
    covered = np.argwhere(planes["alpha"] > 0)
    assert covered.tolist() == [[v, u]]


def test_an_opencv_camera_equal_to_the_look_at_one_draws_the_same_picture():
    mesh = phongrast.Mesh(np.array([[-1.0, -1, 0], [1, -1, 0], [0, 1, 0.5], [0.5, 0.5, -1]]),
                          np.array([[0, 1, 2], [0, 2, 3], [1, 3, 2]]))
    scene = phongrast.Scene.from_mesh(mesh, 60, 80)
    look_at_image, _ = phongrast.render(scene)
    opencv = scene.camera.to_opencv(60, 80)
    np.testing.assert_allclose(opencv.K, [[opencv.K[0, 0], 0, 39.5], [0, opencv.K[1, 1], 29.5], [0, 0, 1]])
    scene.camera = opencv
    opencv_image, _ = phongrast.render(scene)
    # R p + t against r.(p - eye): the same coverage, colours equal to float rounding.
    background = np.all(look_at_image == look_at_image[0, 0], axis=2)
    assert np.array_equal(background, np.all(opencv_image == look_at_image[0, 0], axis=2))
    assert np.count_nonzero(~background) > 200
    np.testing.assert_allclose(opencv_image, look_at_image, atol=1e-5)


def test_orthographic_keeps_an_objects_size_at_any_distance():
    square = phongrast.Mesh(np.array([[-0.5, -0.5, 0.0], [0.5, -0.5, 0], [0.5, 0.5, 0], [-0.5, 0.5, 0]]),
                            np.array([[0, 1, 2], [0, 2, 3]]))
    scene = phongrast.Scene.from_mesh(square, 32, 32)
    counts = []
    for distance in (1.0, 50.0):
        scene.camera = phongrast.Camera.orthographic([0.1, 0.1, distance], [0.1, 0.1, 0], sensor=(2.0, 2.0))
        _, _, planes = phongrast.render(scene, aovs="alpha")
        counts.append(int(np.count_nonzero(planes["alpha"])))
    assert counts == [16 * 16, 16 * 16]
    assert scene.camera.model == "orthographic"
    with pytest.raises(ValueError, match="orthographic"):
        scene.camera.to_opencv(32, 32)


def test_bad_cameras_raise_value_error_naming_the_field():
    pose = opencv_pose()
    stretched = pose.copy()
    stretched[0, :3] *= 1.01
    with pytest.raises(ValueError, match=r"camera.opencv.world_to_camera: the 3x3 part is not a rotation"):
        phongrast.Camera.from_opencv(K, stretched)
    with pytest.raises(ValueError, match=r"K: expected a 3 x 3"):
        phongrast.Camera.from_opencv(K[:2], pose)
    bad_fx = K.copy()
    bad_fx[0, 0] = -1
    with pytest.raises(ValueError, match=r"camera.opencv.fx"):
        phongrast.Camera.from_opencv(bad_fx, pose)
    nan_pose = pose.copy()
    nan_pose[1, 3] = np.nan
    with pytest.raises(ValueError, match=r"world_to_camera\[1\]\[3\]: expected a finite number"):
        phongrast.Camera.from_opencv(K, nan_pose)
    bottom = pose.copy()
    bottom[3, 2] = 1
    with pytest.raises(ValueError, match=r"world_to_camera: expected the last row"):
        phongrast.Camera.from_opencv(K, bottom)
    with pytest.raises(ValueError, match=r"to_opencv"):
        phongrast.Camera.look_at([0, 0, 5], [0, 0, 0]).K


def test_framing_makes_a_look_at_camera():
    mesh = phongrast.Mesh(np.array([[-1.0, -1, 0], [1, -1, 0], [0, 1, 0]]), np.array([[0, 1, 2]]))
    scene = phongrast.Scene.from_mesh(mesh, 20, 30)
    scene.camera = phongrast.Camera.from_opencv(K, opencv_pose())
    scene.frame()
    assert scene.camera.model == "look_at"
    image, stats = phongrast.render(scene)
    assert stats["triangles_drawn"] == 1
