#include "batch_manifest.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/lighting.hpp"
#include "phongrast/option_names.hpp"
#include "phongrast/render.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int max_views = 100000;

std::string describe(const json& value) {
    if (value.is_string()) return "the string " + value.dump();
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_null()) return "null";
    if (value.is_array()) return "an array";
    if (value.is_object()) return "an object";
    return value.dump();
}

/// Reads the fields of one manifest line; every message names the line and the field.
class LineReader {
public:
    LineReader(const std::string& name, int line, const json& object) : object_(object) {
        where_ = name + ":" + std::to_string(line);
    }

    /// "manifest.jsonl:3", what every message starts with.
    const std::string& where() const { return where_; }

    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        throw io::FileError(where_ + ": " + (field.empty() ? "" : "/" + field + ": ") + what);
    }

    const json* find(const char* field) const {
        const auto it = object_.find(field);
        return it == object_.end() ? nullptr : &*it;
    }

    std::string text(const char* field) const {
        const json* value = find(field);
        if (value == nullptr) return "";
        if (!value->is_string() || value->get<std::string>().empty()) {
            fail(field, "expected a non-empty string, got " + describe(*value));
        }
        return value->get<std::string>();
    }

    std::optional<int> whole_number(const char* field, int low, int high) const {
        const json* value = find(field);
        if (value == nullptr) return std::nullopt;
        if (!value->is_number_integer() || value->get<long long>() < low || value->get<long long>() > high) {
            fail(field, "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high) +
                            ", got " + describe(*value));
        }
        return static_cast<int>(value->get<long long>());
    }

    std::optional<double> number(const char* field) const {
        const json* value = find(field);
        if (value == nullptr) return std::nullopt;
        if (!value->is_number()) fail(field, "expected a number, got " + describe(*value));
        return value->get<double>();
    }

    void reject_unknown_fields() const {
        std::set<std::string> known = {"scene", "mesh", "views", "elevation", "elevations", "layout", "shader",
                                       "lighting", "size", "samples", "output", "aov_files", "depth_scale",
                                       "camera_out", "transforms_out", "cameras"};
        std::string named;  // the rendering options' names, from the library's table
        for (const NamedOption& option : named_options()) {
            known.insert(option.key);
            named += ", " + option.key;
        }
        for (auto it = object_.begin(); it != object_.end(); ++it) {
            if (known.count(it.key()) == 0) {
                fail(it.key(), "unknown field; expected scene, mesh, views, elevation, elevations, layout, cameras, shader, "
                               "lighting, size, samples, aov_files, depth_scale, camera_out, transforms_out" + named +
                               " or output");
            }
        }
    }

private:
    const json& object_;
    std::string where_;
};

JobSettings read_settings(const LineReader& reader, const JobSettings& defaults) {
    JobSettings settings = defaults;
    if (const std::string shader = reader.text("shader"); !shader.empty()) settings.shader = shader;
    if (const std::string lighting = reader.text("lighting"); !lighting.empty()) settings.lighting = lighting;
    if (const std::string size = reader.text("size"); !size.empty()) settings.size = size;
    for (const NamedOption& option : named_options()) {
        if (const std::string name = reader.text(option.key.c_str()); !name.empty()) settings.options[option.key] = name;
    }
    if (const std::optional<int> samples = reader.whole_number("samples", 1, 16)) settings.samples = samples;
    if (const std::string files = reader.text("aov_files"); !files.empty()) settings.dataset_files = files;
    if (const std::string camera = reader.text("camera_out"); !camera.empty()) settings.camera_out = camera;
    if (const std::string transforms = reader.text("transforms_out"); !transforms.empty()) {
        settings.transforms_out = transforms;
    }
    if (const std::optional<double> scale = reader.number("depth_scale")) {
        if (!(*scale > 0.0)) reader.fail("depth_scale", "expected a positive number of scene units per step");
        settings.depth_scale = scale;
    }
    try {
        if (!settings.dataset_files.empty()) io::parse_dataset_files(settings.dataset_files);
    } catch (const std::invalid_argument& error) {
        reader.fail("aov_files", error.what());
    }
    // Names are checked now, so that a typo stops the whole batch before it starts.
    try {
        if (!settings.shader.empty()) parse_shader(settings.shader);
    } catch (const std::invalid_argument& error) {
        reader.fail("shader", error.what());
    }
    try {
        if (!settings.lighting.empty()) parse_lighting(settings.lighting);
    } catch (const std::invalid_argument& error) {
        reader.fail("lighting", error.what());
    }
    try {
        if (!settings.size.empty()) parse_size(settings.size);
    } catch (const std::invalid_argument&) {
        reader.fail("size", "expected \"WxH\" with whole numbers from 1 to " + std::to_string(kMaxImageSide) +
                                " and at most " + std::to_string(kMaxImagePixels) +
                                " pixels in all, e.g. \"640x480\"; got \"" + settings.size + "\"");
    }
    for (const auto& [key, name] : settings.options) {
        const NamedOption& option = named_option(key);
        const std::vector<std::string> accepted = accepted_names(option);
        if (name.empty() || std::find(accepted.begin(), accepted.end(), name) != accepted.end()) continue;
        std::string expected;
        for (std::size_t i = 0; i < option.choices.size(); ++i) {
            expected += (i == 0 ? "" : i + 1 == option.choices.size() ? " or " : ", ") +
                        ("\"" + option.choices[i].front() + "\"");
        }
        reader.fail(key, "expected " + expected + ", got \"" + name + "\"");
    }
    return settings;
}

