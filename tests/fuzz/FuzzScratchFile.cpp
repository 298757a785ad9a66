#include "tests/fuzz/FuzzScratchFile.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace eikon::fuzz {

namespace {

namespace fs = std::filesystem;

// One folder per process: libFuzzer's -jobs/-workers run several at once.
class ScratchFolder {
public:
    ScratchFolder() : path_(fs::temp_directory_path() / ("eikon_fuzz_" + std::to_string(getpid()))) {
        fs::create_directories(path_);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

}  // namespace

fs::path writeScratchFile(const std::string& name, std::string_view bytes) {
    static const ScratchFolder folder;
    const fs::path path = folder.path() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error("fuzz: cannot write " + path.string());
    return path;
}

}  // namespace eikon::fuzz
