// The fuzzers' way into eikon's readers, which take paths: the input bytes
// written to a file of a chosen name in a scratch folder of this process,
// removed when the process ends.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace eikon::fuzz {

// Writes `bytes` to <scratch folder>/<name> and returns that path.
std::filesystem::path writeScratchFile(const std::string& name, std::string_view bytes);

// The input as a string view, for the readers' checks that take bytes.
inline std::string_view asBytes(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace eikon::fuzz
