// Post (shaders/tonemap.comp): exposure and a filmic curve turn the HDR image
// into 8-bit sRGB, read back for writing.
#pragma once

#include "gl/GlObjects.h"

#include <cstdint>
#include <vector>

namespace eikon::render {

struct Image8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row 0 at the top
};

class PostStage {
public:
    PostStage(int width, int height);
    // hdrImage: a view's HdrImage buffer as a buffer texture, written
    // before this runs.
    Image8 run(const gl::BufferTexture& hdrImage, double exposureEv);

private:
    int width_, height_;
    gl::Program program_;
    gl::Buffer ldr_;
};

}  // namespace eikon::render
