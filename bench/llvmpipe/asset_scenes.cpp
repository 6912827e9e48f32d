#include "asset_scenes.hpp"

#include <iostream>

namespace llvmpipe_compare {

std::vector<NamedScene> asset_scenes(int /*rows*/) {
    // phongrast::io (the OBJ reader) has not landed yet; until it does, only the
    // generated scenes are compared.
    std::cerr << "bench_llvmpipe: shared asset meshes skipped (no OBJ reader in this build yet)\n";
    return {};
}

}  // namespace llvmpipe_compare
