#include "phongrast/io/scene_file.hpp"
#include "phongrast/image.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include "phongrast/camera.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

using nlohmann::json;

/// Largest image side accepted from a file: the library's (phongrast/image.hpp),
/// shared with the command and Python; the pixel count is checked by the
/// library's validation.
constexpr std::int64_t max_image_side = kMaxImageSide;

std::string type_of(const json& value) {
    if (value.is_number()) return "a number";
    if (value.is_string()) return "a string (" + value.dump() + ")";
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_null()) return "null";
    if (value.is_array()) return "an array of " + std::to_string(value.size());
    return "an object";
}

/// Reads one JSON document; every message names the file and a JSON pointer.
class SceneReader {
public:
    explicit SceneReader(std::string name) : name_(std::move(name)) {}

    [[noreturn]] void fail(const json::json_pointer& where, const std::string& what) const {
        throw FileError(name_ + ": " + (where.empty() ? std::string("/") : where.to_string()) + ": " + what);
    }

    void warn_unknown(const json& object, const json::json_pointer& where,
                      const std::set<std::string>& known, std::vector<std::string>* warnings) const {
        for (auto it = object.begin(); it != object.end(); ++it) {
            if (known.count(it.key()) == 0) {
                warnings->push_back(name_ + ": ignoring unknown field " + (where / it.key()).to_string());
            }
        }
    }

    const json& require_object(const json& value, const json::json_pointer& where) const {
        if (!value.is_object()) fail(where, "expected an object, got " + type_of(value));
        return value;
    }

    const json* optional_field(const json& object, const json::json_pointer& where, const char* key) const {
        (void)where;
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    const json& required_field(const json& object, const json::json_pointer& where, const char* key,
                               const char* expected) const {
        const auto it = object.find(key);
        if (it == object.end()) fail(where / key, std::string("missing required field; expected ") + expected);
        return *it;
    }

    double number(const json& value, const json::json_pointer& where) const {
        if (!value.is_number()) fail(where, "expected a number, got " + type_of(value));
        const double result = value.get<double>();
        // JSON has no NaN or Infinity literals, but 1e999 parses to infinity.
        if (!std::isfinite(result)) fail(where, "expected a finite number, got " + value.dump());
        return result;
    }

    double positive_number(const json& value, const json::json_pointer& where) const {
        const double result = number(value, where);
        if (!(result > 0.0)) fail(where, "expected a positive number, got " + value.dump());
        return result;
    }

    int image_side(const json& value, const json::json_pointer& where) const {
        const double result = number(value, where);
        if (result != std::floor(result) || result < 1.0 || result > double(max_image_side)) {
            fail(where, "expected a whole number of pixels from 1 to " + std::to_string(max_image_side) +
                            ", got " + value.dump());
        }
        return static_cast<int>(result);
    }

    glm::dvec3 triple(const json& value, const json::json_pointer& where) const {
        if (!value.is_array() || value.size() != 3) {
            fail(where, "expected an array of 3 numbers, got " + type_of(value));
        }
        return {number(value[0], where / 0), number(value[1], where / 1), number(value[2], where / 2)};
    }

    /// A material coefficient: one number for all channels, or [r, g, b].
    glm::vec3 coefficient(const json& value, const json::json_pointer& where) const {
        if (value.is_number()) return glm::vec3(static_cast<float>(number(value, where)));
        if (value.is_array()) return glm::vec3(triple(value, where));
        fail(where, "expected a number or an array of 3 numbers, got " + type_of(value));
    }

    std::string string(const json& value, const json::json_pointer& where) const {
        if (!value.is_string()) fail(where, "expected a string, got " + type_of(value));
        return value.get<std::string>();
    }

    const std::string& name() const { return name_; }

private:
    std::string name_;
};

const std::string& reader_name(const SceneReader& reader) { return reader.name(); }

/// "name:line:column" (1-based) of a byte offset into text.
std::string position_in(const std::string& name, const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return name + ":" + std::to_string(line) + ":" + std::to_string(column);
}

json parse_or_explain(const std::string& text, const std::string& name) {
    try {
        return json::parse(text);
    } catch (const json::parse_error& error) {
        // nlohmann reports the byte offset just past the bad character.
        std::string detail = error.what();
        const std::size_t colon = detail.find(": ", detail.find("parse error"));
        if (colon != std::string::npos) detail = detail.substr(colon + 2);
        throw FileError(position_in(name, text, error.byte == 0 ? 0 : error.byte - 1) + ": malformed JSON: " + detail);
    } catch (const json::out_of_range& error) {
        // A number too large for a double, such as 1e999 ("number overflow parsing '1e999'"):
        // nlohmann gives no position, so find the literal it quotes.
        const std::string detail = error.what();
        const std::size_t open = detail.find('\'');
        const std::size_t close = detail.rfind('\'');
        const std::string literal = open < close ? detail.substr(open + 1, close - open - 1) : std::string();
        const std::size_t at = literal.empty() ? std::string::npos : text.find(literal);
        throw FileError((at == std::string::npos ? name : position_in(name, text, at)) +
                        ": expected a finite number, got " + (literal.empty() ? detail : literal));
    }
}

void read_mesh_path(const SceneReader& reader, const json& document, const std::string& folder, SceneFile& result) {
    const json::json_pointer root;
    if (const json* mesh = reader.optional_field(document, root, "mesh")) {
        const std::string relative = reader.string(*mesh, root / "mesh");
        if (relative.empty()) reader.fail(root / "mesh", "expected a mesh file name (.obj, .ply, .stl, .gltf, .glb), got an empty string");
        const std::filesystem::path mesh_path(relative);
        result.mesh_path = mesh_path.is_absolute() || folder.empty()
                               ? mesh_path.string()
                               : (std::filesystem::path(folder) / mesh_path).string();
    }
}

/// A matrix as a list of rows: `rows` (or `other_rows`) rows of `columns`
/// finite numbers each.
std::vector<std::vector<double>> read_matrix(const SceneReader& reader, const json& value,
                                             const json::json_pointer& where, std::size_t rows,
                                             std::size_t other_rows, std::size_t columns, const char* expected) {
    if (!value.is_array() || (value.size() != rows && value.size() != other_rows)) {
        reader.fail(where, std::string("expected ") + expected + ", got " + type_of(value));
    }
    std::vector<std::vector<double>> out;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const json& row = value[i];
        if (!row.is_array() || row.size() != columns) {
            reader.fail(where / i, "expected a row of " + std::to_string(columns) + " numbers, got " + type_of(row));
        }
        out.emplace_back();
        for (std::size_t j = 0; j < columns; ++j) out.back().push_back(reader.number(row[j], where / i / j));
    }
    return out;
}

