// Image files: 8-bit PNG through stb_image_write, written atomically.
#pragma once

#include "bridge/scene/FloatImage.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace eikon::io {

// rgba: width·height·4 bytes, row 0 at the top.
void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// The largest image the readers decode: a float RGBA copy of 2^27 pixels
// takes 2 GiB, and the GPU's textures are smaller still.
inline constexpr int kMaxImageSide = 32768;
inline constexpr long long kMaxImagePixels = 1ll << 27;

struct Rgba8Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// Throws InputError naming the path when the file cannot be read as an
// image (checked as readFloatImage's are).
Rgba8Image readImage(const std::filesystem::path& path);

// An 8-bit image (PNG, JPEG) as linear RGBA floats: its colour channels
// decoded by the sRGB transfer function (IEC 61966-2-1), alpha as stored.
// Throws InputError naming the path when it cannot be read (as readImage).
FloatImage readSrgbImageAsLinear(const std::filesystem::path& path);

// Linear radiance as Radiance .hdr (RGBE), written atomically; rgba has
// width·height·4 floats (alpha ignored).
void writeHdr(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgba);

// Any image stb_image reads (Radiance .hdr keeps its linear values), as RGBA
// floats. Throws InputError naming the path when it cannot be read.
FloatImage readFloatImage(const std::filesystem::path& path);

// The memory readFloatImage takes for this file at its peak — the file's
// bytes, stb_image's float RGBA decoding and the copy returned — from the
// image's header alone; 0 where the header does not say or gives a size
// that is not positive (readFloatImage then says what is wrong).
std::uint64_t floatImageDecodingBytes(const std::filesystem::path& path);

}  // namespace eikon::io
