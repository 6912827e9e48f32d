#include "llvmpipe_renderer.hpp"

// OSMesa's library exports every GL entry point, so the prototypes can be
// called directly (no OSMesaGetProcAddress table needed).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace phongrast::support {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The contract's lighting formula, once, shared by both programs, split as
// the contract's texture rule splits it: A (carries the surface colour) and
// S (specular). LIGHT_COUNT is defined in front of this text. pow(x, 0) is
// undefined in GLSL for x = 0, so n = 0 is handled explicitly (the
// contract's 0^0 = 1). The orthographic camera's viewer is at infinity:
// V = u_toward_viewer (-f) everywhere.
const char* const kLightingGlsl = R"(
uniform vec3 u_eye;
uniform float u_viewer_at_infinity;
uniform vec3 u_toward_viewer;
uniform vec3 u_light_position[LIGHT_ARRAY];
uniform vec3 u_light_intensity[LIGHT_ARRAY];
uniform vec3 u_ambient;   // Ia

vec3 unit_or_zero(vec3 v) {
    float length_squared = dot(v, v);
    return length_squared > 0.0 ? v * inversesqrt(length_squared) : vec3(0.0);
}

void shade(vec3 point, vec3 normal, vec3 color, vec3 ka, vec3 kd, vec3 ks, float shininess,
           out vec3 carried, out vec3 specular) {
    vec3 n = unit_or_zero(normal);
    vec3 v = u_viewer_at_infinity > 0.5 ? u_toward_viewer : unit_or_zero(u_eye - point);
    carried = ka * u_ambient * color;
    specular = vec3(0.0);
    for (int k = 0; k < LIGHT_COUNT; ++k) {
        vec3 l = unit_or_zero(u_light_position[k] - point);
        float n_dot_l = dot(n, l);
        if (n_dot_l > 0.0) {
            carried += u_light_intensity[k] * kd * color * n_dot_l;
            if (dot(v, v) > 0.0) {
                vec3 r = 2.0 * n * n_dot_l - l;
                float r_dot_v = clamp(dot(r, v), 0.0, 1.0);
                float highlight = shininess == 0.0 ? 1.0 : pow(r_dot_v, shininess);
                specular += u_light_intensity[k] * ks * highlight;
            }
        }
    }
}
)";

// Per corner: position, normal, surface colour c (vertex colour x glTF
// colour factor), (s, t), the face's ka, kd, ks, and (n, textured).
const char* const kAttributesGlsl = R"(
uniform mat4 u_clip_from_world;
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec3 a_color;
attribute vec2 a_texcoord;
attribute vec3 a_ka;
attribute vec3 a_kd;
attribute vec3 a_ks;
attribute vec2 a_shininess_textured;
)";

// T(s, t): GL_LINEAR on level 0 of the face's texture, 1 for an untextured face.
const char* const kTexelGlsl = R"(
uniform sampler2D u_texture;
vec3 texel(vec2 texcoord, float textured) {
    return textured > 0.5 ? texture2D(u_texture, texcoord).rgb : vec3(1.0);
}
)";

// Gouraud: A and S per vertex, interpolated; the pixel is T x A + S.
const char* const kGouraudVertex = R"(
varying vec3 v_carried;
varying vec3 v_specular;
varying vec2 v_texcoord;
varying float v_textured;
void main() {
    shade(a_position, a_normal, a_color, a_ka, a_kd, a_ks, a_shininess_textured.x, v_carried, v_specular);
    v_texcoord = a_texcoord;
    v_textured = a_shininess_textured.y;
    gl_Position = u_clip_from_world * vec4(a_position, 1.0);
}
)";
const char* const kGouraudFragment = R"(
varying vec3 v_carried;
varying vec3 v_specular;
varying vec2 v_texcoord;
varying float v_textured;
void main() { gl_FragColor = vec4(texel(v_texcoord, v_textured) * v_carried + v_specular, 1.0); }
)";

