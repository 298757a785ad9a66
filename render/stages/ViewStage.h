// The viewing pass (shaders/view_rays.comp): curved camera rays into a
// linear HDR radiance image. Runs alone when only the camera changes.
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/ReceiverMaps.h"
#include "render/stages/SharpSurfaceBuffer.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace eikon::render {

layout::GpuCamera cameraBlock(const CameraDesc& camera, const RenderDesc& render);
unsigned environmentKind(const EnvironmentDesc& environment);  // layout::EnvironmentKind
// The hdr environment's map (no name for other environments), checked against GL_MAX_TEXTURE_SIZE.
gl::Texture2D environmentTexture(const Scene& scene);
// A vec4 per pixel of the scene's image, checked against GL_MAX_SHADER_STORAGE_BLOCK_SIZE.
gl::Buffer pixelBuffer(const Scene& scene, const std::string& description);

struct ViewInputs {
    const gl::Buffer* fluence = nullptr;           // smoothed φ, when the scene scatters
    const gl::Buffer* fluenceDirection = nullptr;  // and its mean direction
    const gl::Texture3D* stepTexture = nullptr;    // step structure, when built
    const gl::Buffer* multipleFluence = nullptr;   // φ of light scattered ≥ once, with multiple scattering
};

class ViewStage {
public:
    // recordExit: also keep each pixel's exit direction (tests), of one ray
    // through each pixel's centre, whatever render.samples_per_pixel says.
    // multipleScattering: the scene's in-scattering adds the lattice's fluence.
    ViewStage(const Scene& scene, const FieldTextures& fields, const ReceiverMaps& receivers, bool hasStepStructure,
              bool multipleScattering, bool recordExit = false);

    // The image: at pixel stride 1 the mean of render.samples_per_pixel = k² passes
    // of a ray a pixel through the cells of a k × k grid
    // (render/stages/PixelSamples.h), else one preview pass.
    void run(const FieldTextures& fields, const ViewInputs& inputs);
    // One more pass into the mean of those run() and earlier refinements
    // took, through the next cell of the next finer grid: (k+1)², (k+2)², …
    // cells in turn, so that each finished grid is a box-filtered image of
    // its own (the viewer while nothing moves). Only where refinable().
    void refine(const FieldTextures& fields, const ViewInputs& inputs);
    int samplesTaken() const { return samplesTaken_; }  // passes in the image now (0 after a preview)
    // Whether refine() may run and its grid is no finer than finestSide × finestSide.
    bool refinable(int finestSide) const { return pixelStride_ == 1 && samplesTaken_ > 0 && refineSide_ <= finestSide; }
    void setCamera(const CameraDesc& camera);
    // 1: a ray per pixel. k > 1: a preview, one ray per k×k block of pixels
    // filling the block (the viewer while the camera moves), about k² times
    // cheaper.
    void setPixelStride(int stride);
    int pixelStride() const { return pixelStride_; }

    // The linear image (HdrImage) as a buffer texture, for the tone map.
    const gl::BufferTexture& hdrTexels() const { return hdrTexels_; }
    std::vector<float> downloadHdr() const;  // RGBA per pixel, row 0 at the top
    // Per pixel: the direction the ray left in; w = 1 environment, 2 receiver, 0 step cap.
    std::vector<glm::vec4> downloadExits() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void bind(const FieldTextures& fields, const ViewInputs& inputs);
    // Cell `cell` of the k × k grid of each pixel, averaged with the samplesTaken_ passes before it.
    void pass(int cell, int k);

    const ReceiverMaps& receivers_;
    SharpSurfaceBuffer surfaces_;
    bool multipleScattering_;
    RenderDesc render_;
    int width_, height_;
    double stepLength_;     // m: the shortest step in media (render.step_voxels × the smallest voxel edge)
    double longestStep_;    // m: render.step_voxels × the largest voxel edge
    glm::dvec3 stepReach_;  // m: render.step_voxels × the voxel's edge along each axis
    unsigned maxSteps_;
    int pixelStride_ = 1;
    int samplesPerPixel_;
    int samplesTaken_ = 0;
    int refineSide_ = 0, refineCell_ = 0;  // the grid refine() is filling, and its next cell
    float interfaceHalfWidth_;
    gl::Program program_;
    gl::Buffer camera_;
    gl::Buffer hdr_;
    gl::BufferTexture hdrTexels_;
    gl::Buffer exits_;
    gl::Texture2D environment_;
};

}  // namespace eikon::render