/// A pose as the contract writes it: 4x4 rows with last row [0, 0, 0, 1] (or
/// its first 3 rows); the 3x3 part must be a rotation.
Matrix3x4 read_pose(const SceneReader& reader, const json& value, const json::json_pointer& where) {
    const std::vector<std::vector<double>> m =
        read_matrix(reader, value, where, 4, 3, 4, "4 rows of 4 numbers (or 3 rows: [R | t])");
    if (m.size() == 4 && !(m[3][0] == 0.0 && m[3][1] == 0.0 && m[3][2] == 0.0 && m[3][3] == 1.0)) {
        reader.fail(where / 3, "expected the last row [0, 0, 0, 1], got " + value[3].dump());
    }
    Matrix3x4 pose{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) pose[i][j] = m[i][j];
    }
    try {
        validate_pose(pose, "");
    } catch (const std::invalid_argument& error) {
        reader.fail(where, std::string(error.what()).substr(2));  // drop the empty field name's ": "
    }
    return pose;
}

/// An OpenCV camera: "K" and one of "world_to_camera" and "camera_to_world".
void read_opencv_camera(const SceneReader& reader, const json& camera, const json::json_pointer& camera_at,
                        const json& K_value, Camera& out) {
    const json::json_pointer K_at = camera_at / "K";
    const std::vector<std::vector<double>> K =
        read_matrix(reader, K_value, K_at, 3, 3, 3, "[[fx, s, cx], [0, fy, cy], [0, 0, 1]]");
    if (!(K[1][0] == 0.0)) reader.fail(K_at / 1 / 0, "expected 0, got " + K_value[1][0].dump());
    if (!(K[2][0] == 0.0 && K[2][1] == 0.0 && K[2][2] == 1.0)) {
        reader.fail(K_at / 2, "expected [0, 0, 1], got " + K_value[2].dump());
    }
    if (!(K[0][0] > 0.0)) reader.fail(K_at / 0 / 0, "expected fx, a positive number, got " + K_value[0][0].dump());
    if (!(K[1][1] > 0.0)) reader.fail(K_at / 1 / 1, "expected fy, a positive number, got " + K_value[1][1].dump());
    const json* world_to_camera = reader.optional_field(camera, camera_at, "world_to_camera");
    const json* camera_to_world = reader.optional_field(camera, camera_at, "camera_to_world");
    if (world_to_camera != nullptr && camera_to_world != nullptr) {
        reader.fail(camera_at / "camera_to_world", "give one of world_to_camera and camera_to_world, not both");
    }
    if (world_to_camera == nullptr && camera_to_world == nullptr) {
        reader.fail(camera_at / "world_to_camera",
                    "missing required field; an OpenCV camera (K) needs world_to_camera or camera_to_world (4x4)");
    }
    Matrix3x4 pose = world_to_camera != nullptr ? read_pose(reader, *world_to_camera, camera_at / "world_to_camera")
                                                : read_pose(reader, *camera_to_world, camera_at / "camera_to_world");
    if (camera_to_world != nullptr) pose = invert_pose(pose, "camera.camera_to_world");
    out.model = CameraModel::opencv;
    out.opencv.fx = K[0][0];
    out.opencv.skew = K[0][1];
    out.opencv.cx = K[0][2];
    out.opencv.fy = K[1][1];
    out.opencv.cy = K[1][2];
    out.opencv.world_to_camera = pose;
}