// An elevation in degrees, strictly between -90 and 90: straight up or down
// the look-at camera's up vector would be parallel to its view.
double read_elevation(const LineReader& reader, const char* field, const json& value) {
    if (!value.is_number() || !(value.get<double>() > -90.0 && value.get<double>() < 90.0)) {
        reader.fail(field, "expected degrees between -90 and 90 (exclusive), got " + describe(value));
    }
    return value.get<double>();
}

// "cameras" of a mesh job: each element a camera object of the scene file's
// schema, read by the scene file's own reader (io::parse_camera_object), but
// strictly: a field the camera would ignore is an error here, as any unknown
// manifest field is.
void read_cameras(const LineReader& reader, const json& cameras, BatchJob& job) {
    if (!cameras.is_array() || cameras.empty()) {
        reader.fail("cameras", "expected a non-empty array of camera objects (docs/scene-format.md, Camera), got " +
                                   describe(cameras));
    }
    if (cameras.size() > static_cast<std::size_t>(max_views)) {
        reader.fail("cameras", std::to_string(cameras.size()) + " cameras; at most " + std::to_string(max_views) +
                                   " per job");
    }
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        const std::string field = "cameras/" + std::to_string(i);
        if (!cameras[i].is_object()) {
            reader.fail(field, "expected a camera object (look-at: eye, lookat, up, focal, sensor; OpenCV: K and "
                               "world_to_camera or camera_to_world; orthographic: projection, eye, lookat, up, "
                               "sensor), got " + describe(cameras[i]));
        }
        // The element's own text: nlohmann writes numbers so that they read back exactly.
        job.cameras.push_back(io::parse_camera_object(cameras[i].dump(), reader.where(), "/" + field,
                                                      io::UnusedCameraFields::refuse, nullptr));
    }
    job.views = static_cast<int>(job.cameras.size());
}

// An OpenCV camera's K is in pixels of the image, so the job must say which
// image ("size") and K's principal point must lie on it: a K made for
// another resolution (1920x1080 rendered at 640x480) is caught here.
void check_camera_pixels(const LineReader& reader, const BatchJob& job) {
    for (std::size_t i = 0; i < job.cameras.size(); ++i) {
        const Camera& camera = job.cameras[i];
        if (camera.model != CameraModel::opencv) continue;
        const std::string field = "cameras/" + std::to_string(i) + "/K";
        if (job.settings.size.empty()) {
            reader.fail(field, "an OpenCV camera's K is in pixels: give the image size it was made for, \"size\": "
                               "\"WxH\" on the line (or --size)");
        }
        const auto [columns, rows] = parse_size(job.settings.size);  // checked by read_settings
        const double cx = camera.opencv.cx, cy = camera.opencv.cy;
        // OpenCV puts pixel centres at whole numbers: the image spans [-0.5, N - 0.5] x [-0.5, M - 0.5].
        if (!(cx >= -0.5 && cx <= columns - 0.5 && cy >= -0.5 && cy <= rows - 0.5)) {
            std::ostringstream what;
            what << "the principal point (cx, cy) = (" << cx << ", " << cy << ") lies outside the "
                 << job.settings.size << " image (\"size\"); K is in pixels of that image: was it made for another size?";
            reader.fail(field, what.str());
        }
    }
}

