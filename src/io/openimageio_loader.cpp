// Finds and dlopens phongrast_openimageio.so on first use (see openimageio_module.hpp).
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <dlfcn.h>

#include "openimageio_module.hpp"

namespace phongrast::io::detail {
namespace {

namespace fs = std::filesystem;

/// Where to look, in order (see the header).
std::vector<std::string> candidate_paths() {
    std::vector<std::string> paths;
    if (const char* named = std::getenv("PHONGRAST_OPENIMAGEIO_MODULE"); named && *named) {
        paths.emplace_back(named);
        return paths;  // named explicitly: nothing else is tried, so a wrong name is noticed
    }
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&candidate_paths), &info) != 0 && info.dli_fname && *info.dli_fname) {
        const fs::path folder = fs::absolute(fs::path(info.dli_fname)).parent_path();
        paths.push_back((folder / kOpenImageIoModuleFile).string());
        paths.push_back((folder / ".." / "lib" / "phongrast" / kOpenImageIoModuleFile).lexically_normal().string());
        paths.push_back((folder / ".." / PHONGRAST_INSTALL_LIBDIR / "phongrast" / kOpenImageIoModuleFile)
                            .lexically_normal()
                            .string());
    }
    paths.push_back((fs::path(PHONGRAST_INSTALLED_MODULE_DIR) / kOpenImageIoModuleFile).string());
    paths.emplace_back(PHONGRAST_BUILD_TREE_MODULE);
    return paths;
}

struct Loaded {
    const PhongrastOpenImageIoModule* module = nullptr;
    std::string failure;  ///< why it could not be loaded
};

Loaded load() {
    Loaded result;
    std::string tried;
    for (const std::string& path : candidate_paths()) {
        if (!fs::exists(path)) {
            tried += "\n  " + path + " (no such file)";
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            tried += "\n  " + path + " (" + (why ? why : "cannot load") + ")";
            continue;
        }
        using Entry = const PhongrastOpenImageIoModule* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, "phongrast_openimageio_module"));
        const PhongrastOpenImageIoModule* module = entry ? entry() : nullptr;
        if (!module || module->version != kPhongrastOpenImageIoModuleVersion) {
            tried += "\n  " + path + " (a different version of the module)";
            dlclose(handle);
            continue;
        }
        result.module = module;  // never closed: OpenImageIO's threads and caches live until the process ends
        return result;
    }
    result.failure = std::string("phongrast's OpenImageIO module ") + kOpenImageIoModuleFile +
                     " could not be loaded (install phongrast's runtime files, or name the file in "
                     "PHONGRAST_OPENIMAGEIO_MODULE); looked for:" + tried;
    return result;
}

}  // namespace

const PhongrastOpenImageIoModule& openimageio_module(const std::string& purpose) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.module) throw std::runtime_error(purpose + " needs OpenImageIO: " + loaded.failure);
    return *loaded.module;
}

}  // namespace phongrast::io::detail
