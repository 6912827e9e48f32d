// Loads phongrast_openimageio.so on first use (see openimageio_module.hpp).
#include <mutex>
#include <stdexcept>
#include <string>

#include "module_loader.hpp"
#include "openimageio_module.hpp"

namespace phongrast::io::detail {

const PhongrastOpenImageIoModule& openimageio_module(const std::string& purpose) {
    static std::once_flag once;
    static LoadedModule loaded;
    std::call_once(once, [] {
        loaded = load_module({kOpenImageIoModuleFile, "PHONGRAST_OPENIMAGEIO_MODULE", PHONGRAST_BUILD_TREE_MODULE,
                              "phongrast_openimageio_module", kPhongrastOpenImageIoModuleVersion, "OpenImageIO"});
    });
    if (!loaded.table) throw std::runtime_error(purpose + " needs OpenImageIO: " + loaded.failure);
    return *static_cast<const PhongrastOpenImageIoModule*>(loaded.table);
}

}  // namespace phongrast::io::detail
