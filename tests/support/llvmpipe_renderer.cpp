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

#include <glm/geometric.hpp>

namespace phongrast::support {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The contract's lighting formula, once, shared by both programs. LIGHT_COUNT
// is defined in front of this text. pow(x, 0) is undefined in GLSL for x = 0,
// so n = 0 is handled explicitly (the contract's 0^0 = 1).
const char* const kLightingGlsl = R"(
uniform vec3 u_eye;
uniform vec3 u_light_position[LIGHT_ARRAY];
uniform vec3 u_light_intensity[LIGHT_ARRAY];
uniform vec3 u_ambient_factor;   // ka * Ia
uniform vec3 u_kd;
uniform vec3 u_ks;
uniform float u_n;

vec3 unit_or_zero(vec3 v) {
    float length_squared = dot(v, v);
    return length_squared > 0.0 ? v * inversesqrt(length_squared) : vec3(0.0);
}

vec3 shade(vec3 point, vec3 normal, vec3 color) {
    vec3 n = unit_or_zero(normal);
    vec3 v = unit_or_zero(u_eye - point);
    vec3 result = u_ambient_factor * color;
    for (int k = 0; k < LIGHT_COUNT; ++k) {
        vec3 l = unit_or_zero(u_light_position[k] - point);
        float n_dot_l = dot(n, l);
        if (n_dot_l > 0.0) {
            result += u_light_intensity[k] * u_kd * color * n_dot_l;
            if (dot(v, v) > 0.0) {
                vec3 r = 2.0 * n * n_dot_l - l;
                float r_dot_v = clamp(dot(r, v), 0.0, 1.0);
                float highlight = u_n == 0.0 ? 1.0 : pow(r_dot_v, u_n);
                result += u_light_intensity[k] * u_ks * highlight;
            }
        }
    }
    return result;
}
)";

const char* const kGouraudVertex = R"(
uniform mat4 u_clip_from_world;
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec3 a_color;
varying vec3 v_lit;
void main() {
    v_lit = shade(a_position, a_normal, a_color);
    gl_Position = u_clip_from_world * vec4(a_position, 1.0);
}
)";
const char* const kGouraudFragment = R"(
varying vec3 v_lit;
void main() { gl_FragColor = vec4(v_lit, 1.0); }
)";

const char* const kPhongVertex = R"(
uniform mat4 u_clip_from_world;
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec3 a_color;
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_color;
void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_color = a_color;
    gl_Position = u_clip_from_world * vec4(a_position, 1.0);
}
)";
const char* const kPhongFragment = R"(
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_color;
void main() { gl_FragColor = vec4(shade(v_position, v_normal, v_color), 1.0); }
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

/// Gouraud lights in the vertex shader, Phong in the fragment shader.
GLuint link_program(bool phong, std::size_t light_count) {
    const std::string header = "#version 120\n#define LIGHT_COUNT " + std::to_string(light_count) +
                               "\n#define LIGHT_ARRAY " + std::to_string(std::max<std::size_t>(1, light_count)) +
                               "\n";
    const GLuint vertex =
        compile(GL_VERTEX_SHADER, header + (phong ? kPhongVertex : std::string(kLightingGlsl) + kGouraudVertex));
    const GLuint fragment =
        compile(GL_FRAGMENT_SHADER, header + (phong ? std::string(kLightingGlsl) + kPhongFragment : kGouraudFragment));
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glBindAttribLocation(program, 0, "a_position");
    glBindAttribLocation(program, 1, "a_normal");
    glBindAttribLocation(program, 2, "a_color");
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

/// Vertex buffer: position, normal, colour (white when the mesh has none), 9 floats
/// per vertex, bound to attributes 0, 1 and 2.
void upload_vertices(const phongrast::Mesh& mesh, GLuint buffer) {
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 9);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p(mesh.positions[i]);
        const glm::vec3 c = mesh.colors.empty() ? glm::vec3(1.0f) : mesh.colors[i];
        for (float value : {p.x, p.y, p.z, mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z, c.x, c.y, c.z}) {
            interleaved.push_back(value);
        }
    }
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), GL_STATIC_DRAW);
    const GLsizei stride = 9 * sizeof(float);
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexAttribArray(attribute);
        glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(std::size_t(attribute) * 3 * sizeof(float)));
    }
}

