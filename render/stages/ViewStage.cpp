#include "render/stages/ViewStage.h"

#include "bridge/core/Error.h"
#include "gl/GlContext.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/GaussianKernel.h"
#include "render/stages/PhotonStage.h"
#include "render/stages/PixelSamples.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::render {

namespace {

glm::vec4 rgb(const Rgb& value) { return glm::vec4(glm::vec3(value), 0.0f); }

}  // namespace

unsigned environmentKind(const EnvironmentDesc& environment) {
    switch (environment.kind) {
        case EnvironmentDesc::Kind::Uniform: return layout::kUniformEnvironment;
        case EnvironmentDesc::Kind::Sky: return layout::kSkyEnvironment;
        case EnvironmentDesc::Kind::Hdr: return layout::kHdrEnvironment;
    }
    return layout::kUniformEnvironment;
}

gl::Texture2D environmentTexture(const Scene& scene) {
    if (scene.render.environment.kind != EnvironmentDesc::Kind::Hdr) return {};
    const FloatImage* image = scene.render.environment.image.get();
    EIKON_CHECK_MSG(image != nullptr, "an hdr environment arrives with its image read (io/scene)");
    GLint largest = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
    if (image->width > largest || image->height > largest)
        throw InputError("render.environment.path",
                         "an image at most " + std::to_string(largest) + " pixels a side (GL_MAX_TEXTURE_SIZE)",
                         std::to_string(image->width) + " × " + std::to_string(image->height));
    return gl::Texture2D(image->width, image->height, image->rgba.data(),
                         {"render.environment.path", "the environment map"});
}

gl::Buffer pixelBuffer(const Scene& scene, const std::string& description) {
    const std::size_t pixels =
        static_cast<std::size_t>(scene.render.width) * static_cast<std::size_t>(scene.render.height);
    GLint64 largestBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largestBlock);
    if (pixels * sizeof(glm::vec4) > static_cast<std::size_t>(largestBlock))
        throw InputError("render.width × render.height",
                         "at most " + std::to_string(static_cast<std::size_t>(largestBlock) / sizeof(glm::vec4)) +
                             " pixels (the linear image takes 16 bytes a pixel; GL_MAX_SHADER_STORAGE_BLOCK_SIZE is " +
                             std::to_string(largestBlock) + " bytes)",
                         std::to_string(scene.render.width) + " × " + std::to_string(scene.render.height) + " = " +
                             std::to_string(pixels));
    return gl::Buffer(pixels * sizeof(glm::vec4), gl::GpuResource{"render.width × render.height", description});
}

layout::GpuCamera cameraBlock(const CameraDesc& camera, const RenderDesc& render) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const EnvironmentDesc& environment = render.environment;
    const double aspect = static_cast<double>(render.width) / static_cast<double>(render.height);
    // Half the image's height: at unit distance from the pinhole, or in metres on the orthographic image plane.
    const double halfHeight =
        camera.orthographic() ? 0.5 * camera.widthM / aspect : std::tan(glm::radians(camera.fovDeg) / 2);
    layout::GpuCamera block{};
    block.position = glm::vec4(glm::vec3(camera.position), static_cast<float>(halfHeight));
    block.forward = glm::vec4(glm::vec3(forward), static_cast<float>(aspect));
    block.right = glm::vec4(glm::vec3(right), 0.0f);
    block.up = glm::vec4(glm::vec3(up), 0.0f);
    block.image = glm::uvec4(static_cast<unsigned>(render.width), static_cast<unsigned>(render.height),
                             environmentKind(environment),
                             camera.orthographic() ? layout::kOrthographicProjection : layout::kPerspectiveProjection);
    block.radiance = environment.kind == EnvironmentDesc::Kind::Hdr
                         ? glm::vec4(static_cast<float>(environment.intensity),
                                     static_cast<float>(glm::radians(environment.rotationDeg)), 0.0f, 0.0f)
                         : rgb(environment.radiance);
    block.zenith = rgb(environment.zenith);
    block.horizon = rgb(environment.horizon);
    block.groundA = rgb(environment.groundA);
    block.groundB = rgb(environment.groundB);
    block.ground = glm::vec4(static_cast<float>(environment.groundHeight), static_cast<float>(environment.checkerSize),
                             0.0f, 0.0f);
    return block;
}

ViewStage::ViewStage(const Scene& scene, const FieldTextures& fields, const ReceiverMaps& receivers,
                     bool hasStepStructure, bool multipleScattering, bool recordExit)
    : receivers_(receivers), surfaces_(scene), multipleScattering_(multipleScattering), render_(scene.render),
      width_(scene.render.width), height_(scene.render.height),
      samplesPerPixel_(recordExit ? 1 : scene.render.samplesPerPixel) {
    const double voxel = fields.grid().smallestVoxelEdge();
    stepLength_ = scene.render.stepVoxels * voxel;
    stepReach_ = scene.render.stepVoxels * fields.grid().voxelSize();
    longestStep_ = std::max({stepReach_.x, stepReach_.y, stepReach_.z});
    maxSteps_ = defaultMaxSteps(fields.grid(), stepLength_);
    // Past the smoothing kernel (plus a voxel) the index is the bulk value on either side of an interface.
    const auto kernel = gaussianHalfKernel(scene.grid.smoothingSigmaVoxels, scene.grid.smoothingWindowVoxels);
    interfaceHalfWidth_ = static_cast<float>((static_cast<double>(kernel.size()) + 1.0) * voxel);
    program_ = gl::compileComputeProgram(
        "view_rays.comp", {{"EIKON_HAS_EXTINCTION", fields.hasExtinction() ? "1" : "0"},
                           {"EIKON_HAS_SCATTERING", fields.hasScattering() ? "1" : "0"},
                           {"EIKON_HAS_ANISOTROPY", fields.hasAnisotropy() ? "1" : "0"},
                           {"EIKON_HAS_EMISSION", fields.hasEmission() ? "1" : "0"},
                           {"EIKON_MULTIPLE_SCATTERING", multipleScattering ? "1" : "0"},
                           {"EIKON_STEP_STRUCTURE", hasStepStructure ? "1" : "0"},
                           {"EIKON_ENVIRONMENT", std::to_string(environmentKind(scene.render.environment))},
                           surfaces_.kindsOption(),
                           {"EIKON_RECORD_EXIT", recordExit ? "1" : "0"},
                           {"EIKON_LOOP_BUDGET", std::to_string(gl::currentLoopBudget())},
                           receivers.countOption()});
    environment_ = environmentTexture(scene);
    const layout::GpuCamera block = cameraBlock(scene.camera, scene.render);
    camera_ = gl::Buffer(sizeof block, &block, GL_DYNAMIC_STORAGE_BIT);
    hdr_ = pixelBuffer(scene, "the linear image");
    hdrTexels_ = gl::BufferTexture(hdr_, GL_RGBA32F, {"render.width × render.height", "the linear image"});
    if (recordExit) exits_ = pixelBuffer(scene, "the camera rays' exits");
}

