#include "render/stages/ViewStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "render/gl/GlDebug.h"
#include "render/gl/ShaderLibrary.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace eikon::render {

layout::GpuCamera cameraBlock(const CameraDesc& camera, const RenderDesc& render) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    layout::GpuCamera block{};
    block.position = glm::vec4(glm::vec3(camera.position), static_cast<float>(std::tan(glm::radians(camera.fovDeg) / 2)));
    block.forward = glm::vec4(glm::vec3(forward), static_cast<float>(render.width) / static_cast<float>(render.height));
    block.right = glm::vec4(glm::vec3(right), 0.0f);
    block.up = glm::vec4(glm::vec3(up), 0.0f);
    block.background = glm::vec4(glm::vec3(render.background), 0.0f);
    block.image = glm::uvec4(static_cast<unsigned>(render.width), static_cast<unsigned>(render.height), 0u, 0u);
    return block;
}

ViewStage::ViewStage(const Scene& scene, const FieldTextures& fields, const ReceiverMaps& receivers)
    : receivers_(receivers), render_(scene.render), width_(scene.render.width), height_(scene.render.height) {
    program_ = gl::compileComputeProgram(
        "view_rays.comp", {{"EIKON_HAS_EXTINCTION", fields.hasExtinction() ? "1" : "0"},
                           {"EIKON_HAS_SCATTERING", fields.hasScattering() ? "1" : "0"}});
    const layout::GpuCamera block = cameraBlock(scene.camera, scene.render);
    camera_ = gl::Buffer(sizeof block, &block, GL_DYNAMIC_STORAGE_BIT);
    hdr_ = gl::Buffer(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * sizeof(glm::vec4));
}

void ViewStage::setCamera(const CameraDesc& camera) {
    const layout::GpuCamera block = cameraBlock(camera, render_);
    camera_.upload(&block, sizeof block);
}

void ViewStage::run(const FieldTextures& fields, const gl::Buffer& fluence, double stepLength, unsigned maxSteps) {
    fields.bindForTracing();
    receivers_.bind();
    camera_.bindUniform(layout::kCameraBlock);
    if (fields.hasScattering()) fluence.bindStorage(layout::kFluence);
    hdr_.bindStorage(layout::kHdrImage);
    program_.use();
    glUniform1ui(program_.uniform("receiver_count"), receivers_.count());
    glUniform1f(program_.uniform("step_length"), static_cast<float>(stepLength));
    glUniform1ui(program_.uniform("max_steps"), maxSteps);
    program_.dispatchCovering(static_cast<std::size_t>(width_), static_cast<std::size_t>(height_), 1, 8, 8, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl::checkpoint("view stage");
}

}  // namespace eikon::render
