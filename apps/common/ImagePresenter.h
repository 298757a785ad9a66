// Shows a rendered frame in a window (eikon-view's, eikon::View's): the 8-bit image goes into a texture
// that is blitted, scaled to fit and centred, onto the default framebuffer.
#pragma once

#include "gl/GlObjects.h"
#include "render/stages/PostStage.h"

namespace eikon::view {

class ImagePresenter {
public:
    ImagePresenter() = default;
    ~ImagePresenter();
    ImagePresenter(const ImagePresenter&) = delete;
    ImagePresenter& operator=(const ImagePresenter&) = delete;

    void present(const render::Image8& image, int framebufferWidth, int framebufferHeight);

private:
    GLuint texture_ = 0;
    GLuint framebuffer_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace eikon::view
