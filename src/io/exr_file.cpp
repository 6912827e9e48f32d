// EXR reading and writing through phongrast_openexr.so, loaded on the first
// use (openexr_module.hpp says why OpenEXR is not linked).
#include "exr_file.hpp"

#include <algorithm>
#include <mutex>

#include "module_loader.hpp"
#include "openexr_module.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io::detail {
namespace {

/// The module, loaded on the first call; `path`: the file that needs it, for the message.
const PhongrastOpenExrModule& openexr(const std::string& path) {
    static std::once_flag once;
    static LoadedModule loaded;
    std::call_once(once, [] {
        loaded = load_module({kOpenExrModuleFile, "PHONGRAST_OPENEXR_MODULE", PHONGRAST_BUILD_TREE_OPENEXR_MODULE,
                              "phongrast_openexr_module", kPhongrastOpenExrModuleVersion, "OpenEXR"});
    });
    if (!loaded.table) throw FileError(path + ": EXR needs OpenEXR: " + loaded.failure);
    return *static_cast<const PhongrastOpenExrModule*>(loaded.table);
}

std::vector<PhongrastExrChannel> c_channels(const std::vector<ExrChannel>& channels) {
    std::vector<PhongrastExrChannel> out;
    out.reserve(channels.size());
    for (const ExrChannel& channel : channels) {
        out.push_back({channel.name.c_str(), channel.unsigned_int ? 1 : 0, channel.base, channel.stride});
    }
    return out;
}

constexpr std::size_t kErrorSize = 1024;

}  // namespace

void write_exr(const std::string& file, const std::string& path, int columns, int rows,
               const std::vector<ExrChannel>& channels) {
    const PhongrastOpenExrModule& module = openexr(path);
    const std::vector<PhongrastExrChannel> table = c_channels(channels);
    char error[kErrorSize] = {};
    if (module.write(file.c_str(), columns, rows, table.data(), table.size(), error, sizeof error) != 0) {
        throw FileError(path + ": write failed: " + error);
    }
}

struct ExrReader::File {
    const PhongrastOpenExrModule* module = nullptr;
    void* handle = nullptr;
    ~File() {
        if (handle != nullptr) module->close(handle);
    }
};

ExrReader::ExrReader(const std::string& path) : path_(path) {
    file_ = std::make_unique<File>();
    file_->module = &openexr(path);
    char error[kErrorSize] = {};
    file_->handle = file_->module->open(path.c_str(), &columns_, &rows_, error, sizeof error);
    if (file_->handle == nullptr) throw FileError(path + ": cannot read image: " + error);
    const std::size_t count = file_->module->channel_count(file_->handle);
    for (std::size_t i = 0; i < count; ++i) names_.emplace_back(file_->module->channel_name(file_->handle, i));
    if (columns_ < 1 || rows_ < 1 || columns_ > 32768 || rows_ > 32768) {
        throw FileError(path + ": EXR of " + std::to_string(columns_) + "x" + std::to_string(rows_) +
                        " pixels; expected 1 to 32768 per side");
    }
}

ExrReader::~ExrReader() = default;

bool ExrReader::has(const std::string& name) const {
    return std::find(names_.begin(), names_.end(), name) != names_.end();
}

void ExrReader::read(const std::vector<ExrChannel>& channels) {
    const std::vector<PhongrastExrChannel> table = c_channels(channels);
    char error[kErrorSize] = {};
    if (file_->module->read(file_->handle, table.data(), table.size(), error, sizeof error) != 0) {
        throw FileError(path_ + ": cannot read image: " + error);
    }
}

}  // namespace phongrast::io::detail
