// Where in a JSON text nlohmann's parser stopped. Its parse_error carries
// the byte, but out_of_range (a number such as 1e999 too large for a
// double) does not; a second, SAX-only pass over the text reports the
// position of either, so every JSON error can name its line and column.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace eikon {

// The count of bytes read when parsing stopped at an error; nullopt for
// valid JSON.
std::optional<std::size_t> jsonErrorByte(const std::string& text);

}  // namespace eikon