// Phong: everything interpolated, the normal renormalised, c includes T.
// The varyings are declared alike in both stages (kPhongVaryings in front).
const char* const kPhongVaryings = R"(
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_color;
varying vec2 v_texcoord;
varying vec3 v_ka;
varying vec3 v_kd;
varying vec3 v_ks;
varying vec2 v_shininess_textured;
)";
const char* const kPhongVertex = R"(
void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_color = a_color;
    v_texcoord = a_texcoord;
    v_ka = a_ka;
    v_kd = a_kd;
    v_ks = a_ks;
    v_shininess_textured = a_shininess_textured;
    gl_Position = u_clip_from_world * vec4(a_position, 1.0);
}
)";
const char* const kPhongFragment = R"(
void main() {
    vec3 color = v_color * texel(v_texcoord, v_shininess_textured.y);
    vec3 carried;
    vec3 specular;
    shade(v_position, v_normal, color, v_ka, v_kd, v_ks, v_shininess_textured.x, carried, specular);
    gl_FragColor = vec4(carried + specular, 1.0);
}
)";

GLuint compile(GLenum kind, const std::string& source) {
    const GLuint shader = glCreateShader(kind);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::array<char, 4096> log{};
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error(std::string("GLSL compile error: ") + log.data());
    }
    return shader;
}

/// The attribute names in the order of upload_vertices' interleaved layout.
constexpr std::array<const char*, 8> kAttributeNames = {"a_position", "a_normal", "a_color", "a_texcoord",
                                                        "a_ka",       "a_kd",     "a_ks",    "a_shininess_textured"};
constexpr std::array<int, 8> kAttributeSizes = {3, 3, 3, 2, 3, 3, 3, 2};
constexpr int kFloatsPerCorner = 22;

/// Gouraud lights in the vertex shader, Phong in the fragment shader.
GLuint link_program(bool phong, std::size_t light_count) {
    const std::string header = "#version 120\n#define LIGHT_COUNT " + std::to_string(light_count) +
                               "\n#define LIGHT_ARRAY " + std::to_string(std::max<std::size_t>(1, light_count)) +
                               "\n";
    const GLuint vertex = compile(GL_VERTEX_SHADER, header + kAttributesGlsl +
                                                        (phong ? std::string(kPhongVaryings) + kPhongVertex
                                                               : std::string(kLightingGlsl) + kGouraudVertex));
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, header + kTexelGlsl +
                                                            (phong ? std::string(kLightingGlsl) + kPhongVaryings +
                                                                         kPhongFragment
                                                                   : std::string(kGouraudFragment)));
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    for (GLuint attribute = 0; attribute < kAttributeNames.size(); ++attribute) {
        glBindAttribLocation(program, attribute, kAttributeNames[attribute]);
    }
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::array<char, 4096> log{};
        glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
        glDeleteProgram(program);
        throw std::runtime_error(std::string("GLSL link error: ") + log.data());
    }
    return program;
}

/// Column-major 4x4 in double, as OpenGL lays matrices out.
using Matrix = std::array<double, 16>;

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix c{};
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) sum += a[k * 4 + row] * b[column * 4 + k];
            c[column * 4 + row] = sum;
        }
    }
    return c;
}

/// A matrix written as rows (as on paper), stored column-major.
Matrix from_rows(const std::array<std::array<double, 4>, 4>& rows) {
    Matrix m{};
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 4; ++column) m[column * 4 + row] = rows[row][column];
    }
    return m;
}

/// gluLookAt's matrix (the GLU man page's formula).
Matrix look_at(const glm::dvec3& eye, const glm::dvec3& lookat, const glm::dvec3& up) {
    const glm::dvec3 f = glm::normalize(lookat - eye);
    const glm::dvec3 s = glm::normalize(glm::cross(f, up));
    const glm::dvec3 u = glm::cross(s, f);
    return {s.x, u.x, -f.x, 0.0,
            s.y, u.y, -f.y, 0.0,
            s.z, u.z, -f.z, 0.0,
            -glm::dot(s, eye), -glm::dot(u, eye), glm::dot(f, eye), 1.0};
}

/// glFrustum's matrix (the OpenGL 2.1 specification's formula).
Matrix frustum(double left, double right, double bottom, double top, double near, double far) {
    return {2 * near / (right - left), 0.0, 0.0, 0.0,
            0.0, 2 * near / (top - bottom), 0.0, 0.0,
            (right + left) / (right - left), (top + bottom) / (top - bottom), -(far + near) / (far - near), -1.0,
            0.0, 0.0, -2 * far * near / (far - near), 0.0};
}

