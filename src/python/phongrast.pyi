"""Type stubs for the phongrast extension module (pybind11), shipped next to
the module by `pip install .` and as the stub package phongrast-stubs.
Checked by `mypy --strict` on tests/python/typed_example.py (ctest
"python: stubs"); tests/python/test_stubs.py checks every public name of the
module has a stub and the other way round."""

from typing import Any, Callable, Literal, Sequence, overload

import numpy as np
import numpy.typing as npt

__version__: str

# An array or anything numpy turns into one (nested lists, tuples).
_ArrayLike = npt.ArrayLike
_Image = npt.NDArray[np.float32]
_Stats = dict[str, Any]
_Planes = dict[str, npt.NDArray[Any]]
_Progress = Callable[[float], object] | None
_Mode = Literal["seed", "exact"]
_Visibility = Literal["painter", "depth-buffer", "depth_buffer"]
_Precision = Literal["single", "double"]
_SamplePattern = Literal["ordered", "rotated"]
_Overdraw = Literal["auto", "all", "visible"]
_BackFaces = Literal["draw", "cull"]
_TextureFilter = Literal["bilinear", "nearest", "trilinear"]

class FileError(ValueError):
    """A file could not be read or written, or is malformed; the message names the file and the line or field."""

class RenderCancelled(RuntimeError):
    """The render's progress callable returned False; a Renderer stays usable."""

# The seed's functions (same names and arguments as the course exercise).

class PhongMaterial:
    ka: float | npt.NDArray[np.float64]
    kd: float | npt.NDArray[np.float64]
    ks: float | npt.NDArray[np.float64]
    n_phong: float
    def __init__(self, ka: _ArrayLike, kd: _ArrayLike, ks: _ArrayLike, n_phong: float) -> None: ...

class PointLight:
    pos: npt.NDArray[np.float64]
    intensity: float | npt.NDArray[np.float64]
    def __init__(self, pos: _ArrayLike, intensity: _ArrayLike) -> None: ...
    @property
    def position(self) -> npt.NDArray[np.float64]: ...

def light(
    point: _ArrayLike,
    normal: _ArrayLike,
    vcolor: _ArrayLike,
    cam_pos: _ArrayLike,
    mat: Any,
    lights: Any,
    lighting: str = "full",
    *,
    light_amb: _ArrayLike = 0.2,
) -> npt.NDArray[np.float64]: ...
def calculate_normals(verts: _ArrayLike, faces: _ArrayLike) -> npt.NDArray[np.float64]: ...
def render_object(
    shader: str,
    focal: float,
    eye: _ArrayLike,
    lookat: _ArrayLike,
    up: _ArrayLike,
    bg_color: _ArrayLike,
    M: int,
    N: int,
    H: float,
    W: float,
    verts: _ArrayLike,
    vert_colors: _ArrayLike | None,
    faces: _ArrayLike,
    mat: Any,
    lights: Any,
    light_amb: _ArrayLike,
    lighting: str,
    *,
    mode: _Mode = "seed",
    samples: int = 1,
    threads: int = 0,
    visibility: _Visibility = "painter",
    precision: _Precision = "single",
    sample_pattern: _SamplePattern = "ordered",
    overdraw: _Overdraw = "auto",
    back_faces: _BackFaces = "draw",
    texture_filter: _TextureFilter = "bilinear",
    aovs: str = "",
    progress: _Progress = None,
) -> _Image: ...
def shade_gouraud(
    verts_p: _ArrayLike,
    verts_n: _ArrayLike,
    verts_c: _ArrayLike,
    bcoords: _ArrayLike,
    cam_pos: _ArrayLike,
    mat: Any,
    lights: Any,
    light_amb: _ArrayLike,
    X: npt.NDArray[Any],
    lighting: str = "full",
) -> npt.NDArray[Any]: ...
def shade_phong(
    verts_p: _ArrayLike,
    verts_n: _ArrayLike,
    verts_c: _ArrayLike,
    bcoords: _ArrayLike,
    cam_pos: _ArrayLike,
    mat: Any,
    lights: Any,
    light_amb: _ArrayLike,
    X: npt.NDArray[Any],
    lighting: str = "full",
) -> npt.NDArray[Any]: ...

