// Image files: 8-bit PNG through stb_image_write, written atomically.
#pragma once

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

}  // namespace eikon::io
