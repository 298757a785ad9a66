// Whole-file writes that never leave a truncated file behind: the bytes go to
// a temporary name beside the target, are flushed, and are renamed over it.
#pragma once

#include <filesystem>
#include <string_view>

namespace eikon::io {

// Throws std::runtime_error naming the path on any failure; the target is
// then untouched and the temporary removed.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace eikon::io
