// phongrast thumbnail INPUT OUTPUT --size N: a mesh framed as `render MESH`
// frames it, drawn N x N on a transparent background into an RGBA PNG. The
// freedesktop thumbnailer (share/thumbnailers/phongrast.thumbnailer, written by
// the install) runs it as `phongrast thumbnail %i %o --size %s`.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "commands.hpp"
#include "process_exit.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "report.hpp"
#include "scene_setup.hpp"

namespace phongrast::cli {

void add_thumbnail_command(CLI::App& app, ThumbnailCommand& command) {
    CLI::App* thumbnail = app.add_subcommand(
        "thumbnail",
        "Write a thumbnail of a mesh (OBJ, PLY, STL, glTF/GLB): framed as `render MESH` frames it, SIZE x SIZE "
        "pixels, transparent background, RGBA PNG. For file managers (freedesktop thumbnailer: %i %o --size %s)");
    thumbnail->add_option("input", command.input, "Mesh file")->required();
    thumbnail->add_option("output", command.output, "PNG file to write (any name; PNG whatever its extension)")
        ->required();
    thumbnail->add_option("-s,--size", command.size, "Width and height in pixels")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    add_png_compression_flag(*thumbnail, command.png_compression);
}

int run_thumbnail(const ThumbnailCommand& command) {
    const Messages quiet(true);
    SceneFlags flags;
    flags.input = command.input;
    flags.size = std::to_string(command.size) + "x" + std::to_string(command.size);
    flags.quiet = true;
    PreparedScene prepared = prepare_scene(flags, quiet);
    prepared.options.aovs.alpha = true;  // the covered fraction: the background becomes transparent
    const RenderResult result = render(prepared.scene, prepared.options);

    io::ImageWriteOptions options;
    options.png_compression = io::parse_png_compression(command.png_compression);
    // File managers name the output as they like (not always *.png); the PNG
    // writer wants the extension, so write NAME.png next to it and rename.
    bool png_name = false;
    try {
        png_name = io::image_format_for(command.output) == io::ImageFormat::png;
    } catch (const io::FileError&) {
    }
    if (png_name) {
        io::write_png_with_alpha(result.image, result.aovs.alpha, prepared.scene.image.background, command.output,
                                 options);
        return end_one_off_process(0);
    }
    const std::string staged = command.output + ".png";
    io::write_png_with_alpha(result.image, result.aovs.alpha, prepared.scene.image.background, staged, options);
    if (std::rename(staged.c_str(), command.output.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(staged.c_str());
        throw io::FileError(command.output + ": cannot write: " + why);
    }
    return end_one_off_process(0);
}

}  // namespace phongrast::cli
