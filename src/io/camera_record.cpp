#include "phongrast/io/camera_record.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

namespace phongrast::io {
namespace {

// Keys in the order written here (nlohmann::json would sort them).
using json = nlohmann::ordered_json;

/// Pretty JSON with every array of numbers (a vector, a matrix row) on one line.
void write_compact(const json& value, int indent, std::string& out) {
    const std::string pad(static_cast<std::size_t>(indent) * 2, ' ');
    const std::string inner(static_cast<std::size_t>(indent + 1) * 2, ' ');
    const auto flat = [](const json& array) {
        return std::all_of(array.begin(), array.end(), [](const json& v) { return v.is_primitive(); });
    };
    if (value.is_object()) {
        out += "{\n";
        std::size_t i = 0;
        for (auto it = value.begin(); it != value.end(); ++it, ++i) {
            out += inner + json(it.key()).dump() + ": ";
            write_compact(it.value(), indent + 1, out);
            out += i + 1 < value.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (value.is_array() && !value.empty() && !flat(value)) {
        out += "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) {
            out += inner;
            write_compact(value[i], indent + 1, out);
            out += i + 1 < value.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else if (value.is_array()) {
        out += "[";
        for (std::size_t i = 0; i < value.size(); ++i) out += (i == 0 ? "" : ", ") + value[i].dump();
        out += "]";
    } else {
        out += value.dump();
    }
}

json rows_of(const Matrix3x3& m) { return json::array({m[0], m[1], m[2]}); }
json rows_of(const Matrix4x4& m) { return json::array({m[0], m[1], m[2], m[3]}); }
json triple(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

/// The largest z_c of the scene's vertices (objects placed by their transforms).
double farthest_depth(const Scene& scene, const CameraFrame& frame) {
    double farthest = -std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p : scene.mesh.positions) farthest = std::max(farthest, frame.camera_from_world(p).z);
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        for (const glm::dvec3& p : object.mesh->positions) {
            const glm::dvec3 world(object.transform * glm::dvec4(p, 1.0));
            farthest = std::max(farthest, frame.camera_from_world(world).z);
        }
    }
    return farthest;
}

/// The contract's camera object (what a scene's "camera" holds).
json camera_object(const Camera& camera) {
    if (camera.model == CameraModel::opencv) {
        return {{"K", rows_of(camera.opencv.K())}, {"world_to_camera", rows_of(camera.opencv.world_to_camera_4x4())}};
    }
    json out = {{"eye", triple(camera.eye)}, {"lookat", triple(camera.lookat)}, {"up", triple(camera.up)},
                {"sensor", json::array({camera.sensor_height, camera.sensor_width})}};
    if (camera.model == CameraModel::orthographic) {
        out["projection"] = "orthographic";
    } else {
        out["focal"] = camera.focal;
    }
    return out;
}

/// world_to_camera in OpenCV axes for any camera: a look-at or orthographic
/// camera's R has rows r, -u, f and t = -R eye.
Matrix4x4 opencv_pose(const Camera& camera, int rows, int columns) {
    if (camera.model == CameraModel::opencv) return camera.opencv.world_to_camera_4x4();
    const CameraFrame frame = make_camera_frame(camera, rows, columns);
    OpenCvCamera pose;
    const glm::dvec3 axes[3] = {frame.right, -frame.up, frame.forward};
    for (int i = 0; i < 3; ++i) {
        // + 0.0 turns a -0 (a negated zero of the basis) into 0 in the file.
        pose.world_to_camera[i] = {axes[i].x + 0.0, axes[i].y + 0.0, axes[i].z + 0.0, 0.0 - glm::dot(axes[i], camera.eye)};
    }
    return pose.world_to_camera_4x4();
}

/// camera_to_world with OpenGL's camera axes (x right, y up, z backward):
/// OpenCV's camera_to_world with its y and z columns negated.
Matrix4x4 opengl_camera_to_world(const Matrix4x4& world_to_camera) {
    OpenCvCamera pose;
    for (int i = 0; i < 3; ++i) pose.world_to_camera[i] = world_to_camera[i];
    Matrix4x4 out = pose.camera_to_world();
    for (int i = 0; i < 3; ++i) {
        out[i][1] = 0.0 - out[i][1];  // 0 - x, not -x: no -0 in the file
        out[i][2] = 0.0 - out[i][2];
        out[i][3] += 0.0;             // the eye's -0 entries too
    }
    return out;
}

}  // namespace

CameraRecord camera_record(const Scene& scene, const std::string& image_path, const std::string& camera_file) {
    namespace fs = std::filesystem;
    CameraRecord record;
    record.camera = scene.camera;
    record.rows = scene.image.rows;
    record.columns = scene.image.columns;
    const fs::path folder = fs::absolute(camera_file).parent_path();
    const fs::path relative = fs::absolute(image_path).lexically_normal().lexically_relative(folder.lexically_normal());
    record.file_path = relative.empty() ? fs::absolute(image_path).string() : relative.string();
    const CameraFrame frame = make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
    switch (scene.camera.model) {
        case CameraModel::look_at: record.near_depth = scene.camera.focal * 1e-4; break;
        case CameraModel::orthographic: record.near_depth = 0.0; break;
        case CameraModel::opencv: {
            const double farthest = farthest_depth(scene, frame);
            record.near_depth = farthest > 0.0 ? farthest * 1e-4 : 0.0;
            break;
        }
    }
    return record;
}

std::string transforms_json(const std::vector<CameraRecord>& records) {
    if (records.empty()) throw std::invalid_argument("transforms.json: no images");
    // The intrinsics of one record, as the layout names them.
    const auto intrinsics = [](const CameraRecord& record) {
        if (record.camera.model == CameraModel::orthographic) {
            throw std::invalid_argument("transforms.json: " + record.file_path +
                                        ": an orthographic camera has no focal length; the layout needs one");
        }
        const OpenCvCamera k = opencv_form(record.camera, record.rows, record.columns);
        if (k.skew != 0.0) {
            throw std::invalid_argument("transforms.json: " + record.file_path + ": K has skew " +
                                        std::to_string(k.skew) + "; the layout has no skew");
        }
        return json{{"fl_x", k.fx}, {"fl_y", k.fy}, {"cx", k.cx + 0.5}, {"cy", k.cy + 0.5},
                    {"w", record.columns}, {"h", record.rows}};
    };
    const json first = intrinsics(records.front());
    json document = {{"camera_model", "OPENCV"}};
    for (auto it = first.begin(); it != first.end(); ++it) document[it.key()] = it.value();
    const double fl_x = first["fl_x"].get<double>(), fl_y = first["fl_y"].get<double>();
    document["camera_angle_x"] = 2.0 * std::atan(records.front().columns / (2.0 * fl_x));
    document["camera_angle_y"] = 2.0 * std::atan(records.front().rows / (2.0 * fl_y));
    json frames = json::array();
    for (const CameraRecord& record : records) {
        json frame = {{"file_path", record.file_path}};
        const json own = intrinsics(record);
        if (own != first) {
            for (auto it = own.begin(); it != own.end(); ++it) frame[it.key()] = it.value();
        }
        frame["transform_matrix"] =
            rows_of(opengl_camera_to_world(opencv_pose(record.camera, record.rows, record.columns)));
        frames.push_back(std::move(frame));
    }
    document["frames"] = std::move(frames);
    std::string text;
    write_compact(document, 0, text);
    return text + "\n";
}

std::string camera_records_json(const std::vector<CameraRecord>& records) {
    json images = json::array();
    for (const CameraRecord& record : records) {
        const Camera& camera = record.camera;
        const Matrix4x4 pose = opencv_pose(camera, record.rows, record.columns);
        json image = {{"file_path", record.file_path},
                      {"width", record.columns},
                      {"height", record.rows},
                      {"projection", camera.model == CameraModel::orthographic ? "orthographic" : "perspective"}};
        image["K"] = camera.model == CameraModel::orthographic
                         ? json(nullptr)
                         : rows_of(opencv_form(camera, record.rows, record.columns).K());
        image["world_to_camera"] = rows_of(pose);
        image["camera_to_world_opengl"] = rows_of(opengl_camera_to_world(pose));
        image["look_at"] = camera.model == CameraModel::opencv ? json(nullptr) : camera_object(camera);
        image["near"] = record.near_depth;
        images.push_back(std::move(image));
    }
    json document = json::object();
    if (!records.empty()) document["camera"] = camera_object(records.front().camera);
    document["images"] = std::move(images);
    std::string text;
    write_compact(document, 0, text);
    return text + "\n";
}

}  // namespace phongrast::io