/// Where the camera is and which way it looks, from the scene's own fields
/// (not phongrast's CameraFrame): z_c = dot(forward, p - eye) for painter's
/// order, and the eye of the lighting formula.
struct ViewAxis {
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
};

ViewAxis view_axis(const phongrast::Camera& camera) {
    if (camera.model != phongrast::CameraModel::opencv) {
        return {camera.eye, glm::normalize(camera.lookat - camera.eye)};
    }
    // [X, Y, Z] = R p + t: the eye is -R^T t and z_c is R's third row . p + t_z.
    const phongrast::Matrix3x4& pose = camera.opencv.world_to_camera;
    glm::dvec3 eye(0.0);
    for (int i = 0; i < 3; ++i) eye -= pose[i][3] * glm::dvec3(pose[i][0], pose[i][1], pose[i][2]);
    return {eye, glm::dvec3(pose[2][0], pose[2][1], pose[2][2])};
}

/// The contract's camera as an OpenGL clip matrix, for every model.
///
/// Look-at: glFrustum after gluLookAt, with the near plane moved from `focal`
/// to 1e-4 x focal and the sides scaled alike, which keeps the x/y projection
/// identical and clips where phongrast clips (a frustum with near = focal
/// would cut away everything between the eye and the image plane).
/// OpenCV: K and [R | t] written straight into the clip matrix (w = Z), the
/// contract's +0.5 pixel centre included, near = 1e-4 x the largest z_c.
/// Orthographic: x_c, y_c scaled by the sensor, near at the eye's plane.
/// Rows come out top to bottom because OSMESA_Y_UP is 0 (window y up, memory
/// rows down). The far plane lies beyond every vertex.
Matrix clip_from_world(const phongrast::Camera& camera, const std::vector<glm::dvec3>& positions, int rows,
                       int columns) {
    const ViewAxis axis = view_axis(camera);
    double farthest = 0.0;
    for (const glm::dvec3& p : positions) farthest = std::max(farthest, glm::dot(axis.forward, p - axis.eye));
    switch (camera.model) {
        case phongrast::CameraModel::look_at: {
            farthest = std::max(farthest, camera.focal);
            const double scale = 1e-4;
            const double half_width = 0.5 * camera.sensor_width * scale;
            const double half_height = 0.5 * camera.sensor_height * scale;
            return multiply(
                frustum(-half_width, half_width, -half_height, half_height, camera.focal * scale, 2.0 * farthest),
                look_at(camera.eye, camera.lookat, camera.up));
        }
        case phongrast::CameraModel::opencv: {
            const phongrast::OpenCvCamera& cv = camera.opencv;
            const double n = std::max(1e-4 * farthest, 1e-300), f = 2.0 * std::max(farthest, n);
            const double N = columns, M = rows;
            const Matrix projection = from_rows({{{2 * cv.fx / N, 2 * cv.skew / N, 2 * (cv.cx + 0.5) / N - 1, 0.0},
                                                  {0.0, -2 * cv.fy / M, 1 - 2 * (cv.cy + 0.5) / M, 0.0},
                                                  {0.0, 0.0, (f + n) / (f - n), -2 * f * n / (f - n)},
                                                  {0.0, 0.0, 1.0, 0.0}}});
            const phongrast::Matrix3x4& pose = cv.world_to_camera;
            const Matrix world_to_camera = from_rows({{pose[0], pose[1], pose[2], {0.0, 0.0, 0.0, 1.0}}});
            return multiply(projection, world_to_camera);
        }
        case phongrast::CameraModel::orthographic: {
            const glm::dvec3 f = axis.forward;
            const glm::dvec3 r = glm::normalize(glm::cross(f, camera.up));
            const glm::dvec3 u = glm::cross(r, f);
            const glm::dvec3& e = camera.eye;
            const Matrix camera_from_world = from_rows({{{r.x, r.y, r.z, -glm::dot(r, e)},
                                                         {u.x, u.y, u.z, -glm::dot(u, e)},
                                                         {f.x, f.y, f.z, -glm::dot(f, e)},
                                                         {0.0, 0.0, 0.0, 1.0}}});
            const double far = 2.0 * std::max(farthest, 1e-300);
            const Matrix projection = from_rows({{{2 / camera.sensor_width, 0.0, 0.0, 0.0},
                                                  {0.0, 2 / camera.sensor_height, 0.0, 0.0},
                                                  {0.0, 0.0, 2 / far, -1.0},
                                                  {0.0, 0.0, 0.0, 1.0}}});
            return multiply(projection, camera_from_world);
        }
    }
    throw std::invalid_argument("camera.model: unknown");
}

