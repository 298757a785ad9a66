#include "io/image/RadianceCheck.h"

#include "bridge/core/Error.h"

#include <cstdio>
#include <string>

namespace eikon::io {

namespace {

bool startsWith(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

// One scanline of new-style run-length data from `at`: four channels of
// `width` values. Returns false (with `why`) when it does not fit.
bool skipRunLengthScanline(std::string_view bytes, std::size_t& at, int width, std::string& why) {
    if (at + 4 > bytes.size()) {
        why = "the file ends in its marker";
        return false;
    }
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
    if (byte(at) != 2 || byte(at + 1) != 2 || ((byte(at + 2) << 8) | byte(at + 3)) != width) {
        why = "a scanline marker other than 2, 2 and the width " + std::to_string(width);
        return false;
    }
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
        int filled = 0;
        while (filled < width) {
            if (at >= bytes.size()) {
                why = "the file ends inside channel " + std::to_string(channel);
                return false;
            }
            int count = byte(at++);
            const bool run = count > 128;
            if (run) count -= 128;
            if (count == 0 || count > width - filled) {
                why = "a count of " + std::to_string(count) + " with " + std::to_string(width - filled) +
                      " values left in channel " + std::to_string(channel);
                return false;
            }
            const std::size_t payload = run ? 1 : static_cast<std::size_t>(count);
            if (at + payload > bytes.size()) {
                why = "the file ends inside channel " + std::to_string(channel);
                return false;
            }
            at += payload;
            filled += count;
        }
    }
    return true;
}

}  // namespace

bool isRadiance(std::string_view bytes) { return startsWith(bytes, "#?RADIANCE") || startsWith(bytes, "#?RGBE"); }

void checkRadiance(std::string_view bytes, const std::string& path) {
    if (!isRadiance(bytes)) throw InputError(path, "a Radiance .hdr file (#?RADIANCE)", "another kind of file");
    // The header: lines up to an empty one.
    std::size_t at = bytes.find('\n');
    bool format = false;
    for (;;) {
        if (at == std::string_view::npos) throw InputError(path, "a Radiance header ended by an empty line", "none");
        const std::size_t start = at + 1;
        at = bytes.find('\n', start);
        const std::string_view line = bytes.substr(start, (at == std::string_view::npos ? bytes.size() : at) - start);
        if (line.empty()) break;
        if (line == "FORMAT=32-bit_rle_rgbe") format = true;
    }
    if (!format) throw InputError(path, "FORMAT=32-bit_rle_rgbe in its header", "no such line");
    const std::size_t resolutionStart = at + 1;
    at = bytes.find('\n', resolutionStart);
    if (at == std::string_view::npos) throw InputError(path, "a resolution line \"-Y height +X width\"", "none");
    const std::string resolution(bytes.substr(resolutionStart, at - resolutionStart));
    int height = 0, width = 0, read = 0;
    if (std::sscanf(resolution.c_str(), "-Y %d +X %d%n", &height, &width, &read) != 2 ||
        read != static_cast<int>(resolution.size()) || height < 1 || width < 1)
        throw InputError(path + ": resolution line", "\"-Y height +X width\" with both at least 1", "\"" + resolution + "\"");
    ++at;
    const std::size_t pixels = static_cast<std::size_t>(height) * static_cast<std::size_t>(width);
    const auto flatFits = [&](std::size_t from) { return bytes.size() >= from && bytes.size() - from >= 4 * pixels; };
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
    const bool runLength = width >= 8 && width < 32768 && at + 4 <= bytes.size() && byte(at) == 2 &&
                           byte(at + 1) == 2 && (byte(at + 2) & 0x80) == 0;
    if (!runLength) {
        if (!flatFits(at))
            throw InputError(path, std::to_string(4 * pixels) + " bytes of flat pixels for " + std::to_string(width) +
                                       " × " + std::to_string(height),
                             std::to_string(bytes.size() - std::min(at, bytes.size())) + " (truncated)");
        return;
    }
    for (int row = 0; row < height; ++row) {
        std::string why;
        if (!skipRunLengthScanline(bytes, at, width, why))
            throw InputError(path + ": scanline " + std::to_string(row) + " of " + std::to_string(height),
                             "run-length data for " + std::to_string(width) + " pixels", why + " (truncated or corrupt)");
    }
}

}  // namespace eikon::io
