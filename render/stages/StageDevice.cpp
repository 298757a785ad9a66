#include "render/stages/StageDevice.h"

#include "gl/GlContext.h"

#include <epoxy/gl.h>

namespace eikon::render {

StageDevice gridPassDevice(ComputeDevice requested) {
    gl::GlInfo current;
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    current.renderer = renderer ? renderer : "";
    return runsOnGpu(requested, !current.rendersOnCpu()) ? StageDevice::Gpu : StageDevice::Cpu;
}

const char* stageDeviceName(StageDevice device) { return device == StageDevice::Cpu ? "cpu" : "gpu"; }

void downloadTexels(const gl::Texture3D& texture, GLenum format, void* data, std::size_t bytes) {
    glGetTextureImage(texture.id(), 0, format, GL_FLOAT, static_cast<GLsizei>(bytes), data);
}

}  // namespace eikon::render