/// The one texture image the scene's faces use (null for none). The
/// comparison binds one texture for the whole draw, so a scene whose faces
/// use two different images is refused.
const phongrast::TextureMap* only_texture(const phongrast::Mesh& mesh) {
    const phongrast::TextureMap* found = nullptr;
    for (const phongrast::FaceMaterial& material : mesh.materials) {
        if (!material.texture || !material.texture->image) continue;
        if (found != nullptr && found->image != material.texture->image) {
            throw std::invalid_argument("mesh.materials: the llvmpipe comparison binds one texture image per scene");
        }
        found = &*material.texture;
    }
    return found;
}

GLint gl_wrap(phongrast::TextureWrap wrap) {
    switch (wrap) {
        case phongrast::TextureWrap::repeat: return GL_REPEAT;
        case phongrast::TextureWrap::clamp_to_edge: return GL_CLAMP_TO_EDGE;
        case phongrast::TextureWrap::mirrored_repeat: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

/// The texture as 32-bit float RGB on level 0 only, GL_LINEAR both ways (the
/// contract's lookup). Rows go up bottom first: OpenGL's t = 0 is the first
/// row it is given, the contract's t = 0 the image's bottom row.
void upload_texture(const phongrast::TextureMap& map, GLuint texture) {
    const phongrast::TextureImage& image = *map.image;
    std::vector<float> texels;
    texels.reserve(image.texels.size() * 3);
    for (int row = image.rows - 1; row >= 0; --row) {
        for (int column = 0; column < image.columns; ++column) {
            const glm::vec3& t = image.at(row, column);
            texels.insert(texels.end(), {t.x, t.y, t.z});
        }
    }
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F_ARB, image.columns, image.rows, 0, GL_RGB, GL_FLOAT, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(map.wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(map.wrap_t));
}

/// What one GL vertex is made of: a position with the texture coordinate,
/// file normal and material of the corners that share it.
struct CornerKey {
    std::uint32_t position = 0, texcoord = phongrast::kNoIndex, normal = phongrast::kNoIndex,
                  material = phongrast::kNoIndex;
    bool operator==(const CornerKey& other) const {
        return position == other.position && texcoord == other.texcoord && normal == other.normal &&
               material == other.material;
    }
};
struct CornerKeyHash {
    std::size_t operator()(const CornerKey& key) const {
        std::uint64_t h = key.position;
        for (std::uint32_t part : {key.texcoord, key.normal, key.material}) h = h * 0x9E3779B97F4A7C15ull ^ part;
        return std::size_t(h ^ (h >> 29));
    }
};

/// The vertex buffer (kFloatsPerCorner floats per vertex, bound to the
/// attributes of kAttributeNames) and, per triangle corner, its vertex.
///
/// Vertices are welded as an OpenGL application would weld an OBJ: corners
/// share a vertex when they share position, texture coordinate, file normal
/// and material, so a mesh without per-corner attributes keeps one vertex per
/// position, in its own order (the vertex shader runs once per vertex, as it
/// did before textures were added to this comparison). Each face's material
/// follows the contract's precedence for a one-mesh scene: the scene's fields,
/// then the face's own, then the base material.
std::vector<std::uint32_t> upload_vertices(const phongrast::Scene& scene, GLuint buffer) {
    const phongrast::Mesh& mesh = scene.mesh;
    const bool file_normals = scene.normals == phongrast::NormalSource::file && !mesh.file_normals.empty();
    const auto key_of = [&](std::size_t t, int corner) {
        CornerKey key;
        key.position = mesh.triangles[t][std::size_t(corner)];
        key.material = t < mesh.face_materials.size() ? mesh.face_materials[t] : phongrast::kNoIndex;
        const phongrast::FaceMaterial* face =
            key.material == phongrast::kNoIndex ? nullptr : &mesh.materials[key.material];
        const bool textured = face != nullptr && face->texture && face->texture->image &&
                              t < mesh.texcoord_triangles.size() &&
                              mesh.texcoord_triangles[t][0] != phongrast::kNoIndex;
        if (textured) key.texcoord = mesh.texcoord_triangles[t][std::size_t(corner)];
        if (file_normals && t < mesh.file_normal_triangles.size()) {
            const std::uint32_t k = mesh.file_normal_triangles[t][std::size_t(corner)];
            if (k != phongrast::kNoIndex && mesh.file_normals[k] != glm::vec3(0.0f)) key.normal = k;
        }
        return key;
    };
    std::vector<float> interleaved;
    const auto append = [&](const CornerKey& key) {
        const phongrast::FaceMaterial* face =
            key.material == phongrast::kNoIndex ? nullptr : &mesh.materials[key.material];
        phongrast::PhongMaterial material = scene.material;
        if (face != nullptr) material = face->coefficients.over(material);
        material = scene.material_fields.over(material);
        const glm::vec3 factor = face != nullptr ? face->color_factor : glm::vec3(1.0f);
        const glm::vec3 p(mesh.positions[key.position]);
        const glm::vec3 normal = key.normal != phongrast::kNoIndex ? mesh.file_normals[key.normal] : mesh.normals[key.position];
        const glm::vec3 c = (mesh.colors.empty() ? glm::vec3(1.0f) : mesh.colors[key.position]) * factor;
        const bool textured = key.texcoord != phongrast::kNoIndex;
        const glm::vec2 st = textured ? mesh.texcoords[key.texcoord] : glm::vec2(0.0f);
        for (float value : {p.x, p.y, p.z, normal.x, normal.y, normal.z, c.x, c.y, c.z, st.x, st.y, material.ka.x,
                            material.ka.y, material.ka.z, material.kd.x, material.kd.y, material.kd.z, material.ks.x,
                            material.ks.y, material.ks.z, material.n, textured ? 1.0f : 0.0f}) {
            interleaved.push_back(value);
        }
    };

    std::vector<std::uint32_t> corner_vertex(mesh.triangles.size() * 3);
    std::vector<CornerKey> keys(corner_vertex.size());
    bool per_position = true;  // every corner of a position has the same key
    std::vector<std::uint32_t> key_of_position(mesh.positions.size(), phongrast::kNoIndex);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int corner = 0; corner < 3; ++corner) {
            const CornerKey key = key_of(t, corner);
            keys[3 * t + std::size_t(corner)] = key;
            std::uint32_t& first = key_of_position[key.position];
            if (first == phongrast::kNoIndex) first = std::uint32_t(3 * t + std::size_t(corner));
            per_position = per_position && keys[first] == key;
        }
    }
    if (per_position) {
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            append(key_of_position[v] == phongrast::kNoIndex ? CornerKey{std::uint32_t(v)} : keys[key_of_position[v]]);
        }
        for (std::size_t k = 0; k < keys.size(); ++k) corner_vertex[k] = keys[k].position;
    } else {
        std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertex_of;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const auto [it, inserted] = vertex_of.emplace(keys[k], std::uint32_t(vertex_of.size()));
            if (inserted) append(keys[k]);
            corner_vertex[k] = it->second;
        }
    }

    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), GL_STATIC_DRAW);
    const GLsizei stride = kFloatsPerCorner * sizeof(float);
    std::size_t offset = 0;
    for (GLuint attribute = 0; attribute < kAttributeSizes.size(); ++attribute) {
        glEnableVertexAttribArray(attribute);
        glVertexAttribPointer(attribute, kAttributeSizes[attribute], GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset * sizeof(float)));
        offset += std::size_t(kAttributeSizes[attribute]);
    }
    return corner_vertex;
}

