// A whole input file in memory, for readers that check it before parsing.
#pragma once

#include <filesystem>
#include <string>

namespace eikon::io {

// Throws InputError naming the path when the file cannot be read;
// `expected` names what the caller wanted ("a mesh file", …).
std::string readFileBytes(const std::filesystem::path& path, const std::string& expected = "a readable file");

}  // namespace eikon::io