constexpr const char* kCameraExpected =
    "an object: eye, lookat, up, focal, sensor (look-at); K and world_to_camera or camera_to_world (OpenCV); "
    "projection \"orthographic\", eye, lookat, up, sensor";

/// The camera object at `camera_at`, into `out`. Fields the camera does not
/// use (unknown ones, the look-at fields beside K, an orthographic camera's
/// focal) are warnings, or errors naming the field when `unused` says so.
void read_camera_object(const SceneReader& reader, const json& camera_value, const json::json_pointer& camera_at,
                        Camera& out, std::vector<std::string>& warnings,
                        UnusedCameraFields unused = UnusedCameraFields::warn) {
    const json& camera = reader.require_object(camera_value, camera_at);
    const std::set<std::string> known = {"eye",     "lookat", "up", "focal", "sensor", "K", "world_to_camera",
                                         "camera_to_world", "projection"};
    const bool refuse = unused == UnusedCameraFields::refuse;
    if (refuse) {
        for (auto it = camera.begin(); it != camera.end(); ++it) {
            if (known.count(it.key()) == 0) {
                reader.fail(camera_at / it.key(), "unknown field; a camera has eye, lookat, up, focal, sensor, K, "
                                                  "world_to_camera, camera_to_world or projection");
            }
        }
    }
    reader.warn_unknown(camera, camera_at, known, &warnings);
    bool orthographic = false;
    if (const json* projection = reader.optional_field(camera, camera_at, "projection")) {
        const std::string name = reader.string(*projection, camera_at / "projection");
        if (name != "orthographic" && name != "perspective") {
            reader.fail(camera_at / "projection", "expected \"perspective\" or \"orthographic\", got " + projection->dump());
        }
        orthographic = name == "orthographic";
    }
    if (const json* K = reader.optional_field(camera, camera_at, "K")) {
        if (orthographic) reader.fail(camera_at / "projection", "an OpenCV camera (K) is a perspective camera, not orthographic");
        read_opencv_camera(reader, camera, camera_at, *K, out);
        // A file may also carry the look-at form (--camera-out writes both): the matrices win.
        for (const char* ignored : {"eye", "lookat", "up", "focal", "sensor"}) {
            if (!camera.contains(ignored)) continue;
            if (refuse) {
                reader.fail(camera_at / ignored, "an OpenCV camera (K) is placed by its matrices; give K with "
                                                 "world_to_camera or camera_to_world, or the look-at fields, not both");
            }
            warnings.push_back(reader_name(reader) + ": ignoring " + (camera_at / ignored).to_string() +
                               ": an OpenCV camera (K) is placed by its matrices");
        }
        return;
    }
    for (const char* opencv_only : {"world_to_camera", "camera_to_world"}) {
        if (camera.contains(opencv_only)) reader.fail(camera_at / "K", std::string("missing; ") + opencv_only + " is given, so K is required");
    }
    out.model = orthographic ? CameraModel::orthographic : CameraModel::look_at;
    out.eye = reader.triple(reader.required_field(camera, camera_at, "eye", "[x, y, z]"), camera_at / "eye");
    out.lookat = reader.triple(reader.required_field(camera, camera_at, "lookat", "[x, y, z]"), camera_at / "lookat");
    if (const json* up = reader.optional_field(camera, camera_at, "up")) {
        out.up = reader.triple(*up, camera_at / "up");
    }
    if (orthographic) {
        if (camera.contains("focal")) {
            if (refuse) reader.fail(camera_at / "focal", "an orthographic camera has no focal length; leave it out");
            warnings.push_back(reader_name(reader) + ": ignoring " + (camera_at / "focal").to_string() +
                                      ": an orthographic camera has no focal length");
        }
    } else {
        out.focal = reader.positive_number(reader.required_field(camera, camera_at, "focal", "a positive number"),
                                           camera_at / "focal");
    }
    const json& sensor = reader.required_field(camera, camera_at, "sensor", "[height, width]");
    if (!sensor.is_array() || sensor.size() != 2) {
        reader.fail(camera_at / "sensor", "expected [height, width] (2 numbers), got " + type_of(sensor));
    }
    out.sensor_height = reader.positive_number(sensor[0], camera_at / "sensor" / 0);
    out.sensor_width = reader.positive_number(sensor[1], camera_at / "sensor" / 1);
}