/// The uniforms of kLightingGlsl, the texture unit and the camera matrix.
void set_uniforms(GLuint program, const phongrast::Scene& scene) {
    const Matrix matrix_double =
        clip_from_world(scene.camera, scene.mesh.positions, scene.image.rows, scene.image.columns);
    std::array<float, 16> matrix{};
    std::transform(matrix_double.begin(), matrix_double.end(), matrix.begin(), [](double v) { return float(v); });
    glUniformMatrix4fv(glGetUniformLocation(program, "u_clip_from_world"), 1, GL_FALSE, matrix.data());

    std::vector<float> light_positions, light_intensities;
    for (const phongrast::PointLight& light : scene.lights) {
        const glm::vec3 p(light.position);
        light_positions.insert(light_positions.end(), {p.x, p.y, p.z});
        light_intensities.insert(light_intensities.end(), {light.intensity.x, light.intensity.y, light.intensity.z});
    }
    if (!scene.lights.empty()) {
        glUniform3fv(glGetUniformLocation(program, "u_light_position"), GLsizei(scene.lights.size()),
                     light_positions.data());
        glUniform3fv(glGetUniformLocation(program, "u_light_intensity"), GLsizei(scene.lights.size()),
                     light_intensities.data());
    }
    const ViewAxis axis = view_axis(scene.camera);
    const glm::vec3 eye(axis.eye), toward_viewer(-axis.forward);
    glUniform3f(glGetUniformLocation(program, "u_eye"), eye.x, eye.y, eye.z);
    glUniform1f(glGetUniformLocation(program, "u_viewer_at_infinity"),
                scene.camera.model == phongrast::CameraModel::orthographic ? 1.0f : 0.0f);
    glUniform3f(glGetUniformLocation(program, "u_toward_viewer"), toward_viewer.x, toward_viewer.y, toward_viewer.z);
    glUniform3f(glGetUniformLocation(program, "u_ambient"), scene.ambient.x, scene.ambient.y, scene.ambient.z);
    glUniform1i(glGetUniformLocation(program, "u_texture"), 0);
}

}  // namespace

