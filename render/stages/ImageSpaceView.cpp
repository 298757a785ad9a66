#include "render/stages/ImageSpaceView.h"

#include "render/gl/GlDebug.h"
#include "render/gl/ShaderLibrary.h"
#include "render/stages/ViewStage.h"

#include <glm/gtc/type_ptr.hpp>

namespace eikon::render {

gl::Buffer imageSpaceSurfaceExtinction(const Scene& scene) {
    std::vector<glm::vec4> extinction;
    for (const ObjectDesc& object : scene.objects)
        if (object.isSharp()) extinction.emplace_back(glm::vec3(object.material.extinction), 0.0f);
    if (extinction.empty()) extinction.emplace_back(0.0f);  // a buffer of one for a scene without surfaces
    return gl::Buffer(extinction.size() * sizeof(glm::vec4), extinction.data(), GL_DYNAMIC_STORAGE_BIT,
                      {"objects", "the surfaces' extinction"});
}

ImageSpaceView::ImageSpaceView(const Scene& scene, const ReceiverMaps& receivers, SurfaceRaster& raster,
                               bool recordExit)
    : receivers_(receivers), raster_(raster), extinction_(imageSpaceSurfaceExtinction(scene)),
      render_(scene.render), camera_(scene.camera),
      layers_(scene.render.width, scene.render.height, {"render.width × render.height", "the camera's surface layers"}),
      program_(gl::compileComputeProgram(
          "image_space_view.comp", {{"EIKON_ENVIRONMENT", std::to_string(environmentKind(scene.render.environment))},
                                    {"EIKON_RECORD_EXIT", recordExit ? "1" : "0"}})),
      hdr_(pixelBuffer(scene, "the linear image")), environment_(environmentTexture(scene)) {
    if (recordExit) exits_ = pixelBuffer(scene, "the camera rays' exits");
    const layout::GpuCamera block = cameraBlock(scene.camera, scene.render);
    cameraBlock_ = gl::Buffer(sizeof block, &block, GL_DYNAMIC_STORAGE_BIT);
}

void ImageSpaceView::run(const FieldTextures& fields) {
    const Viewpoint view = cameraViewpoint(camera_, render_, kRasterNearPlane, kRasterFarPlane);
    raster_.draw(view, layers_, fields);
    const layout::GpuCamera block = cameraBlock(camera_, render_);
    cameraBlock_.upload(&block, sizeof block);
    fields.bindForTracing();
    receivers_.bind();
    raster_.surfaces().bind();
    layers_.bind();
    extinction_.bindStorage(layout::kImageSpaceSurfaces);
    cameraBlock_.bindUniform(layout::kCameraBlock);
    if (environment_.id()) environment_.bindSampler(layout::kEnvironmentTexture);
    hdr_.bindStorage(layout::kHdrImage);
    if (exits_.id()) exits_.bindStorage(layout::kViewExit);
    program_.use();
    glUniformMatrix4fv(program_.uniform("view_projection"), 1, GL_FALSE, glm::value_ptr(view.viewProjection));
    glUniform1ui(program_.uniform("receiver_count"), receivers_.count());
    program_.dispatchCovering(static_cast<std::size_t>(render_.width), static_cast<std::size_t>(render_.height), 1, 8,
                              8, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    gl::checkpoint("image-space view");
}

std::vector<float> ImageSpaceView::downloadHdr() const {
    std::vector<float> rgba(hdr_.bytes() / sizeof(float));
    hdr_.download(rgba.data(), rgba.size() * sizeof(float));
    return rgba;
}

std::vector<glm::vec4> ImageSpaceView::downloadExits() const {
    std::vector<glm::vec4> exits(exits_.bytes() / sizeof(glm::vec4));
    if (!exits.empty()) exits_.download(exits.data(), exits.size() * sizeof(glm::vec4));
    return exits;
}

}  // namespace eikon::render