void read_camera(const SceneReader& reader, const json& document, SceneFile& result) {
    const json::json_pointer root;
    read_camera_object(reader, reader.required_field(document, root, "camera", kCameraExpected), root / "camera",
                       result.scene.camera, result.warnings);
}

void read_image(const SceneReader& reader, const json& document, SceneFile& result) {
    const json::json_pointer root;
    ImageSpec& out = result.scene.image;
    const json::json_pointer image_at = root / "image";
    const json& image = reader.require_object(
        reader.required_field(document, root, "image", "an object with height and width"), image_at);
    reader.warn_unknown(image, image_at, {"height", "width", "background"}, &result.warnings);
    out.rows = reader.image_side(reader.required_field(image, image_at, "height", "a positive integer"),
                                 image_at / "height");
    out.columns = reader.image_side(reader.required_field(image, image_at, "width", "a positive integer"),
                                    image_at / "width");
    if (const json* background = reader.optional_field(image, image_at, "background")) {
        out.background = glm::vec3(reader.triple(*background, image_at / "background"));
    }
}

/// A "material" object (the scene's or an object's): ka, kd, ks, n.
MaterialFields material_fields(const SceneReader& reader, const json& material, const json::json_pointer& material_at,
                               std::vector<std::string>* warnings) {
    MaterialFields result;
    reader.require_object(material, material_at);
    reader.warn_unknown(material, material_at, {"ka", "kd", "ks", "n"}, warnings);
    if (const json* ka = reader.optional_field(material, material_at, "ka")) {
        result.ka = reader.coefficient(*ka, material_at / "ka");
    }
    if (const json* kd = reader.optional_field(material, material_at, "kd")) {
        result.kd = reader.coefficient(*kd, material_at / "kd");
    }
    if (const json* ks = reader.optional_field(material, material_at, "ks")) {
        result.ks = reader.coefficient(*ks, material_at / "ks");
    }
    if (const json* n = reader.optional_field(material, material_at, "n")) {
        const double exponent = reader.number(*n, material_at / "n");
        if (exponent < 0.0) reader.fail(material_at / "n", "expected a non-negative number, got " + n->dump());
        result.n = static_cast<float>(exponent);
    }
    return result;
}

void read_material(const SceneReader& reader, const json& document, SceneFile& result) {
    const json::json_pointer root;
    const json* material = reader.optional_field(document, root, "material");
    if (material == nullptr) return;
    result.material = material_fields(reader, *material, root / "material", &result.warnings);
}

NormalSource normal_source(const SceneReader& reader, const json& value, const json::json_pointer& where) {
    const std::string text = reader.string(value, where);
    try {
        return parse_normal_source(text);
    } catch (const std::invalid_argument& error) {
        reader.fail(where, error.what());
    }
}

/// A 4x4 "transform": a list of 4 rows of 4 finite numbers, the last row 0 0 0 1.
glm::dmat4 matrix_field(const SceneReader& reader, const json& value, const json::json_pointer& where) {
    const char* expected = "expected a 4x4 matrix as a list of 4 rows of 4 numbers, the last row [0, 0, 0, 1]";
    if (!value.is_array() || value.size() != 4) reader.fail(where, std::string(expected) + ", got " + type_of(value));
    glm::dmat4 m(1.0);
    for (std::size_t row = 0; row < 4; ++row) {
        const json& cells = value[row];
        if (!cells.is_array() || cells.size() != 4) {
            reader.fail(where / row, std::string(expected) + "; this row is " + type_of(cells));
        }
        for (std::size_t column = 0; column < 4; ++column) {
            // glm is column-major: m[column][row].
            m[static_cast<glm::length_t>(column)][static_cast<glm::length_t>(row)] =
                reader.number(cells[column], where / row / column);
        }
    }
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) {
        reader.fail(where / 3, std::string(expected) + "; got " + value[3].dump());
    }
    return m;
}

