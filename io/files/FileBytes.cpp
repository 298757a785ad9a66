#include "io/files/FileBytes.h"

#include "bridge/core/Error.h"

#include <fstream>
#include <sstream>

namespace eikon::io {

std::string readFileBytes(const std::filesystem::path& path, const std::string& expected) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (!file) throw InputError(path.string(), expected, "a file that cannot be read");
    return bytes.str();
}

}  // namespace eikon::io