/// The contract's glFrustum after gluLookAt. The near plane is moved from
/// `focal` to 1e-4 x focal with the sides scaled alike, which keeps the x/y
/// projection identical and clips where phongrast clips (a frustum with
/// near = focal would cut away everything between the eye and the image plane).
/// The far plane lies beyond every vertex.
Matrix clip_from_world(const phongrast::Camera& camera, const std::vector<glm::dvec3>& positions) {
    const glm::dvec3 forward = glm::normalize(camera.lookat - camera.eye);
    double farthest = camera.focal;
    for (const glm::dvec3& p : positions) farthest = std::max(farthest, glm::dot(forward, p - camera.eye));
    const double scale = 1e-4;
    const double half_width = 0.5 * camera.sensor_width * scale;
    const double half_height = 0.5 * camera.sensor_height * scale;
    return multiply(frustum(-half_width, half_width, -half_height, half_height, camera.focal * scale, 2.0 * farthest),
                    look_at(camera.eye, camera.lookat, camera.up));
}

/// The uniforms of kLightingGlsl and the camera matrix.
void set_uniforms(GLuint program, const phongrast::Scene& scene) {
    const Matrix matrix_double = clip_from_world(scene.camera, scene.mesh.positions);
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
    const glm::vec3 eye(scene.camera.eye);
    const glm::vec3 ambient_factor = scene.material.ka * scene.ambient;
    glUniform3f(glGetUniformLocation(program, "u_eye"), eye.x, eye.y, eye.z);
    glUniform3f(glGetUniformLocation(program, "u_ambient_factor"), ambient_factor.x, ambient_factor.y,
                ambient_factor.z);
    glUniform3f(glGetUniformLocation(program, "u_kd"), scene.material.kd.x, scene.material.kd.y,
                scene.material.kd.z);
    glUniform3f(glGetUniformLocation(program, "u_ks"), scene.material.ks.x, scene.material.ks.y,
                scene.material.ks.z);
    glUniform1f(glGetUniformLocation(program, "u_n"), scene.material.n);
}

}  // namespace

struct LlvmpipeRenderer::State {
    OSMesaContext context = nullptr;
    std::vector<float> buffer;  // RGBA float, rows top to bottom
    int rows = 0;
    int columns = 0;

    GLuint vertex_buffer = 0;
    GLuint index_buffer = 0;
    GLuint program = 0;

    // What draw() needs every frame.
    std::vector<glm::dvec3> positions;
    std::vector<phongrast::Triangle> triangles;
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0.0};
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
}

LlvmpipeRenderer::~LlvmpipeRenderer() {
    if (state_->program != 0) glDeleteProgram(state_->program);
    glDeleteBuffers(1, &state_->vertex_buffer);
    glDeleteBuffers(1, &state_->index_buffer);
    OSMesaDestroyContext(state_->context);
}

void LlvmpipeRenderer::load(const phongrast::Scene& scene) {
    State& s = *state_;
    const phongrast::Mesh& mesh = scene.mesh;
    if (scene.shader == phongrast::Shader::flat) {
        throw std::invalid_argument("shader: the llvmpipe comparison implements gouraud and phong only");
    }
    if (mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh.normals: expected one per vertex (call calculate_normals first)");
    }
    if (!scene.lighting.ambient || !scene.lighting.diffuse || !scene.lighting.specular) {
        throw std::invalid_argument("lighting: the llvmpipe comparison implements 'full' only");
    }

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

    upload_vertices(mesh, s.vertex_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.index_buffer);

    if (s.program != 0) glDeleteProgram(s.program);
    const bool phong = scene.shader == phongrast::Shader::phong;
    s.program = link_program(phong, scene.lights.size());
    glUseProgram(s.program);
    set_uniforms(s.program, scene);

    s.eye = scene.camera.eye;
    s.forward = glm::normalize(scene.camera.lookat - scene.camera.eye);
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
        s.vertex_depth[i] = glm::dot(s.forward, s.positions[i] - s.eye);
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
        const phongrast::Triangle& tri = s.triangles[s.order[k]];
        s.indices[3 * k] = tri[0];
        s.indices[3 * k + 1] = tri[1];
        s.indices[3 * k + 2] = tri[2];
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