/// An object's model matrix must be finite and invertible: its 3x3 part's
/// determinant is compared with the product of its rows' lengths (Hadamard's
/// bound), so the test does not depend on the object's size.
void check_invertible(const SceneReader& reader, const glm::dmat4& m, const json::json_pointer& where,
                      const std::string& object) {
    const glm::dmat3 linear(m);
    const double determinant = glm::determinant(linear);
    double bound = 1.0;
    for (glm::length_t row = 0; row < 3; ++row) {
        bound *= std::sqrt(linear[0][row] * linear[0][row] + linear[1][row] * linear[1][row] +
                           linear[2][row] * linear[2][row]);
    }
    for (glm::length_t column = 0; column < 4; ++column) {
        for (glm::length_t row = 0; row < 4; ++row) {
            if (!std::isfinite(m[column][row])) {
                reader.fail(where, object + ": the model matrix is not finite (check the scale)");
            }
        }
    }
    if (!std::isfinite(determinant) || !std::isfinite(bound)) {
        reader.fail(where, object + ": the model matrix's determinant is not finite (values too large)");
    }
    if (!(std::abs(determinant) > 1e-12 * bound)) {
        reader.fail(where, object + ": the model matrix is singular (determinant " + std::to_string(determinant) +
                               "); expected an invertible transform (no zero scale, no flattened axis)");
    }
}

/// One entry of "objects".
SceneFileObject read_object(const SceneReader& reader, const json& value, const json::json_pointer& at,
                            std::size_t index, const std::string& folder, std::vector<std::string>* warnings) {
    const json& object = reader.require_object(value, at);
    reader.warn_unknown(object, at, {"mesh", "transform", "translation", "rotation", "scale", "material", "normals"},
                        warnings);
    SceneFileObject result;
    const std::string relative =
        reader.string(reader.required_field(object, at, "mesh", "a mesh file name (.obj, .ply, .stl, .gltf, .glb)"),
                      at / "mesh");
    if (relative.empty()) {
        reader.fail(at / "mesh", "expected a mesh file name (.obj, .ply, .stl, .gltf, .glb), got an empty string");
    }
    const std::filesystem::path mesh_path(relative);
    result.mesh_path = mesh_path.is_absolute() || folder.empty() ? mesh_path.string()
                                                                 : (std::filesystem::path(folder) / mesh_path).string();
    result.name = "objects[" + std::to_string(index) + "] (" + relative + ")";

    const json* transform = reader.optional_field(object, at, "transform");
    const json* translation = reader.optional_field(object, at, "translation");
    const json* rotation = reader.optional_field(object, at, "rotation");
    const json* scale = reader.optional_field(object, at, "scale");
    if (transform != nullptr) {
        if (translation != nullptr || rotation != nullptr || scale != nullptr) {
            reader.fail(at, "both \"transform\" and translation/rotation/scale; expected one form: a 4x4 "
                            "\"transform\", or any of \"translation\", \"rotation\", \"scale\"");
        }
        result.transform = matrix_field(reader, *transform, at / "transform");
        check_invertible(reader, result.transform, at / "transform", result.name);
    } else if (translation != nullptr || rotation != nullptr || scale != nullptr) {
        glm::dvec3 t(0.0);
        glm::dvec4 q(0.0, 0.0, 0.0, 1.0);
        glm::dvec3 s(1.0);
        if (translation != nullptr) t = reader.triple(*translation, at / "translation");
        if (rotation != nullptr) {
            const json::json_pointer rotation_at = at / "rotation";
            if (!rotation->is_array() || rotation->size() != 4) {
                reader.fail(rotation_at, "expected a unit quaternion [x, y, z, w], got " + type_of(*rotation));
            }
            for (glm::length_t i = 0; i < 4; ++i) {
                q[i] = reader.number((*rotation)[static_cast<std::size_t>(i)], rotation_at / static_cast<std::size_t>(i));
            }
            const double length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
            if (!(std::abs(length - 1.0) <= 1e-6)) {
                reader.fail(rotation_at, "expected a unit quaternion [x, y, z, w] (length 1 to 1e-6), got length " +
                                             std::to_string(length));
            }
        }
        if (scale != nullptr) {
            const json::json_pointer scale_at = at / "scale";
            if (scale->is_number()) {
                s = glm::dvec3(reader.number(*scale, scale_at));
            } else if (scale->is_array()) {
                s = reader.triple(*scale, scale_at);
            } else {
                reader.fail(scale_at, "expected a number or [sx, sy, sz], got " + type_of(*scale));
            }
            if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) {
                reader.fail(scale_at, result.name + ": a zero scale makes the model matrix singular; expected "
                                                    "non-zero scales (negative ones mirror)");
            }
        }
        result.transform = compose_transform(t, q, s);
        check_invertible(reader, result.transform, at, result.name);
    }
    if (const json* material = reader.optional_field(object, at, "material")) {
        result.material = material_fields(reader, *material, at / "material", warnings);
    }
    if (const json* normals = reader.optional_field(object, at, "normals")) {
        result.normals = normal_source(reader, *normals, at / "normals");
    }
    return result;
}