void ViewStage::setCamera(const CameraDesc& camera) {
    const layout::GpuCamera block = cameraBlock(camera, render_);
    camera_.upload(&block, sizeof block);
}

void ViewStage::setPixelStride(int stride) {
    EIKON_CHECK_MSG(stride >= 1, "a pixel stride of at least 1");
    pixelStride_ = stride;
}

void ViewStage::bind(const FieldTextures& fields, const ViewInputs& inputs) {
    fields.bindForTracing();
    receivers_.bind();
    camera_.bindUniform(layout::kCameraBlock);
    if (fields.hasScattering()) {
        inputs.fluence->bindStorage(layout::kFluence);
        inputs.fluenceDirection->bindStorage(layout::kFluenceDirection);
    }
    if (multipleScattering_) {
        EIKON_CHECK_MSG(inputs.multipleFluence, "the lattice's fluence for a scene with multiple scattering");
        inputs.multipleFluence->bindStorage(layout::kMultipleFluence);
    }
    if (inputs.stepTexture) inputs.stepTexture->bindSampler(layout::kStepTexture);
    if (environment_.id()) environment_.bindSampler(layout::kEnvironmentTexture);
    hdr_.bindStorage(layout::kHdrImage);
    if (exits_.id()) exits_.bindStorage(layout::kViewExit);
    program_.use();
    if (!surfaces_.empty()) {
        surfaces_.bind();
        glUniform1ui(program_.uniform("sharp_surface_count"), surfaces_.count());
        glUniform1ui(program_.uniform("surface_depth"), static_cast<GLuint>(render_.surfaceDepth));
    }
    glUniform1f(program_.uniform("step_length"), static_cast<float>(stepLength_));
    glUniform1f(program_.uniform("longest_step"), static_cast<float>(longestStep_));
    glUniform3f(program_.uniform("step_reach"), static_cast<float>(stepReach_.x), static_cast<float>(stepReach_.y),
                static_cast<float>(stepReach_.z));
    glUniform1ui(program_.uniform("max_steps"), maxSteps_);
    glUniform1f(program_.uniform("interface_half_width"), interfaceHalfWidth_);
    glUniform1ui(program_.uniform("pixel_stride"), static_cast<GLuint>(pixelStride_));
}

void ViewStage::pass(int cell, int k) {
    const glm::vec2 offset = pixelStride_ > 1 ? glm::vec2(0.5f) : gridSampleOffset(cell, k);
    glUniform2f(program_.uniform("sample_offset"), offset.x, offset.y);
    glUniform1ui(program_.uniform("samples_before"), static_cast<GLuint>(samplesTaken_));
    // A preview's ray stands for its block, a sample for its cell.
    if (environmentKind(render_.environment) == layout::kSkyEnvironment)  // the only filtered environment
        glUniform1f(program_.uniform("footprint_pixels"), pixelStride_ > 1 ? static_cast<float>(pixelStride_)
                                                                            : 1.0f / static_cast<float>(k));
    const auto blocks = [&](int pixels) { return static_cast<std::size_t>((pixels + pixelStride_ - 1) / pixelStride_); };
    program_.dispatchCovering(blocks(width_), blocks(height_));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    ++samplesTaken_;
}

void ViewStage::run(const FieldTextures& fields, const ViewInputs& inputs) {
    bind(fields, inputs);
    samplesTaken_ = 0;
    const int k = pixelStride_ == 1 ? sampleGridSide(samplesPerPixel_) : 1;
    for (int cell = 0; cell < k * k; ++cell) pass(cell, k);
    if (pixelStride_ > 1) samplesTaken_ = 0;  // a preview is not refined
    refineSide_ = k + 1;
    refineCell_ = 0;
    gl::checkpoint("view stage");
}

void ViewStage::refine(const FieldTextures& fields, const ViewInputs& inputs) {
    EIKON_CHECK_MSG(pixelStride_ == 1 && samplesTaken_ > 0, "a full image to refine");
    bind(fields, inputs);
    pass(refineCell_, refineSide_);
    if (++refineCell_ == refineSide_ * refineSide_) {
        ++refineSide_;
        refineCell_ = 0;
    }
    gl::checkpoint("view stage refinement");
}

std::vector<float> ViewStage::downloadHdr() const {
    return hdr_.downloadAll<float>();
}

std::vector<glm::vec4> ViewStage::downloadExits() const {
    return exits_.downloadAll<glm::vec4>();
}

}  // namespace eikon::render
