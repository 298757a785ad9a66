#include "apps/common/ImagePresenter.h"

#include <algorithm>

namespace eikon::view {

ImagePresenter::~ImagePresenter() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
}

void ImagePresenter::present(const render::Image8& image, int framebufferWidth, int framebufferHeight) {
    if (image.rgba.empty()) return;
    if (image.width != width_ || image.height != height_) {
        if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
        if (texture_) glDeleteTextures(1, &texture_);
        glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
        glTextureStorage2D(texture_, 1, GL_RGBA8, image.width, image.height);
        glCreateFramebuffers(1, &framebuffer_);
        glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
        width_ = image.width;
        height_ = image.height;
    }
    glTextureSubImage2D(texture_, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    const double scale = std::min(static_cast<double>(framebufferWidth) / width_,
                                  static_cast<double>(framebufferHeight) / height_);
    const int w = static_cast<int>(width_ * scale), h = static_cast<int>(height_ * scale);
    const int x = (framebufferWidth - w) / 2, y = (framebufferHeight - h) / 2;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // Row 0 of the image is its top; the framebuffer's row 0 is its bottom: flip.
    glBlitNamedFramebuffer(framebuffer_, 0, 0, 0, width_, height_, x, y + h, x + w, y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

}  // namespace eikon::view