void read_objects(const SceneReader& reader, const json& document, const std::string& folder, SceneFile& result) {
    const json::json_pointer root;
    const json* objects = reader.optional_field(document, root, "objects");
    if (objects == nullptr) return;
    const json::json_pointer objects_at = root / "objects";
    if (reader.optional_field(document, root, "mesh") != nullptr) {
        reader.fail(root, "both \"mesh\" and \"objects\"; expected exactly one of them");
    }
    if (!objects->is_array() || objects->empty()) {
        reader.fail(objects_at, "expected a non-empty array of objects, got " + type_of(*objects));
    }
    for (std::size_t i = 0; i < objects->size(); ++i) {
        result.objects.push_back(read_object(reader, (*objects)[i], objects_at / i, i, folder, &result.warnings));
    }
}

void read_lights(const SceneReader& reader, const json& document, SceneFile& result) {
    const json::json_pointer root;
    if (const json* ambient = reader.optional_field(document, root, "ambient")) {
        result.scene.ambient = glm::vec3(reader.triple(*ambient, root / "ambient"));
    }
    const json* lights = reader.optional_field(document, root, "lights");
    if (lights == nullptr) return;
    const json::json_pointer lights_at = root / "lights";
    if (!lights->is_array()) reader.fail(lights_at, "expected an array of lights, got " + type_of(*lights));
    for (std::size_t i = 0; i < lights->size(); ++i) {
        const json::json_pointer light_at = lights_at / i;
        const json& light = reader.require_object((*lights)[i], light_at);
        reader.warn_unknown(light, light_at, {"position", "intensity"}, &result.warnings);
        PointLight point;
        point.position =
            reader.triple(reader.required_field(light, light_at, "position", "[x, y, z]"), light_at / "position");
        point.intensity = glm::vec3(
            reader.triple(reader.required_field(light, light_at, "intensity", "[r, g, b]"), light_at / "intensity"));
        result.scene.lights.push_back(point);
    }
}

void read_shader_and_lighting(const SceneReader& reader, const json& document, Scene& scene) {
    const json::json_pointer root;
    if (const json* shader = reader.optional_field(document, root, "shader")) {
        try {
            scene.shader = parse_shader(reader.string(*shader, root / "shader"));
        } catch (const std::invalid_argument& error) {
            reader.fail(root / "shader", error.what());
        }
    }
    if (const json* lighting = reader.optional_field(document, root, "lighting")) {
        try {
            scene.lighting = parse_lighting(reader.string(*lighting, root / "lighting"));
        } catch (const std::invalid_argument& error) {
            reader.fail(root / "lighting", error.what());
        }
    }
}

}  // namespace

SceneFile parse_scene_json(const std::string& text, const std::string& name, const std::string& folder) {
    const SceneReader reader(name);
    const json document = parse_or_explain(text, name);
    const json::json_pointer root;
    reader.require_object(document, root);

    SceneFile result;
    reader.warn_unknown(document, root,
                        {"mesh", "objects", "camera", "image", "material", "ambient", "lights", "shader",
                         "lighting", "normals"},
                        &result.warnings);
    read_mesh_path(reader, document, folder, result);
    read_objects(reader, document, folder, result);
    if (const json* normals = reader.optional_field(document, root, "normals")) {
        result.scene.normals = normal_source(reader, *normals, root / "normals");
    }
    read_camera(reader, document, result);
    read_image(reader, document, result);
    read_material(reader, document, result);
    read_lights(reader, document, result);
    read_shader_and_lighting(reader, document, result.scene);

    // The camera's geometric conditions (eye == lookat, up parallel to the view).
    try {
        make_camera_frame(result.scene.camera, result.scene.image.rows, result.scene.image.columns);
    } catch (const std::invalid_argument& error) {
        throw FileError(name + ": " + error.what());
    }
    return result;
}

