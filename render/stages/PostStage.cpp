#include "render/stages/PostStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"

#include <cmath>

namespace eikon::render {

PostStage::PostStage(int width, int height)
    : width_(width), height_(height), program_(gl::compileComputeProgram("tonemap.comp")),
      ldr_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {}

Image8 PostStage::run(const gl::BufferTexture& hdrImage, double exposureEv) {
    const auto pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the view wrote the buffer as storage
    hdrImage.bindSampler(layout::kHdrImageTexture);
    ldr_.bindStorage(layout::kLdrImage);
    program_.use();
    glUniform2ui(program_.uniform("image_size"), static_cast<GLuint>(width_), static_cast<GLuint>(height_));
    glUniform1f(program_.uniform("exposure_scale"), static_cast<float>(std::exp2(exposureEv)));
    program_.dispatchCovering(static_cast<std::size_t>(width_), static_cast<std::size_t>(height_));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    Image8 image{width_, height_, std::vector<std::uint8_t>(pixels * 4)};
    ldr_.download(image.rgba.data(), image.rgba.size());
    gl::checkpoint("post stage");
    return image;
}

}  // namespace eikon::render
