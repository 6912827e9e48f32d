// libFuzzer target: the scene-file parser (phongrast::io::parse_scene_json),
// then a small render of the scene it accepts with a fixed tetrahedron as its
// mesh, so cameras, lights and materials reach the renderer.
//
// A clear error (phongrast::io::FileError, or std::invalid_argument from the
// renderer's validation) is the expected answer to bad input; anything else is
// a finding.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "fuzz_common.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        phongrast::io::SceneFile file = phongrast::io::parse_scene_json(text, "fuzz.json", "/nonexistent");
        phongrast_fuzz::render_small(phongrast_fuzz::tetrahedron(), &file.scene);
    } catch (const phongrast::io::FileError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
