// The C++ side of the Python module's bit-for-bit tests: evaluates the
// library's own light() and calculate_normals() on numbers read from stdin and
// prints the results with enough digits to round-trip exactly.
//
//   python_reference light     one case per line:
//       point(3) normal(3) color(3) eye(3) ka(3) kd(3) ks(3) n ambient(3) lighting light_count
//       then position(3) intensity(3) per light; prints the RGB result (double)
//   python_reference normals   "Nv NT", Nv positions (3 each), NT faces (3 each);
//       prints one normal (float) per line
//   python_reference shade     one triangle per line: gouraud|phong rows columns, then per corner
//       column row normal(3) color(3), then centroid(3) eye(3) ka(3) kd(3) ks(3) n ambient(3)
//       lighting light_count and position(3) intensity(3) per light; prints "row column r g b"
//       (double) per painted pixel, then an empty line
#include <array>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"
#include "phongrast/seed_fill.hpp"

namespace {

glm::dvec3 read3(std::istream& in) {
    glm::dvec3 v;
    in >> v.x >> v.y >> v.z;
    return v;
}

int run_light(std::istream& in) {
    while (true) {
        const glm::dvec3 point = read3(in), normal = read3(in), color = read3(in), eye = read3(in);
        phongrast::PhongMaterial material;
        material.ka = glm::vec3(read3(in));
        material.kd = glm::vec3(read3(in));
        material.ks = glm::vec3(read3(in));
        in >> material.n;
        const glm::dvec3 ambient = read3(in);
        std::string lighting;
        std::size_t count = 0;
        in >> lighting >> count;
        if (!in) return 0;
        std::vector<phongrast::PointLight> lights(count);
        for (phongrast::PointLight& light : lights) {
            light.position = read3(in);
            light.intensity = glm::vec3(read3(in));
        }
        const glm::dvec3 lit = phongrast::light<double>(point, normal, color, eye, material, lights, ambient,
                                                        phongrast::parse_lighting(lighting));
        std::printf("%.17g %.17g %.17g\n", lit.x, lit.y, lit.z);
    }
}

int run_normals(std::istream& in) {
    std::size_t vertex_count = 0, face_count = 0;
    in >> vertex_count >> face_count;
    std::vector<glm::dvec3> positions(vertex_count);
    for (glm::dvec3& p : positions) p = read3(in);
    std::vector<phongrast::Triangle> faces(face_count);
    for (phongrast::Triangle& f : faces) in >> f[0] >> f[1] >> f[2];
    if (!in) return 1;
    for (const glm::vec3& n : phongrast::calculate_normals(positions, faces)) {
        std::printf("%.9g %.9g %.9g\n", static_cast<double>(n.x), static_cast<double>(n.y), static_cast<double>(n.z));
    }
    return 0;
}

phongrast::PhongMaterial read_material(std::istream& in) {
    phongrast::PhongMaterial material;
    material.ka = glm::vec3(read3(in));
    material.kd = glm::vec3(read3(in));
    material.ks = glm::vec3(read3(in));
    in >> material.n;
    return material;
}

int run_shade(std::istream& in) {
    while (true) {
        std::string shader;
        int rows = 0, columns = 0;
        in >> shader >> rows >> columns;
        if (!in) return 0;
        std::array<phongrast::SeedCorner, 3> corners;
        for (phongrast::SeedCorner& corner : corners) {
            in >> corner.pixel.x >> corner.pixel.y;
            corner.normal = read3(in);
            corner.color = read3(in);
        }
        phongrast::SeedLighting lighting;
        lighting.centroid = read3(in);
        lighting.eye = read3(in);
        lighting.material = read_material(in);
        lighting.ambient = read3(in);
        std::string terms;
        std::size_t count = 0;
        in >> terms >> count;
        lighting.lighting = phongrast::parse_lighting(terms);
        lighting.lights.resize(count);
        for (phongrast::PointLight& light : lighting.lights) {
            light.position = read3(in);
            light.intensity = glm::vec3(read3(in));
        }
        const phongrast::PaintPixel print = [](int row, int column, const glm::dvec3& c) {
            std::printf("%d %d %.17g %.17g %.17g\n", row, column, c.x, c.y, c.z);
        };
        if (shader == "gouraud") {
            phongrast::shade_gouraud(corners, lighting, rows, columns, print);
        } else {
            phongrast::shade_phong(corners, lighting, rows, columns, print);
        }
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "light") return run_light(std::cin);
    if (mode == "normals") return run_normals(std::cin);
    if (mode == "shade") return run_shade(std::cin);
    std::fprintf(stderr, "usage: python_reference light|normals|shade < input\n");
    return 2;
}
