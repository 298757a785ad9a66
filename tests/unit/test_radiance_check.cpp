// Radiance .hdr files checked before stb_image decodes them: a valid map
// reads back, and a map cut anywhere inside its pixel data — run-length or
// flat — or with a zero-sized resolution is refused with an InputError that
// names the file (stb's decoder loops forever on such truncations).
#include "bridge/core/Error.h"
#include "io/files/FileBytes.h"
#include "io/image/ImageIo.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

class RadianceCheckTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_radiance_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A width × height map of smoothly varying radiance, as eikon writes it.
    std::string mapBytes(int width, int height) {
        std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4);
        for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = 0.5f + 0.001f * static_cast<float>(i % 97);
        const fs::path path = dir_ / "map.hdr";
        writeHdr(path, width, height, rgba);
        return readFileBytes(path);
    }
    fs::path write(const std::string& name, const std::string& bytes) {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
    fs::path dir_;
};

std::string messageOf(const fs::path& path) {
    try {
        readFloatImage(path);
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

TEST_F(RadianceCheckTest, AValidMapReadsBack) {
    const FloatImage image = readFloatImage(write("ok.hdr", mapBytes(64, 16)));
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 16);
    EXPECT_NEAR(image.rgba[4], 0.504f, 0.005f);  // RGBE keeps 8 bits of mantissa
}

// Run-length scanlines (width 64) and flat ones (width 4), cut after every
// few bytes of their pixel data.
TEST_F(RadianceCheckTest, EveryTruncationInsideThePixelsIsRefused) {
    for (const int width : {64, 4}) {
        const std::string bytes = mapBytes(width, 16);
        const std::size_t pixelsStart = bytes.find("+X ") + bytes.substr(bytes.find("+X ")).find('\n') + 1;
        int cuts = 0;
        for (std::size_t length = pixelsStart; length < bytes.size(); length += 5, ++cuts) {
            const fs::path path = write("cut.hdr", bytes.substr(0, length));
            const std::string message = messageOf(path);
            ASSERT_NE(message.find("cut.hdr"), std::string::npos) << "width " << width << ", " << length << " bytes: " << message;
            ASSERT_NE(message.find("truncated"), std::string::npos) << message;
        }
        EXPECT_GT(cuts, 20);
    }
}

// The 8-bit reader checks the file as the float one does: stb looped for
// ever in it on a map cut inside its first scanline (found by fuzz_image).
TEST_F(RadianceCheckTest, The8BitReaderRefusesTruncatedMapsToo) {
    const std::string bytes = mapBytes(64, 16);
    const std::size_t pixelsStart = bytes.find("+X ") + bytes.substr(bytes.find("+X ")).find('\n') + 1;
    const fs::path path = write("cut8.hdr", bytes.substr(0, pixelsStart + 6));
    try {
        readImage(path);
        FAIL() << "a truncated map was read";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("cut8.hdr"), std::string::npos) << error.what();
    }
}

// A header declaring more pixels than the readers decode (a PNG of
// 16000², 4 GiB as floats) is refused before stb allocates for it.
TEST_F(RadianceCheckTest, AnImageLargerThanTheReadersDecodeIsRefusedFromItsHeader) {
    std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
    for (const unsigned side : {16000u, 16000u})
        for (int shift = 24; shift >= 0; shift -= 8) png += static_cast<char>((side >> shift) & 0xff);
    png += std::string("\x08\x02\0\0\0", 5) + std::string(4, '\0');  // 8-bit RGB; stb does not read the CRC
    const std::string message = messageOf(write("huge.png", png + std::string(64, '\0')));
    EXPECT_NE(message.find("huge.png: expected an image of at most 32768 pixels a side and 134217728 pixels, found 16000 × 16000"), std::string::npos) << message;
}

TEST_F(RadianceCheckTest, AZeroSizedResolutionIsRefused) {
    std::string bytes = mapBytes(16, 4);
    bytes.replace(bytes.find("-Y 4 +X 16"), 10, "-Y 0 +X 0");
    const std::string message = messageOf(write("empty.hdr", bytes));
    EXPECT_NE(message.find("empty.hdr: resolution line"), std::string::npos) << message;
    EXPECT_NE(message.find("at least 1"), std::string::npos) << message;
}

}  // namespace
}  // namespace eikon::io