struct LlvmpipeRenderer::State {
    OSMesaContext context = nullptr;
    std::vector<float> buffer;  // RGBA float, rows top to bottom
    int rows = 0;
    int columns = 0;

    GLuint vertex_buffer = 0;
    GLuint index_buffer = 0;
    GLuint texture = 0;
    GLuint program = 0;

    // What draw() needs every frame.
    std::vector<glm::dvec3> positions;
    std::vector<phongrast::Triangle> triangles;
    std::vector<std::uint32_t> corner_vertex;  // per triangle corner, its GL vertex
    ViewAxis axis;
    glm::vec3 background{0.0f};
    std::vector<double> vertex_depth;
    std::vector<double> triangle_depth;
    std::vector<std::uint32_t> order;
    std::vector<std::uint32_t> indices;
};

LlvmpipeRenderer::LlvmpipeRenderer() : state_(std::make_unique<State>()) {
    state_->context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (state_->context == nullptr) throw std::runtime_error("OSMesaCreateContextExt failed");
    // A context only becomes current with a buffer; start with 1 x 1.
    state_->rows = state_->columns = 1;
    state_->buffer.assign(4, 0.0f);
    if (!OSMesaMakeCurrent(state_->context, state_->buffer.data(), GL_FLOAT, 1, 1)) {
        OSMesaDestroyContext(state_->context);
        throw std::runtime_error("OSMesaMakeCurrent with a GL_FLOAT buffer failed");
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    glGenBuffers(1, &state_->vertex_buffer);
    glGenBuffers(1, &state_->index_buffer);
    glGenTextures(1, &state_->texture);
}

LlvmpipeRenderer::~LlvmpipeRenderer() {
    if (state_->program != 0) glDeleteProgram(state_->program);
    glDeleteBuffers(1, &state_->vertex_buffer);
    glDeleteBuffers(1, &state_->index_buffer);
    glDeleteTextures(1, &state_->texture);
    OSMesaDestroyContext(state_->context);
}

void LlvmpipeRenderer::load(const phongrast::Scene& scene) {
    State& s = *state_;
    const phongrast::Mesh& mesh = scene.mesh;
    if (scene.shader == phongrast::Shader::flat) {
        throw std::invalid_argument("shader: the llvmpipe comparison implements gouraud and phong only");
    }
    if (!scene.objects.empty()) {
        throw std::invalid_argument("objects: the llvmpipe comparison draws one-mesh scenes only");
    }
    if (mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh.normals: expected one per vertex (call calculate_normals first)");
    }
    if (!scene.lighting.ambient || !scene.lighting.diffuse || !scene.lighting.specular) {
        throw std::invalid_argument("lighting: the llvmpipe comparison implements 'full' only");
    }
    const phongrast::TextureMap* texture = only_texture(mesh);

    s.rows = scene.image.rows;
    s.columns = scene.image.columns;
    s.buffer.assign(std::size_t(s.rows) * std::size_t(s.columns) * 4, 0.0f);
    if (!OSMesaMakeCurrent(s.context, s.buffer.data(), GL_FLOAT, s.columns, s.rows)) {
        throw std::runtime_error("OSMesaMakeCurrent failed for " + std::to_string(s.columns) + "x" +
                                 std::to_string(s.rows));
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    glViewport(0, 0, s.columns, s.rows);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DITHER);
    glDisable(GL_BLEND);

    s.corner_vertex = upload_vertices(scene, s.vertex_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.index_buffer);
    glActiveTexture(GL_TEXTURE0);
    if (texture != nullptr) upload_texture(*texture, s.texture);

    if (s.program != 0) glDeleteProgram(s.program);
    const bool phong = scene.shader == phongrast::Shader::phong;
    s.program = link_program(phong, scene.lights.size());
    glUseProgram(s.program);
    set_uniforms(s.program, scene);

    s.axis = view_axis(scene.camera);
    s.positions = mesh.positions;
    s.triangles = mesh.triangles;
    s.background = scene.image.background;
    s.vertex_depth.resize(mesh.positions.size());
    s.triangle_depth.resize(mesh.triangles.size());
    s.order.resize(mesh.triangles.size());
    s.indices.resize(mesh.triangles.size() * 3);
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL error while loading the scene");
}

FrameTimes LlvmpipeRenderer::draw() {
    State& s = *state_;
    FrameTimes times;
    const Clock::time_point start = Clock::now();

    // Painter's order as the contract defines it: mean z_c, farthest first, stable.
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        s.vertex_depth[i] = glm::dot(s.axis.forward, s.positions[i] - s.axis.eye);
    }
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        const phongrast::Triangle& tri = s.triangles[t];
        s.triangle_depth[t] = (s.vertex_depth[tri[0]] + s.vertex_depth[tri[1]] + s.vertex_depth[tri[2]]) / 3.0;
    }
    std::iota(s.order.begin(), s.order.end(), 0u);
    std::stable_sort(s.order.begin(), s.order.end(), [&s](std::uint32_t a, std::uint32_t b) {
        return s.triangle_depth[a] > s.triangle_depth[b];
    });
    for (std::size_t k = 0; k < s.order.size(); ++k) {
        const std::size_t first = 3 * std::size_t(s.order[k]);
        s.indices[3 * k] = s.corner_vertex[first];
        s.indices[3 * k + 1] = s.corner_vertex[first + 1];
        s.indices[3 * k + 2] = s.corner_vertex[first + 2];
    }
    times.sort = seconds_since(start);

    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(s.indices.size() * sizeof(std::uint32_t)), s.indices.data(),
                 GL_STREAM_DRAW);
    glClearColor(s.background.x, s.background.y, s.background.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(s.indices.size()), GL_UNSIGNED_INT, nullptr);
    glFinish();
    times.total = seconds_since(start);
    return times;
}

phongrast::Image LlvmpipeRenderer::image() const {
    const State& s = *state_;
    phongrast::Image image(s.rows, s.columns);
    for (int row = 0; row < s.rows; ++row) {
        for (int column = 0; column < s.columns; ++column) {
            const float* rgba = &s.buffer[(std::size_t(row) * std::size_t(s.columns) + std::size_t(column)) * 4];
            image.at(row, column) = glm::vec3(rgba[0], rgba[1], rgba[2]);
        }
    }
    return image;
}

std::string LlvmpipeRenderer::description() const {
    const auto text = [](GLenum name) {
        const GLubyte* value = glGetString(name);
        return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
    };
    return text(GL_RENDERER) + " / " + text(GL_VERSION);
}

}  // namespace phongrast::support

// Mesa 22.3's OSMesa never frees the framebuffers OSMesaMakeCurrent creates
// (about 1 KB per process, all allocated inside libOSMesa). LeakSanitizer reads
// this hook in sanitizer builds (the asan preset) so that Mesa's leak does not
// fail our tests; leaks in phongrast's own code are still reported.
extern "C" __attribute__((used, visibility("default"))) const char* __lsan_default_suppressions() {
    return "leak:libOSMesa.so\n";
}
