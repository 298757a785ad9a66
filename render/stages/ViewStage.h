// The viewing pass (shaders/view_rays.comp): curved camera rays into a
// linear HDR radiance image.
#pragma once

#include "bridge/scene/Scene.h"
#include "render/gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/ReceiverMaps.h"

namespace eikon::render {

layout::GpuCamera cameraBlock(const CameraDesc& camera, const RenderDesc& render);

class ViewStage {
public:
    ViewStage(const Scene& scene, const FieldTextures& fields, const ReceiverMaps& receivers);

    // Fluence is the photon stage's buffer (ignored when the scene does not scatter).
    void run(const FieldTextures& fields, const gl::Buffer& fluence, double stepLength, unsigned maxSteps);
    void setCamera(const CameraDesc& camera);

    const gl::Buffer& hdrImage() const { return hdr_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    const ReceiverMaps& receivers_;
    RenderDesc render_;
    int width_, height_;
    gl::Program program_;
    gl::Buffer camera_;
    gl::Buffer hdr_;
};

}  // namespace eikon::render
