// phongrast sheet: the seed's eight figures (Gouraud and Phong, each with
// ambient, diffuse, specular and full lighting) as one labelled grid.
#include <iterator>
#include <filesystem>

#include "commands.hpp"
#include "interrupt.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/sheet.hpp"
#include "report.hpp"
#include "scene_setup.hpp"

namespace phongrast::cli {
namespace {

struct Figure {
    Shader shader;
    Lighting lighting;
    const char* label;
    const char* file_stem;
};

const Figure figures[] = {
    {Shader::gouraud, Lighting::only_ambient(), "Gouraud, ambient", "gouraud-ambient"},
    {Shader::gouraud, Lighting::only_diffuse(), "Gouraud, diffuse", "gouraud-diffuse"},
    {Shader::gouraud, Lighting::only_specular(), "Gouraud, specular", "gouraud-specular"},
    {Shader::gouraud, Lighting::full(), "Gouraud, full", "gouraud-full"},
    {Shader::phong, Lighting::only_ambient(), "Phong, ambient", "phong-ambient"},
    {Shader::phong, Lighting::only_diffuse(), "Phong, diffuse", "phong-diffuse"},
    {Shader::phong, Lighting::only_specular(), "Phong, specular", "phong-specular"},
    {Shader::phong, Lighting::full(), "Phong, full", "phong-full"},
};

}  // namespace

void add_sheet_command(CLI::App& app, SheetCommand& command) {
    CLI::App* sheet = app.add_subcommand(
        "sheet",
        "Render the seed's eight figures (Gouraud and Phong x ambient, diffuse, specular, full) as one "
        "labelled 4x2 grid. --shader and --lighting are ignored: the sheet sets both per figure.");
    add_scene_flags(*sheet, command.scene,
                    "Sheet image, .png or .exr. Default: NAME-sheet.png in the current folder");
    sheet->add_option("--figures", command.figures_folder,
                      "Also write each figure to this folder as gouraud-ambient.png ... phong-full.png "
                      "(the sheet's extension)");
}

int run_sheet(const SheetCommand& command) {
    const Messages messages(command.scene.quiet);
    PreparedScene prepared = prepare_scene(command.scene, messages);
    const std::string output = choose_output(command.scene.output, prepared.name + "-sheet.png", messages);
    std::string extension = std::filesystem::path(output).extension().string();
    if (!command.figures_folder.empty()) {
        std::error_code error;
        if (!std::filesystem::is_directory(command.figures_folder, error)) {
            throw io::FileError(command.figures_folder + ": --figures folder does not exist");
        }
    }

    // No bar (the [figure/8] line shows progress); the callback lets Ctrl-C stop a figure mid-render.
    prepared.options.progress = progress_bar(false, "");
    stop_if_interrupted();
    std::vector<io::SheetCell> cells;
    RenderStats total;
    const int count = static_cast<int>(std::size(figures));
    for (int i = 0; i < count; ++i) {
        const Figure& figure = figures[i];
        messages.progress(i + 1, count, figure.label);
        prepared.scene.shader = figure.shader;
        prepared.scene.lighting = figure.lighting;
        RenderResult result = render(prepared.scene, prepared.options);
        total += result.stats;
        cells.push_back({std::move(result.image), figure.label});
    }
    messages.progress_done();

    stop_if_interrupted();
    io::write_image(io::compose_sheet(cells, 4), output);
    if (!command.figures_folder.empty()) {
        for (int i = 0; i < count; ++i) {
            const std::string path =
                (std::filesystem::path(command.figures_folder) / (std::string(figures[i].file_stem) + extension))
                    .string();
            io::write_image(cells[static_cast<std::size_t>(i)].image, path);
        }
    }
    messages.result("8 figures: " + summary_line(total, total.seconds));
    messages.result("wrote " + std::filesystem::absolute(output).lexically_normal().string());
    return 0;
}

}  // namespace phongrast::cli
