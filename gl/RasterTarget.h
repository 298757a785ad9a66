// An offscreen framebuffer the raster passes draw into (headless through
// EGL as on a window's context): one RGBA32F colour texture, read back by
// compute passes with texelFetch, and a 32-bit depth buffer. Also the empty
// vertex array a core-profile draw needs when the vertex shader pulls its
// vertices from a storage buffer.
#pragma once

#include "gl/GlObjects.h"

#include <glm/vec4.hpp>

namespace eikon::gl {

void deleteFramebuffer(GLuint id);
void deleteRenderbuffer(GLuint id);
void deleteVertexArray(GLuint id);

class RasterTarget {
public:
    RasterTarget() = default;
    RasterTarget(int width, int height, const GpuResource& resource);

    int width() const { return width_; }
    int height() const { return height_; }
    // Binds the framebuffer and viewport and clears colour to `clear` and depth to 1.
    void beginDrawing(const glm::vec4& clear);
    // Binds the framebuffer and viewport and keeps what it holds (drawing adds to it).
    void continueDrawing();
    // Draws into, and says it is, only its first `width` × `height` texels
    // from now on (at most the size it was made with).
    void useCorner(int width, int height);
    void bindColour(GLuint unit) const { glBindTextureUnit(unit, colour_.id()); }

private:
    GpuReservation reservation_;
    GlName<deleteTexture> colour_;
    GlName<deleteRenderbuffer> depth_;
    GlName<deleteFramebuffer> framebuffer_;
    int width_ = 0, height_ = 0;            // in use
    int madeWidth_ = 0, madeHeight_ = 0;    // allocated
};

class EmptyVertexArray {
public:
    EmptyVertexArray();
    void bind() const { glBindVertexArray(name_.id()); }

private:
    GlName<deleteVertexArray> name_;
};

}  // namespace eikon::gl