SceneFile read_scene_file(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw FileError(path + ": scene file not found (no such file)");
    if (std::filesystem::is_directory(path, error)) throw FileError(path + ": is a folder; expected a scene file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path + ": cannot read scene file: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw FileError(path + ": cannot read scene file: " + std::strerror(errno));
    return parse_scene_json(text.str(), path, std::filesystem::path(path).parent_path().string());
}

Camera parse_camera_json(const std::string& text, const std::string& name, std::vector<std::string>* warnings) {
    const json document = parse_or_explain(text, name);
    const SceneReader reader(name);
    const json::json_pointer root;
    reader.require_object(document, root);
    std::vector<std::string> found;
    Camera camera;
    if (document.contains("camera")) {
        read_camera_object(reader, document["camera"], root / "camera", camera, found);
    } else {
        read_camera_object(reader, document, root, camera, found);
    }
    try {
        make_camera_frame(camera, 1, 1);  // the geometric conditions (eye == lookat, up parallel to the view)
    } catch (const std::invalid_argument& error) {
        throw FileError(name + ": " + error.what());
    }
    if (warnings != nullptr) warnings->insert(warnings->end(), found.begin(), found.end());
    return camera;
}

Camera parse_camera_object(const std::string& text, const std::string& name, const std::string& where,
                          UnusedCameraFields unused, std::vector<std::string>* warnings) {
    json::json_pointer camera_at;
    try {
        camera_at = json::json_pointer(where);
    } catch (const json::exception&) {
        throw std::invalid_argument("parse_camera_object: '" + where + "' is not a JSON pointer (\"\" or \"/a/0\")");
    }
    const json document = parse_or_explain(text, name);
    const SceneReader reader(name);
    std::vector<std::string> found;
    Camera camera;
    read_camera_object(reader, document, camera_at, camera, found, unused);
    try {
        make_camera_frame(camera, 1, 1);  // the geometric conditions (eye == lookat, up parallel to the view)
    } catch (const std::invalid_argument& error) {
        // "camera.up: must not be ..." names the field: as a pointer below `where`.
        const std::string what = error.what();
        const std::size_t colon = what.find(": ");
        if (what.rfind("camera.", 0) == 0 && colon != std::string::npos) {
            reader.fail(camera_at / what.substr(7, colon - 7), what.substr(colon + 2));
        }
        reader.fail(camera_at, what);
    }
    if (warnings != nullptr) warnings->insert(warnings->end(), found.begin(), found.end());
    return camera;
}

Camera read_camera_file(const std::string& path, std::vector<std::string>* warnings) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw FileError(path + ": camera file not found (no such file)");
    if (std::filesystem::is_directory(path, error)) throw FileError(path + ": is a folder; expected a camera file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path + ": cannot read camera file: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw FileError(path + ": cannot read camera file: " + std::strerror(errno));
    return parse_camera_json(text.str(), path, warnings);
}

glm::dmat4 compose_transform(const glm::dvec3& translation, const glm::dvec4& rotation, const glm::dvec3& scale) {
    const double length = std::sqrt(rotation.x * rotation.x + rotation.y * rotation.y + rotation.z * rotation.z +
                                    rotation.w * rotation.w);
    const double x = rotation.x / length, y = rotation.y / length, z = rotation.z / length, w = rotation.w / length;
    // The rotation matrix of a unit quaternion (as glTF), rows r, columns c: R[r][c].
    const double r[3][3] = {
        {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * w), 2.0 * (x * z + y * w)},
        {2.0 * (x * y + z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * w)},
        {2.0 * (x * z - y * w), 2.0 * (y * z + x * w), 1.0 - 2.0 * (x * x + y * y)},
    };
    glm::dmat4 m(1.0);
    for (glm::length_t c = 0; c < 3; ++c) {
        for (glm::length_t row = 0; row < 3; ++row) m[c][row] = r[row][c] * scale[c];  // R * S: column c scaled by s_c
    }
    m[3] = glm::dvec4(translation, 1.0);  // T * (R * S)
    return m;
}

PhongMaterial default_material() { return PhongMaterial{}; }

