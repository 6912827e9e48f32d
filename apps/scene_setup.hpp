// From command-line flags to a scene ready to render: the scene file or the
// automatically framed mesh (or the default scene), then the overrides.
#ifndef PHONGRAST_APPS_SCENE_SETUP_HPP
#define PHONGRAST_APPS_SCENE_SETUP_HPP

#include <string>

#include "command_line.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/render.hpp"
#include "report.hpp"

namespace phongrast::cli {

struct PreparedScene {
    Scene scene;
    RenderOptions options;
    std::string name;  ///< stem for default output names ("default", "bunny")
    double load_seconds = 0.0;  ///< reading and checking the mesh file
};

/// Finds assets/default.json: ./assets, then the source tree, then
/// <folder of the executable>/../share/phongrast, then the share folder of the
/// configured install prefix. Throws phongrast::io::FileError listing where it looked.
std::string find_default_scene();

/// Loads, frames and overrides. Notes (defaults used, the chosen scene of an
/// automatically framed mesh) go through `messages`. Throws io::FileError or
/// std::invalid_argument for bad input.
PreparedScene prepare_scene(const SceneFlags& flags, const Messages& messages);

/// prepare_scene for a scene given as JSON text (a batch manifest's inline
/// scene): `name` stands for the file in messages and is the PreparedScene's
/// name; relative mesh paths start at `folder`. Its input and mesh flags are not used.
PreparedScene prepare_scene_text(const std::string& text, const std::string& name, const std::string& folder,
                                 const SceneFlags& flags, const Messages& messages);

/// `output` if given, else NAME + suffix in the current folder. Checks the
/// extension and that the folder exists, before anything is rendered. A
/// default name that is already a file is replaced with a warning, so that
/// `render dog.ply` then `render dog.glb` do not overwrite dog.png silently.
std::string choose_output(const std::string& output, const std::string& default_name, const Messages& messages);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_SCENE_SETUP_HPP
