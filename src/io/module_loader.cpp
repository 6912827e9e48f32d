// Finds and dlopens one of phongrast's modules (see module_loader.hpp).
#include "module_loader.hpp"

#include <cstdlib>
#include <filesystem>
#include <vector>

#include <dlfcn.h>

namespace phongrast::io::detail {
namespace {

namespace fs = std::filesystem;

/// Where to look, in order (see the header).
std::vector<std::string> candidate_paths(const ModuleSearch& search) {
    std::vector<std::string> paths;
    if (const char* named = std::getenv(search.environment); named && *named) {
        paths.emplace_back(named);
        return paths;  // named explicitly: nothing else is tried, so a wrong name is noticed
    }
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&candidate_paths), &info) != 0 && info.dli_fname && *info.dli_fname) {
        const fs::path folder = fs::absolute(fs::path(info.dli_fname)).parent_path();
        paths.push_back((folder / search.file).string());
        paths.push_back((folder / ".." / "lib" / "phongrast" / search.file).lexically_normal().string());
        paths.push_back(
            (folder / ".." / PHONGRAST_INSTALL_LIBDIR / "phongrast" / search.file).lexically_normal().string());
    }
    paths.push_back((fs::path(PHONGRAST_INSTALLED_MODULE_DIR) / search.file).string());
    paths.emplace_back(search.build_tree_file);
    return paths;
}

}  // namespace

LoadedModule load_module(const ModuleSearch& search) {
    LoadedModule result;
    std::string tried;
    for (const std::string& path : candidate_paths(search)) {
        std::error_code error;
        if (!fs::exists(path, error)) {
            tried += "\n  " + path + " (no such file)";
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            tried += "\n  " + path + " (" + (why ? why : "cannot load") + ")";
            continue;
        }
        using Entry = const void* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, search.entry));
        const void* table = entry ? entry() : nullptr;
        if (!table || *static_cast<const int*>(table) != search.version) {
            tried += "\n  " + path + " (a different version of the module)";
            dlclose(handle);
            continue;
        }
        result.table = table;  // never closed: see the header
        return result;
    }
    result.failure = std::string("phongrast's ") + search.library + " module " + search.file +
                     " could not be loaded (install phongrast's runtime files, or name the file in " +
                     search.environment + "); looked for:" + tried;
    return result;
}

}  // namespace phongrast::io::detail
