// The subcommands. Each `add_*` registers its flags on the CLI11 app and
// returns the state its `run_*` reads after parsing.
#ifndef PHONGRAST_APPS_COMMANDS_HPP
#define PHONGRAST_APPS_COMMANDS_HPP

#include <string>

#include <CLI/CLI.hpp>

#include "batch_manifest.hpp"
#include "command_line.hpp"

namespace phongrast::cli {

/// --png-compression fast|default|small (png_compression_flag.cpp), into `value`.
void add_png_compression_flag(CLI::App& command, std::string& value);
/// --aov-files LIST and --depth-scale S (dataset_files_flags.cpp).
void add_dataset_file_flags(CLI::App& command, std::string& files, double& depth_scale);

struct RenderCommand {
    SceneFlags scene;
    int repeat = 0;  ///< 0: one render, no warm-up
    std::string stats_json;
    std::string aovs;          ///< --aov: "depth,normal,id,alpha" into one EXR
    bool transparent = false;  ///< --transparent: PNG with alpha, background transparent
    std::string png_compression = "default";
    std::string dataset_files;   ///< --aov-files: "depth,mask,..." next to the image
    double depth_scale = 0.001;  ///< --depth-scale: scene units per step of NAME.depth.png
    std::string camera_out;      ///< --camera-out: the image's camera as JSON (io/camera_record.hpp)
};
void add_render_command(CLI::App& app, RenderCommand& command);
int run_render(const RenderCommand& command);

struct SheetCommand {
    SceneFlags scene;
    std::string figures_folder;
};
void add_sheet_command(CLI::App& app, SheetCommand& command);
int run_sheet(const SheetCommand& command);

struct GenerateCommand {
    std::string output = "default.obj";
    int segments = 240;
    int sides = 20;
    bool quiet = false;
};
void add_generate_command(CLI::App& app, GenerateCommand& command);
int run_generate(const GenerateCommand& command);

struct BatchCommand {
    std::string manifest;
    std::string output_folder;
    std::string shard;  ///< "I/N"; empty: from the scheduler's variables
    int shards = 0;     ///< with JOB_COMPLETION_INDEX; 0: not given
    double job_timeout = 0.0;
    bool force = false;
    bool status = false;
    bool quiet = false;
    int threads = 0;
    int samples = 0;      ///< 0: not given
    JobSettings defaults;  ///< --shader, --lighting, --size and the named options (--mode, ...)
    std::string png_compression = "default";
    double depth_scale = 0.0;  ///< --depth-scale; 0: not given
};
void add_batch_command(CLI::App& app, BatchCommand& command);
int run_batch(const BatchCommand& command);

/// phongrast thumbnail INPUT OUTPUT --size N: the freedesktop thumbnailer
/// (Exec=phongrast thumbnail %i %o --size %s), thumbnail_command.cpp.
struct ThumbnailCommand {
    std::string input;
    std::string output;
    int size = 256;
    std::string png_compression = "default";
};
void add_thumbnail_command(CLI::App& app, ThumbnailCommand& command);
int run_thumbnail(const ThumbnailCommand& command);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_COMMANDS_HPP
