// Image files: 8-bit PNG through stb_image_write, written atomically.
#pragma once

#include "bridge/scene/FloatImage.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace eikon::io {

// rgba: width·height·4 bytes, row 0 at the top.
void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

struct Rgba8Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// Throws InputError naming the path when the file cannot be read as an image.
Rgba8Image readImage(const std::filesystem::path& path);

// Linear radiance as Radiance .hdr (RGBE), written atomically; rgba has
// width·height·4 floats (alpha ignored).
void writeHdr(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgba);

// Any image stb_image reads (Radiance .hdr keeps its linear values), as RGBA
// floats. Throws InputError naming the path when it cannot be read.
FloatImage readFloatImage(const std::filesystem::path& path);

}  // namespace eikon::io
