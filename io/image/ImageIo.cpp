#include "io/image/ImageIo.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"
#include "io/files/FileBytes.h"
#include "io/image/RadianceCheck.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>
#include <string>

namespace eikon::io {

namespace {

// stb_image_write's callback: appends the encoded bytes to a std::string.
void appendToString(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

// Loads with stb_image as 4 channels of T (stbi_uc or float) and copies them out.
template <typename T, typename Loader>
std::vector<T> loadRgba(const std::filesystem::path& path, int& width, int& height, const char* expected,
                        Loader load) {
    int channels = 0;
    T* pixels = load(path.c_str(), &width, &height, &channels, 4);
    if (!pixels) throw InputError(path.string(), expected, stbi_failure_reason());
    std::vector<T> rgba(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(pixels);
    return rgba;
}

}  // namespace

void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
    EIKON_CHECK(rgba.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::string encoded;
    if (!stbi_write_png_to_func(appendToString, &encoded, width, height, 4, rgba.data(), width * 4))
        throw std::runtime_error(path.string() + ": PNG encoding failed");
    writeFileAtomically(path, encoded);
}

void writeHdr(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgba) {
    EIKON_CHECK(rgba.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::string encoded;
    if (!stbi_write_hdr_to_func(appendToString, &encoded, width, height, 4, rgba.data()))
        throw std::runtime_error(path.string() + ": HDR encoding failed");
    writeFileAtomically(path, encoded);
}

FloatImage readFloatImage(const std::filesystem::path& path) {
    const std::string bytes = readFileBytes(path, "a readable Radiance .hdr (or PNG/JPEG) image");
    if (bytes.size() > 0x7fffffff) throw InputError(path.string(), "an image file below 2 GiB", std::to_string(bytes.size()) + " bytes");
    if (isRadiance(bytes)) checkRadiance(bytes, path.string());
    FloatImage image;
    image.rgba = loadRgba<float>(path, image.width, image.height, "a readable Radiance .hdr (or PNG/JPEG) image",
                                 [&](const char*, int* w, int* h, int* channels, int wanted) {
                                     return stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                                                   static_cast<int>(bytes.size()), w, h, channels,
                                                                   wanted);
                                 });
    return image;
}

Rgba8Image readImage(const std::filesystem::path& path) {
    Rgba8Image image;
    image.rgba = loadRgba<stbi_uc>(path, image.width, image.height, "a readable PNG, JPEG or HDR image", stbi_load);
    return image;
}

}  // namespace eikon::io