PhongMaterial resolve_material(const MaterialFields& fields, const std::optional<PhongMaterial>& from_mtl,
                               std::vector<std::string>* defaults_used) {
    const PhongMaterial defaults = default_material();
    PhongMaterial result;
    auto pick = [&](const auto& field, auto from_mtl_value, auto default_value, const char* name) {
        if (field) return *field;
        if (from_mtl) return from_mtl_value;
        if (defaults_used) defaults_used->push_back(name);
        return default_value;
    };
    result.ka = pick(fields.ka, from_mtl ? from_mtl->ka : glm::vec3(0.0f), defaults.ka, "ka");
    result.kd = pick(fields.kd, from_mtl ? from_mtl->kd : glm::vec3(0.0f), defaults.kd, "kd");
    result.ks = pick(fields.ks, from_mtl ? from_mtl->ks : glm::vec3(0.0f), defaults.ks, "ks");
    result.n = pick(fields.n, from_mtl ? from_mtl->n : 0.0f, defaults.n, "n");
    return result;
}

namespace {

std::string format_number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.7g", value);
    return buffer;
}

std::string format_exact(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

template <typename Vector>
std::string format_triple(const Vector& v) {
    return "[" + format_number(double(v.x)) + ", " + format_number(double(v.y)) + ", " +
           format_number(double(v.z)) + "]";
}

/// [r, g, b], or the single number when all three are equal.
std::string format_coefficient(const glm::vec3& v) {
    if (v.x == v.y && v.y == v.z) return format_number(double(v.x));
    return format_triple(v);
}

}  // namespace

std::string scene_to_json(const Scene& scene, const std::string& mesh_path) {
    // Written by hand rather than json::dump so that each vector stays on one line.
    std::ostringstream out;
    out << "{\n";
    out << "  \"mesh\": " << json(mesh_path).dump() << ",\n";
    out << "  \"camera\": {\n";
    if (scene.camera.model == CameraModel::opencv) {
        const OpenCvCamera& cv = scene.camera.opencv;
        const auto row = [](const auto& values) {
            std::string text = "[";
            // Round-trip precision: 7 digits would bend a rotation by ~1e-7.
            for (std::size_t j = 0; j < values.size(); ++j) text += (j == 0 ? "" : ", ") + format_exact(values[j]);
            return text + "]";
        };
        const Matrix3x3 K = cv.K();
        const Matrix4x4 pose = cv.world_to_camera_4x4();
        out << "    \"K\": [" << row(K[0]) << ", " << row(K[1]) << ", " << row(K[2]) << "],\n";
        out << "    \"world_to_camera\": [" << row(pose[0]) << ",\n                        " << row(pose[1])
            << ",\n                        " << row(pose[2]) << ",\n                        " << row(pose[3]) << "]\n";
    } else {
        const bool orthographic = scene.camera.model == CameraModel::orthographic;
        if (orthographic) out << "    \"projection\": \"orthographic\",\n";
        out << "    \"eye\": " << format_triple(scene.camera.eye) << ", \"lookat\": " << format_triple(scene.camera.lookat)
            << ", \"up\": " << format_triple(scene.camera.up) << ",\n";
        out << "    ";
        if (!orthographic) out << "\"focal\": " << format_number(scene.camera.focal) << ", ";
        out << "\"sensor\": [" << format_number(scene.camera.sensor_height) << ", "
            << format_number(scene.camera.sensor_width) << "]\n";
    }
    out << "  },\n";
    out << "  \"image\": { \"height\": " << scene.image.rows << ", \"width\": " << scene.image.columns
        << ", \"background\": " << format_triple(scene.image.background) << " },\n";
    out << "  \"material\": { \"ka\": " << format_coefficient(scene.material.ka)
        << ", \"kd\": " << format_coefficient(scene.material.kd) << ", \"ks\": " << format_coefficient(scene.material.ks)
        << ", \"n\": " << format_number(double(scene.material.n)) << " },\n";
    out << "  \"ambient\": " << format_triple(scene.ambient) << ",\n";
    out << "  \"lights\": [";
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        out << (i == 0 ? "\n" : ",\n") << "    { \"position\": " << format_triple(scene.lights[i].position)
            << ", \"intensity\": " << format_triple(scene.lights[i].intensity) << " }";
    }
    out << (scene.lights.empty() ? "],\n" : "\n  ],\n");
    if (scene.normals == NormalSource::file) out << "  \"normals\": \"file\",\n";
    out << "  \"shader\": \"" << to_string(scene.shader) << "\",\n";
    out << "  \"lighting\": \"" << to_string(scene.lighting) << "\"\n";
    out << "}\n";
    return out.str();
}

}  // namespace phongrast::io