# The Pythonic layer.

class Texture:
    """A texture map: (rows, columns, 3) float texels (row 0 the top row) and its wrap modes."""
    def __init__(self, texels: _ArrayLike, wrap_s: str = "repeat", wrap_t: str = "repeat") -> None: ...
    @staticmethod
    def load(path: str, wrap_s: str = "repeat", wrap_t: str = "repeat") -> Texture: ...
    @property
    def size(self) -> tuple[int, int]: ...
    @property
    def wrap(self) -> tuple[str, str]: ...
    def sample(self, s: float, t: float) -> tuple[float, float, float]: ...

class Material:
    """A face material: the coefficients it sets, a texture and glTF's colour factor."""
    def __init__(
        self,
        ka: float | _ArrayLike | None = None,
        kd: float | _ArrayLike | None = None,
        ks: float | _ArrayLike | None = None,
        n: float | None = None,
        texture: Texture | None = None,
        color_factor: _ArrayLike | None = None,
        name: str = "",
    ) -> None: ...
    @property
    def fields(self) -> dict[str, Any]: ...
    @property
    def has_texture(self) -> bool: ...
    @property
    def name(self) -> str: ...

class Mesh:
    def __init__(
        self,
        vertices: _ArrayLike,
        faces: _ArrayLike,
        colors: _ArrayLike | None = None,
        texcoords: _ArrayLike | None = None,
        normals: _ArrayLike | None = None,
        material: Material | None = None,
        materials: Sequence[Material] | None = None,
        face_materials: _ArrayLike | None = None,
    ) -> None: ...
    @staticmethod
    def load(path: str) -> Mesh: ...
    @property
    def has_texcoords(self) -> bool: ...
    @property
    def has_normals(self) -> bool: ...
    @property
    def material_count(self) -> int: ...
    def save(self, path: str) -> None: ...
    @property
    def positions(self) -> npt.NDArray[np.float64]: ...
    @property
    def colors(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def faces(self) -> npt.NDArray[np.uint32]: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...

_CameraModel = Literal["look_at", "opencv", "orthographic"]

class Camera:
    @staticmethod
    def look_at(
        eye: _ArrayLike,
        lookat: _ArrayLike,
        up: _ArrayLike = ...,
        focal: float = 1.0,
        sensor: tuple[float, float] = ...,
    ) -> Camera: ...
    @staticmethod
    def orthographic(
        eye: _ArrayLike, lookat: _ArrayLike, up: _ArrayLike = ..., sensor: tuple[float, float] = ...
    ) -> Camera: ...
    @staticmethod
    def from_opencv(K: _ArrayLike, world_to_camera: _ArrayLike) -> Camera: ...
    @staticmethod
    def from_opencv_camera_to_world(K: _ArrayLike, camera_to_world: _ArrayLike) -> Camera: ...
    @property
    def model(self) -> _CameraModel: ...
    @property
    def K(self) -> npt.NDArray[np.float64]: ...
    @property
    def world_to_camera(self) -> npt.NDArray[np.float64]: ...
    @property
    def camera_to_world(self) -> npt.NDArray[np.float64]: ...
    @property
    def eye(self) -> tuple[float, float, float]: ...
    def to_opencv(self, rows: int, columns: int) -> Camera: ...
    def project(self, points: _ArrayLike, rows: int, columns: int) -> npt.NDArray[np.float64]: ...

class Scene:
    @staticmethod
    def load(path: str, mesh: Mesh | None = None) -> Scene: ...
    @staticmethod
    def from_dict(description: dict[str, Any], folder: str = ".") -> Scene: ...
    @staticmethod
    def from_mesh(mesh: Mesh, rows: int = 512, columns: int = 512) -> Scene: ...
    def copy(self) -> Scene: ...
    @property
    def eye(self) -> npt.NDArray[np.float64]: ...
    @eye.setter
    def eye(self, value: _ArrayLike) -> None: ...
    @property
    def lookat(self) -> npt.NDArray[np.float64]: ...
    @lookat.setter
    def lookat(self, value: _ArrayLike) -> None: ...
    @property
    def up(self) -> npt.NDArray[np.float64]: ...
    @up.setter
    def up(self, value: _ArrayLike) -> None: ...
    @property
    def background(self) -> npt.NDArray[np.float64]: ...
    @background.setter
    def background(self, value: _ArrayLike) -> None: ...
    @property
    def ambient(self) -> npt.NDArray[np.float64]: ...
    @ambient.setter
    def ambient(self, value: _ArrayLike) -> None: ...
    @property
    def focal(self) -> float: ...
    @focal.setter
    def focal(self, value: float) -> None: ...
    @property
    def sensor(self) -> tuple[float, float]: ...
    @sensor.setter
    def sensor(self, value: tuple[float, float]) -> None: ...
    @property
    def camera(self) -> Camera: ...
    @camera.setter
    def camera(self, value: Camera) -> None: ...
    @property
    def size(self) -> tuple[int, int]: ...
    @size.setter
    def size(self, value: tuple[int, int]) -> None: ...
    @property
    def shader(self) -> str: ...
    @shader.setter
    def shader(self, value: str) -> None: ...
    @property
    def lighting(self) -> str: ...
    @lighting.setter
    def lighting(self, value: str) -> None: ...
    @property
    def material(self) -> dict[str, Any]: ...
    @material.setter
    def material(self, value: Any) -> None: ...
    @property
    def lights(self) -> list[dict[str, npt.NDArray[np.float64]]]: ...
    @lights.setter
    def lights(self, value: Sequence[Any]) -> None: ...
    @property
    def mesh(self) -> Mesh: ...
    @mesh.setter
    def mesh(self, value: Mesh) -> None: ...
    @property
    def objects(self) -> list[dict[str, Any]]: ...
    @property
    def normals(self) -> str: ...
    @normals.setter
    def normals(self, value: str) -> None: ...
    def frame(self, rows: int | None = None, columns: int | None = None) -> None: ...
    @property
    def warnings(self) -> list[str]: ...

@overload
def render(
    scene: Scene,
    *,
    mode: _Mode = "exact",
    samples: int = 1,
    threads: int = 0,
    visibility: _Visibility = "painter",
    precision: _Precision = "single",
    sample_pattern: _SamplePattern = "ordered",
    overdraw: _Overdraw = "auto",
    back_faces: _BackFaces = "draw",
    texture_filter: _TextureFilter = "bilinear",
    progress: _Progress = None,
) -> tuple[_Image, _Stats]: ...
@overload
def render(
    scene: Scene,
    *,
    aovs: str,
    mode: _Mode = "exact",
    samples: int = 1,
    threads: int = 0,
    visibility: _Visibility = "painter",
    precision: _Precision = "single",
    sample_pattern: _SamplePattern = "ordered",
    overdraw: _Overdraw = "auto",
    back_faces: _BackFaces = "draw",
    texture_filter: _TextureFilter = "bilinear",
    progress: _Progress = None,
) -> tuple[_Image, _Stats, _Planes]: ...

class Renderer:
    def __init__(
        self,
        *,
        mode: _Mode = "exact",
        samples: int = 1,
        threads: int = 0,
        visibility: _Visibility = "painter",
        precision: _Precision = "single",
        sample_pattern: _SamplePattern = "ordered",
        overdraw: _Overdraw = "auto",
        back_faces: _BackFaces = "draw",
    texture_filter: _TextureFilter = "bilinear",
        aovs: str = "",
        progress: _Progress = None,
    ) -> None: ...
    # (image, stats), or (image, stats, planes) when the Renderer was made with aovs.
    def render(self, scene: Scene) -> tuple[Any, ...]: ...
    def _cpp_render_seconds(self, scene: Scene, repeats: int) -> list[float]: ...

def release_render_memory() -> None: ...
def read_image(path: str) -> _Image: ...
def write_image(image: npt.NDArray[np.uint8] | npt.NDArray[np.floating[Any]] | _ArrayLike, path: str) -> None: ...
def read_aovs(path: str) -> tuple[_Image, _Planes]: ...
def _cpp_render_seconds(scene: Scene, repeats: int, **options: Any) -> list[float]: ...
def _coefficient(value: Any, name: str) -> Any: ...
def _exponent(value: Any) -> float: ...
def _position(value: Any) -> npt.NDArray[np.float64]: ...
