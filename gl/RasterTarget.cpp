#include "gl/RasterTarget.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>
#include <string>

namespace eikon::gl {

void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }

RasterTarget::RasterTarget(int width, int height, const GpuResource& resource)
    : reservation_(resource, 20 * std::uint64_t(width) * std::uint64_t(height)), width_(width), height_(height),
      madeWidth_(width), madeHeight_(height) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    colour_ = GlName<deleteTexture>(id);
    glTextureStorage2D(id, 1, GL_RGBA32F, width, height);
    expectCreated(resource, 16 * std::uint64_t(width) * std::uint64_t(height));
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCreateRenderbuffers(1, &id);
    depth_ = GlName<deleteRenderbuffer>(id);
    glNamedRenderbufferStorage(id, GL_DEPTH_COMPONENT32F, width, height);
    glCreateFramebuffers(1, &id);
    framebuffer_ = GlName<deleteFramebuffer>(id);
    glNamedFramebufferTexture(id, GL_COLOR_ATTACHMENT0, colour_.id(), 0);
    glNamedFramebufferRenderbuffer(id, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the framebuffer for " + resource.description + " (" + resource.keyPath +
                                 ") is incomplete: status " + std::to_string(status));
}

void RasterTarget::useCorner(int width, int height) {
    if (width < 1 || height < 1 || width > madeWidth_ || height > madeHeight_)
        throw std::logic_error("a raster target's corner of " + std::to_string(width) + "×" + std::to_string(height) +
                               " does not fit its " + std::to_string(madeWidth_) + "×" + std::to_string(madeHeight_));
    width_ = width;
    height_ = height;
}

void RasterTarget::continueDrawing() {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
}

void RasterTarget::beginDrawing(const glm::vec4& clear) {
    continueDrawing();
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, glm::value_ptr(clear));
    const float farthest = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &farthest);
}

EmptyVertexArray::EmptyVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    name_ = GlName<deleteVertexArray>(id);
}

}  // namespace eikon::gl
