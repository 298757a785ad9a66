#include "io/image/ImageIo.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"
#include "io/files/FileBytes.h"
#include "io/image/RadianceCheck.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <system_error>
#include <string>

namespace eikon::io {

namespace {

// stb_image_write's callback: appends the encoded bytes to a std::string.
void appendToString(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

// A PNG's chunks (a 32-bit big-endian length, a type, the data, a CRC) up
// to IEND must lie within the file: stb allocates what a chunk's length
// claims before it reads (a 95-byte file claiming an IDAT of 1.8 GB; found
// by fuzz_image).
void checkPngChunks(const std::string& bytes, const std::string& path) {
    static const std::string signature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.compare(0, signature.size(), signature) != 0) return;
    for (std::size_t at = signature.size(); at + 12 <= bytes.size();) {
        const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])); };
        const std::uint32_t length = byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
        if (length > bytes.size() - at - 12)
            throw InputError(path + ": byte " + std::to_string(at), "a PNG chunk within the file",
                             "a chunk \"" + bytes.substr(at + 4, 4) + "\" claiming " + std::to_string(length) +
                                 " bytes of the " + std::to_string(bytes.size() - at - 12) + " left");
        if (bytes.compare(at + 4, 4, "IEND") == 0) return;
        at += 12 + length;
    }
}

// An image file's bytes, checked before stb_image decodes them: at most
// 2 GiB; a Radiance file walked through to its last scanline (stb loops
// forever on some truncated ones: RadianceCheck.h); and a size stb can
// decode without allocating gigabytes for a header that lies (every image
// kind declares its size first).
std::string checkedImageBytes(const std::filesystem::path& path, const char* expected) {
    std::string bytes = readFileBytes(path, expected);
    if (bytes.size() > 0x7fffffff)
        throw InputError(path.string(), "an image file below 2 GiB", std::to_string(bytes.size()) + " bytes");
    if (isRadiance(bytes)) checkRadiance(bytes, path.string());
    checkPngChunks(bytes, path.string());
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &width,
                              &height, &channels) &&
        (width > kMaxImageSide || height > kMaxImageSide ||
         static_cast<long long>(width) * height > kMaxImagePixels))
        throw InputError(path.string(),
                         "an image of at most " + std::to_string(kMaxImageSide) + " pixels a side and " +
                             std::to_string(kMaxImagePixels) + " pixels",
                         std::to_string(width) + " × " + std::to_string(height) + " pixels");
    return bytes;
}

// Decodes with stb_image as 4 channels of T (stbi_uc or float) and copies them out.
template <typename T, typename Loader>
std::vector<T> loadRgba(const std::filesystem::path& path, const std::string& bytes, int& width, int& height,
                        const char* expected, Loader load) {
    int channels = 0;
    T* pixels = load(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &width, &height,
                     &channels, 4);
    if (!pixels) throw InputError(path.string(), expected, stbi_failure_reason());
    std::vector<T> rgba(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(pixels);
    return rgba;
}

}  // namespace

void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
    EIKON_CHECK_EQ(rgba.size(), static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::string encoded;
    if (!stbi_write_png_to_func(appendToString, &encoded, width, height, 4, rgba.data(), width * 4))
        throw std::runtime_error(path.string() + ": PNG encoding failed");
    writeFileAtomically(path, encoded);
}

void writeHdr(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgba) {
    EIKON_CHECK_EQ(rgba.size(), static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::string encoded;
    if (!stbi_write_hdr_to_func(appendToString, &encoded, width, height, 4, rgba.data()))
        throw std::runtime_error(path.string() + ": HDR encoding failed");
    writeFileAtomically(path, encoded);
}

FloatImage readFloatImage(const std::filesystem::path& path) {
    constexpr const char* kExpected = "a readable Radiance .hdr (or PNG/JPEG) image";
    const std::string bytes = checkedImageBytes(path, kExpected);
    FloatImage image;
    image.rgba = loadRgba<float>(path, bytes, image.width, image.height, kExpected, stbi_loadf_from_memory);
    return image;
}

std::uint64_t floatImageDecodingBytes(const std::filesystem::path& path) {
    int width = 0, height = 0, channels = 0;
    std::error_code error;
    const std::uintmax_t fileBytes = std::filesystem::file_size(path, error);
    // A header stb cannot read, or one with a size that is not positive, is
    // readFloatImage's to refuse, with its own message.
    if (error || !stbi_info(path.c_str(), &width, &height, &channels) || width <= 0 || height <= 0) return 0;
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    return fileBytes + 2 * pixels * 4 * sizeof(float);
}

Rgba8Image readImage(const std::filesystem::path& path) {
    constexpr const char* kExpected = "a readable PNG, JPEG or HDR image";
    const std::string bytes = checkedImageBytes(path, kExpected);
    Rgba8Image image;
    image.rgba = loadRgba<stbi_uc>(path, bytes, image.width, image.height, kExpected, stbi_load_from_memory);
    return image;
}

FloatImage readSrgbImageAsLinear(const std::filesystem::path& path) {
    const Rgba8Image encoded = readImage(path);
    std::array<float, 256> decoded{};
    for (std::size_t value = 0; value < decoded.size(); ++value) {
        const double v = static_cast<double>(value) / 255.0;
        decoded[value] = static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
    }
    FloatImage image{encoded.width, encoded.height, std::vector<float>(encoded.rgba.size())};
    for (std::size_t i = 0; i < encoded.rgba.size(); ++i)
        image.rgba[i] = i % 4 == 3 ? static_cast<float>(encoded.rgba[i]) / 255.0f : decoded[encoded.rgba[i]];
    return image;
}

}  // namespace eikon::io
