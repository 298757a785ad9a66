#include "render/stages/ImageSpaceView.h"

#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/ViewStage.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <string>

namespace eikon::render {

namespace {

gl::Program viewProgram(const Scene& scene, const ReceiverMaps& receivers, int pass, bool recordExit) {
    gl::ShaderDefines options = WaterHeightFields::programOptions(scene);
    options.insert({{"EIKON_PASS", std::to_string(pass)},
                    {"EIKON_ENVIRONMENT", std::to_string(environmentKind(scene.render.environment))},
                    {"EIKON_RECORD_EXIT", recordExit ? "1" : "0"},
                    receivers.countOption()});
    return gl::compileComputeProgram("image_space_view.comp", options);
}

}  // namespace

glm::dvec2 rasterPlanes(const glm::dvec3& eye, const glm::dvec3& centre, double radius) {
    const double distance = glm::length(centre - eye);
    const double farPlane = 1.01 * (distance + radius);
    return {std::max(0.99 * (distance - radius), 1e-3 * radius), farPlane};
}

ImageSpaceView::ImageSpaceView(const Scene& scene, const ReceiverMaps& receivers, SurfaceRaster& raster,
                               bool recordExit)
    : receivers_(receivers), raster_(raster),
      render_(scene.render), camera_(scene.camera),
      gridCentre_(0.5 * (scene.grid.boundsMin + scene.grid.boundsMax)),
      gridRadius_(0.5 * glm::length(scene.grid.boundsMax - scene.grid.boundsMin)),
      hdr_(pixelBuffer(scene, "the linear image")), environment_(environmentTexture(scene)) {
    if (raster.hasLayerSurfaces()) {
        layers_.emplace(scene.render.width, scene.render.height,
                        gl::GpuResource{"render.width × render.height", "the camera's surface layers"});
        listingProgram_ = viewProgram(scene, receivers, 0, recordExit);
        surfaceProgram_ = viewProgram(scene, receivers, 1, recordExit);
        surfacePixels_ = gl::Buffer(static_cast<std::size_t>(scene.render.width) *
                                        static_cast<std::size_t>(scene.render.height) * sizeof(GLuint),
                                    {"render.width × render.height", "the list of pixels that see a surface"});
        surfacePixelCount_ = gl::Buffer(sizeof(glm::uvec4), {"render", "the count of pixels that see a surface"});
    } else {
        surfaceProgram_ = viewProgram(scene, receivers, 2, recordExit);
    }
    hdrTexels_ = gl::BufferTexture(hdr_, GL_RGBA32F, {"render.width × render.height", "the linear image"});
    if (recordExit) exits_ = pixelBuffer(scene, "the camera rays' exits");
    const layout::GpuCamera block = cameraBlock(scene.camera, scene.render);
    cameraBlock_ = gl::Buffer(sizeof block, &block, GL_DYNAMIC_STORAGE_BIT);
}

void ImageSpaceView::run(const FieldTextures& fields) {
    const glm::dvec2 planes = rasterPlanes(camera_.position, gridCentre_, gridRadius_);
    const Viewpoint view = cameraViewpoint(camera_, render_, planes.x, planes.y);
    if (layers_) raster_.draw(view, *layers_, fields);
    else raster_.updateWater(fields);
    const layout::GpuCamera block = cameraBlock(camera_, render_);
    cameraBlock_.upload(&block, sizeof block);
    fields.bindForTracing();
    receivers_.bind();
    raster_.bindSurfaces();
    cameraBlock_.bindUniform(layout::kCameraBlock);
    if (environment_.id()) environment_.bindSampler(layout::kEnvironmentTexture);
    hdr_.bindStorage(layout::kHdrImage);
    if (exits_.id()) exits_.bindStorage(layout::kViewExit);
    if (layers_) {
        drawThroughLayers(view);
    } else {
        surfaceProgram_.use();
        surfaceProgram_.dispatchCovering(static_cast<std::size_t>(render_.width),
                                         static_cast<std::size_t>(render_.height));
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    gl::checkpoint("image-space view");
}

void ImageSpaceView::drawThroughLayers(const Viewpoint& view) {
    layers_->bind();
    const glm::uvec4 noPixels(0u, 1u, 1u, 0u);  // pass 1's work groups (x, y, z) and the pixels listed
    surfacePixelCount_.upload(&noPixels, sizeof noPixels);
    surfacePixels_.bindStorage(layout::kSurfacePixels);
    surfacePixelCount_.bindStorage(layout::kSurfacePixelCount);
    listingProgram_.use();
    listingProgram_.dispatchCovering(static_cast<std::size_t>(render_.width),
                                     static_cast<std::size_t>(render_.height));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    surfaceProgram_.use();
    glUniformMatrix4fv(surfaceProgram_.uniform("view_projection"), 1, GL_FALSE, glm::value_ptr(view.viewProjection));
    surfaceProgram_.dispatchIndirect(surfacePixelCount_);
}

std::vector<float> ImageSpaceView::downloadHdr() const {
    return hdr_.downloadAll<float>();
}

std::vector<glm::vec4> ImageSpaceView::downloadExits() const {
    return exits_.downloadAll<glm::vec4>();
}

}  // namespace eikon::render