// "layout", "views", "elevation" and "elevations" of a mesh job, or its "cameras".
void read_views(const LineReader& reader, const json& object, BatchJob& job) {
    for (const char* field : {"views", "elevation", "elevations", "layout"}) {
        if (job.kind != JobKind::mesh && object.contains(field)) reader.fail(field, "only a \"mesh\" job has views");
    }
    if (const json* cameras = reader.find("cameras")) {
        if (job.kind != JobKind::mesh) {
            reader.fail("cameras", "only a \"mesh\" job has cameras (a scene has its own \"camera\")");
        }
        for (const char* field : {"views", "layout", "elevation", "elevations"}) {
            if (object.contains(field)) {
                reader.fail(field, "\"cameras\" gives every view's camera; expected either \"cameras\" or "
                                   "views/layout/elevation(s), not both");
            }
        }
        read_cameras(reader, *cameras, job);
        return;
    }
    const std::string layout = reader.text("layout");
    if (layout == "sphere") {
        job.layout = ViewLayout::sphere;
    } else if (layout == "hemisphere") {
        job.layout = ViewLayout::hemisphere;
    } else if (!layout.empty() && layout != "turntable") {
        reader.fail("layout", "expected \"turntable\", \"sphere\" or \"hemisphere\", got \"" + layout + "\"");
    }
    const int views = reader.whole_number("views", 1, max_views).value_or(1);
    if (job.layout != ViewLayout::turntable) {
        for (const char* field : {"elevation", "elevations"}) {
            if (object.contains(field)) reader.fail(field, "a " + layout + " layout chooses its own elevations");
        }
        job.views = views;
        return;
    }
    if (object.contains("elevation") && object.contains("elevations")) {
        reader.fail("elevations", "both \"elevation\" and \"elevations\"; expected one of them");
    }
    if (const json* one = reader.find("elevation")) job.elevations = {read_elevation(reader, "elevation", *one)};
    if (const json* rings = reader.find("elevations")) {
        if (!rings->is_array() || rings->empty()) {
            reader.fail("elevations", "expected a non-empty array of degrees, got " + describe(*rings));
        }
        job.elevations.clear();
        for (std::size_t i = 0; i < rings->size(); ++i) {
            const std::string field = "elevations/" + std::to_string(i);
            job.elevations.push_back(read_elevation(reader, field.c_str(), (*rings)[i]));
        }
    }
    const long long total = static_cast<long long>(views) * static_cast<long long>(job.elevations.size());
    if (total > max_views) {
        reader.fail("elevations", std::to_string(views) + " views x " + std::to_string(job.elevations.size()) +
                                      " rings = " + std::to_string(total) + " images; at most " +
                                      std::to_string(max_views) + " per job");
    }
    job.views = static_cast<int>(total);
}

void read_source(const LineReader& reader, const json& object, const std::string& folder, BatchJob& job) {
    const json* scene = reader.find("scene");
    const json* mesh = reader.find("mesh");
    if ((scene == nullptr) == (mesh == nullptr)) {
        reader.fail("", scene ? "both \"scene\" and \"mesh\"; expected one of them"
                              : "expected \"scene\" (a scene file or an inline scene) or \"mesh\" (an OBJ file)");
    }
    if (scene != nullptr && scene->is_object()) {
        job.kind = JobKind::inline_scene;
        job.scene_json = scene->dump();
        job.folder = folder;
    } else if (scene != nullptr) {
        job.kind = JobKind::scene_file;
        job.path = (fs::path(folder) / reader.text("scene")).lexically_normal().string();
    } else {
        job.kind = JobKind::mesh;
        job.path = (fs::path(folder) / reader.text("mesh")).lexically_normal().string();
    }
    read_views(reader, object, job);
}

std::string default_pattern(const BatchJob& job) {
    return job.kind == JobKind::mesh && job.views > 1 ? "{name}-{view}.png" : "{name}.png";
}

std::string name_of(const BatchJob& job) {
    if (job.kind == JobKind::inline_scene) return "line-" + std::to_string(job.line);
    return fs::path(job.path).stem().string();
}

// `name` as a path inside the output folder (relative, no '..'), or the field's error.
std::string inside_output_folder(const LineReader& reader, const char* field, const std::string& name) {
    const fs::path path = fs::path(name).lexically_normal();
    bool climbs = path.is_absolute();
    for (const fs::path& part : path) climbs = climbs || part == "..";
    if (climbs) reader.fail(field, "'" + name + "' must stay inside the output folder (relative, no '..')");
    return path.string();
}

