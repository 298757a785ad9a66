// libFuzzer target: the image readers — readFloatImage (environment maps:
// Radiance .hdr checked first, PNG, JPEG) and readImage (8-bit images) —
// on the input as a file. Only an image or an InputError may come out.
#include "bridge/core/Error.h"
#include "io/image/ImageIo.h"
#include "tests/fuzz/FuzzScratchFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = eikon::fuzz::writeScratchFile("image.hdr", eikon::fuzz::asBytes(data, size));
    try {
        eikon::io::readFloatImage(path);
    } catch (const eikon::InputError&) {
    }
    try {
        eikon::io::readImage(path);
    } catch (const eikon::InputError&) {
    }
    return 0;
}
