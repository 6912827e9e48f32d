// --png-compression, shared by render, batch and thumbnail.
#include "commands.hpp"

namespace phongrast::cli {

void add_png_compression_flag(CLI::App& command, std::string& value) {
    command.add_option("--png-compression", value,
                       "PNG only: fast (larger files), default, or small (slower); the pixels are the same")
        ->check(CLI::IsMember({"fast", "default", "small"}))
        ->capture_default_str();
}

}  // namespace phongrast::cli