// A per-job file's pattern ({name}, {line}; one file for all views) expanded.
std::string job_file(const LineReader& reader, const char* field, const std::string& pattern, const BatchJob& job) {
    if (pattern.empty()) return "";
    if (pattern.find("{view") != std::string::npos) {
        reader.fail(field, "one file per job holds every view's camera: {view} has no value here");
    }
    std::string name;
    try {
        name = expand_output_pattern(pattern, name_of(job), job.line, 0, 1);
    } catch (const std::exception& error) {
        reader.fail(field, error.what());
    }
    if (fs::path(name).extension() != ".json") reader.fail(field, "expected a .json file name, got '" + name + "'");
    return inside_output_folder(reader, field, name);
}

void read_outputs(const LineReader& reader, BatchJob& job) {
    job.camera_file = job_file(reader, "camera_out", job.settings.camera_out, job);
    job.transforms_file = job_file(reader, "transforms_out", job.settings.transforms_out, job);
    std::string pattern = reader.text("output");
    if (pattern.empty()) pattern = default_pattern(job);
    for (int view = 0; view < job.views; ++view) {
        std::string output;
        try {
            output = expand_output_pattern(pattern, name_of(job), job.line, view, job.views);
            io::image_format_for(output);
        } catch (const std::exception& error) {
            reader.fail("output", error.what());
        }
        job.outputs.push_back(inside_output_folder(reader, "output", output));
    }
}

/// Follows a SAX parse of a line to the value it stopped at, for messages:
/// the JSON pointer of that value ("/cameras/1/world_to_camera/0/3").
class PathOfError : public nlohmann::json_sax<json> {
public:
    json::json_pointer pointer() const {
        json::json_pointer result;
        for (const Level& level : levels_) result = level.array ? result / level.index : result / level.key;
        return result;
    }
    std::size_t position = 0;  ///< bytes read when the parse stopped
    int error_id = 0;          ///< nlohmann's exception id (406: a number too large for a double)

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& key) override {
        levels_.back().key = key;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t at, const std::string&, const nlohmann::detail::exception& error) override {
        position = at;
        error_id = error.id;
        return false;
    }

private:
    struct Level {
        bool array = false;
        std::size_t index = 0;  ///< array: the element being read
        std::string key;        ///< object: the last key
    };
    std::vector<Level> levels_;

    bool value() {
        if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
        return true;
    }
    bool open(bool array) {
        levels_.push_back({array, 0, ""});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return value();
    }
};

/// The message for a line that is not JSON. NaN and Infinity (which Python's
/// json.dumps writes for float('nan') and float('inf')) and numbers too large
/// for a double name the field; other errors the byte.
[[noreturn]] void malformed_line(const std::string& text, const std::string& name, int line,
                                 const json::exception& error) {
    PathOfError path;
    json::sax_parse(text, &path);
    // The literal around where the parse stopped.
    const auto literal_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.'; };
    std::size_t start = std::min(path.position == 0 ? 0 : path.position - 1, text.size());
    while (start > 0 && literal_char(text[start - 1])) --start;
    std::size_t end = start;
    while (end < text.size() && literal_char(text[end])) ++end;
    const std::string literal = text.substr(start, end - start);
    std::string word = literal.substr(literal.find_first_not_of("+-") == std::string::npos ? 0 : literal.find_first_not_of("+-"));
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::string where = name + ":" + std::to_string(line);
    if (path.error_id == 406 || word == "nan" || word == "infinity" || word == "inf") {
        const std::string pointer = path.pointer().to_string();
        throw io::FileError(where + ": " + (pointer.empty() ? "/" : pointer) + ": expected a finite number, got " +
                            literal + " (JSON has no NaN or Infinity; check the numbers the line was made from)");
    }
    const std::string detail = error.what();
    const std::size_t colon = detail.find(": ");
    const auto* parse_error = dynamic_cast<const json::parse_error*>(&error);
    const std::size_t byte = parse_error != nullptr ? parse_error->byte : path.position;
    throw io::FileError(where + ":" + std::to_string(byte) + ": malformed JSON: " +
                        (colon == std::string::npos ? detail : detail.substr(colon + 2)));
}

