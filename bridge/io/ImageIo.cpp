#include "bridge/io/ImageIo.h"

#include "bridge/core/Error.h"
#include "bridge/io/AtomicFile.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>
#include <string>

namespace eikon::io {

void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
    EIKON_CHECK(rgba.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::string encoded;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &encoded, width, height, 4, rgba.data(), width * 4))
        throw std::runtime_error(path.string() + ": PNG encoding failed");
    writeFileAtomically(path, encoded);
}

void writeHdr(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgba) {
    EIKON_CHECK(rgba.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::string encoded;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (!stbi_write_hdr_to_func(append, &encoded, width, height, 4, rgba.data()))
        throw std::runtime_error(path.string() + ": HDR encoding failed");
    writeFileAtomically(path, encoded);
}

FloatImage readFloatImage(const std::filesystem::path& path) {
    FloatImage image;
    int channels = 0;
    float* pixels = stbi_loadf(path.c_str(), &image.width, &image.height, &channels, 4);
    if (!pixels) throw InputError(path.string(), "a readable Radiance .hdr (or PNG/JPEG) image", stbi_failure_reason());
    image.rgba.assign(pixels, pixels + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
    stbi_image_free(pixels);
    return image;
}

Rgba8Image readImage(const std::filesystem::path& path) {
    Rgba8Image image;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
    if (!pixels) throw InputError(path.string(), "a readable PNG, JPEG or HDR image", stbi_failure_reason());
    image.rgba.assign(pixels, pixels + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
    stbi_image_free(pixels);
    return image;
}

}  // namespace eikon::io
