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

private:
    std::string name_;
};

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

void read_camera(const SceneReader& reader, const json& document, SceneFile& result) {
    const json::json_pointer root;
    Camera& out = result.scene.camera;
    const json::json_pointer camera_at = root / "camera";
    const json& camera = reader.require_object(
        reader.required_field(document, root, "camera", "an object with eye, lookat, up, focal, sensor"), camera_at);
    reader.warn_unknown(camera, camera_at, {"eye", "lookat", "up", "focal", "sensor"}, &result.warnings);
    out.eye = reader.triple(reader.required_field(camera, camera_at, "eye", "[x, y, z]"), camera_at / "eye");
    out.lookat = reader.triple(reader.required_field(camera, camera_at, "lookat", "[x, y, z]"), camera_at / "lookat");
    if (const json* up = reader.optional_field(camera, camera_at, "up")) {
        out.up = reader.triple(*up, camera_at / "up");
    }
    out.focal = reader.positive_number(reader.required_field(camera, camera_at, "focal", "a positive number"),
                                       camera_at / "focal");
    const json& sensor = reader.required_field(camera, camera_at, "sensor", "[height, width]");
    if (!sensor.is_array() || sensor.size() != 2) {
        reader.fail(camera_at / "sensor", "expected [height, width] (2 numbers), got " + type_of(sensor));
    }
    out.sensor_height = reader.positive_number(sensor[0], camera_at / "sensor" / 0);
    out.sensor_width = reader.positive_number(sensor[1], camera_at / "sensor" / 1);
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

void read_material(const SceneReader& reader, const json& document, SceneFile& result) {
    const json::json_pointer root;
    const json* material = reader.optional_field(document, root, "material");
    if (material == nullptr) return;
    const json::json_pointer material_at = root / "material";
    reader.require_object(*material, material_at);
    reader.warn_unknown(*material, material_at, {"ka", "kd", "ks", "n"}, &result.warnings);
    if (const json* ka = reader.optional_field(*material, material_at, "ka")) {
        result.material.ka = reader.coefficient(*ka, material_at / "ka");
    }
    if (const json* kd = reader.optional_field(*material, material_at, "kd")) {
        result.material.kd = reader.coefficient(*kd, material_at / "kd");
    }
    if (const json* ks = reader.optional_field(*material, material_at, "ks")) {
        result.material.ks = reader.coefficient(*ks, material_at / "ks");
    }
    if (const json* n = reader.optional_field(*material, material_at, "n")) {
        const double exponent = reader.number(*n, material_at / "n");
        if (exponent < 0.0) reader.fail(material_at / "n", "expected a non-negative number, got " + n->dump());
        result.material.n = static_cast<float>(exponent);
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
                        {"mesh", "camera", "image", "material", "ambient", "lights", "shader", "lighting"},
                        &result.warnings);
    read_mesh_path(reader, document, folder, result);
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
    out << "    \"eye\": " << format_triple(scene.camera.eye) << ", \"lookat\": " << format_triple(scene.camera.lookat)
        << ", \"up\": " << format_triple(scene.camera.up) << ",\n";
    out << "    \"focal\": " << format_number(scene.camera.focal) << ", \"sensor\": ["
        << format_number(scene.camera.sensor_height) << ", " << format_number(scene.camera.sensor_width) << "]\n";
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
    out << "  \"shader\": \"" << to_string(scene.shader) << "\",\n";
    out << "  \"lighting\": \"" << to_string(scene.lighting) << "\"\n";
    out << "}\n";
    return out.str();
}

}  // namespace phongrast::io
