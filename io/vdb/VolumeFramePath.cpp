#include "io/vdb/VolumeFramePath.h"

#include <cstdio>
#include <filesystem>

namespace eikon {

std::string volumeFramePath(const VolumeDesc& volume, int number) {
    if (!volume.sequence) return volume.path;
    const std::filesystem::path path(volume.path);
    std::string name = path.filename().string();
    const std::size_t first = name.find('#');
    const std::size_t width = name.find_last_of('#') - first + 1;
    char digits[32];
    std::snprintf(digits, sizeof digits, "%0*d", static_cast<int>(width), number);
    name.replace(first, width, digits);
    return (path.parent_path() / name).string();
}

}  // namespace eikon