BatchJob parse_line(const std::string& text, const std::string& name, int line, const std::string& folder,
                    const JobSettings& defaults) {
    json object;
    try {
        object = json::parse(text);
    } catch (const json::exception& error) {  // parse_error, or out_of_range for 1e999
        malformed_line(text, name, line, error);
    }
    const LineReader reader(name, line, object);
    if (!object.is_object()) reader.fail("", "expected a JSON object (one job per line), got " + describe(object));
    reader.reject_unknown_fields();
    BatchJob job;
    job.line = line;
    read_source(reader, object, folder, job);
    job.settings = read_settings(reader, defaults);
    check_camera_pixels(reader, job);
    if (!job.settings.dataset_files.empty()) job.dataset_files = io::parse_dataset_files(job.settings.dataset_files);
    if (job.settings.depth_scale) job.dataset_options.depth_scale = *job.settings.depth_scale;
    read_outputs(reader, job);
    return job;
}

}  // namespace

std::string expand_output_pattern(const std::string& pattern, const std::string& name, int line, int view,
                                  int views) {
    const int view_digits = static_cast<int>(std::to_string(std::max(0, views - 1)).size());
    std::string result;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '{') {
            result += pattern[i];
            continue;
        }
        const std::size_t close = pattern.find('}', i);
        if (close == std::string::npos) throw std::invalid_argument("'{' without '}' in \"" + pattern + "\"");
        const std::string key = pattern.substr(i + 1, close - i - 1);
        int width = view_digits;
        if (key == "name") {
            result += name;
        } else if (key == "line") {
            result += std::to_string(line);
        } else if (key == "view" || (key.rfind("view:", 0) == 0 && key.size() == 6 && std::isdigit(static_cast<unsigned char>(key[5])))) {
            if (key.size() == 6) width = key[5] - '0';
            const std::string digits = std::to_string(view);
            result += std::string(static_cast<std::size_t>(std::max(0, width - static_cast<int>(digits.size()))), '0');
            result += digits;
        } else {
            throw std::invalid_argument("unknown placeholder {" + key + "} in \"" + pattern +
                                        "\"; expected {name}, {line}, {view} or {view:N}");
        }
        i = close;
    }
    return result;
}

Manifest parse_manifest(const std::string& text, const std::string& name, const std::string& folder,
                        const JobSettings& defaults) {
    Manifest manifest;
    manifest.path = name;
    manifest.folder = folder;
    std::map<std::string, int> writer_of;  // output -> line, to find two jobs writing one image
    int line = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string content = text.substr(start, end - start);
        start = end + 1;
        ++line;
        if (content.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank lines are allowed
        BatchJob job = parse_line(content, name, line, folder, defaults);
        std::vector<std::string> files = job.files_of_job();
        for (std::size_t view = 0; view < job.outputs.size(); ++view) {
            for (const std::string& file : job.files_of_view(view)) files.push_back(file);
        }
        for (const std::string& output : files) {
            const auto [it, inserted] = writer_of.emplace(output, line);
            if (!inserted) {
                throw io::FileError(name + ":" + std::to_string(line) + ": /output: '" + output +
                                    "' is also written by line " + std::to_string(it->second) +
                                    (it->second == line ? " (add {view} to the pattern)" : "") +
                                    "; every file needs its own name");
            }
        }
        manifest.jobs.push_back(std::move(job));
    }
    return manifest;
}

std::vector<std::string> BatchJob::files_of_view(std::size_t view) const {
    std::vector<std::string> files = io::dataset_file_paths(outputs[view], dataset_files);
    files.push_back(outputs[view]);
    return files;
}

std::vector<std::string> BatchJob::files_of_job() const {
    std::vector<std::string> files;
    if (!camera_file.empty()) files.push_back(camera_file);
    if (!transforms_file.empty()) files.push_back(transforms_file);
    return files;
}

bool outputs_exist(const BatchJob& job, const std::string& output_folder) {
    std::error_code error;
    for (const std::string& file : job.files_of_job()) {
        if (!fs::is_regular_file(fs::path(output_folder) / file, error)) return false;
    }
    for (std::size_t view = 0; view < job.outputs.size(); ++view) {
        for (const std::string& output : job.files_of_view(view)) {
            if (!fs::is_regular_file(fs::path(output_folder) / output, error)) return false;
        }
    }
    return true;
}

Manifest read_manifest(const std::string& path, const JobSettings& defaults) {
    std::error_code error;
    if (fs::is_directory(path, error)) throw io::FileError(path + ": is a folder; expected a manifest (JSON Lines)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw io::FileError(path + ": manifest not found or unreadable");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string folder = fs::path(path).has_parent_path() ? fs::path(path).parent_path().string() : ".";
    return parse_manifest(text.str(), path, folder, defaults);
}

}  // namespace phongrast::cli
