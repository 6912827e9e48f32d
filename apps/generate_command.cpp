// phongrast generate: writes the project's own default mesh as OBJ.
#include <filesystem>

#include "commands.hpp"
#include "default_mesh.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/obj_file.hpp"
#include "report.hpp"

namespace phongrast::cli {

void add_generate_command(CLI::App& app, GenerateCommand& command) {
    CLI::App* generate = app.add_subcommand(
        "generate",
        "Write the default scene's mesh: a (2,3) torus knot tube with rainbow vertex colours "
        "(assets/default.obj is this command's output with the default flags)");
    generate->add_option("-o,--output", command.output, "OBJ file to write")->capture_default_str();
    generate->add_option("--segments", command.segments, "Rings along the knot")
        ->check(CLI::Range(3, 100000))
        ->capture_default_str();
    generate->add_option("--sides", command.sides, "Vertices around each ring")
        ->check(CLI::Range(3, 1000))
        ->capture_default_str();
    generate->add_flag("-q,--quiet", command.quiet, "Print nothing but errors");
}

int run_generate(const GenerateCommand& command) {
    const Messages messages(command.quiet);
    const Mesh mesh = make_torus_knot(command.segments, command.sides);
    const std::string comment = "phongrast generate --segments " + std::to_string(command.segments) + " --sides " +
                                std::to_string(command.sides) +
                                "\n(2,3) torus knot tube, vertex colours r g b after x y z";
    io::write_obj(mesh, command.output, comment, 6);
    messages.result(std::to_string(mesh.triangles.size()) + " triangles, " + std::to_string(mesh.positions.size()) +
                    " vertices");
    messages.result("wrote " + std::filesystem::absolute(command.output).lexically_normal().string());
    return 0;
}

}  // namespace phongrast::cli
