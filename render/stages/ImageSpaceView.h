// The image-space camera view (shaders/image_space_view.comp, [Hu07] §2):
// the camera's surface layers drawn with the raster pipeline, then per
// pixel Fresnel reflection and two-interface refraction found in those
// layers, into the same linear HDR image as the eikonal ViewStage. Where
// the only sharp surfaces are water bodies, no layers are drawn: each
// pixel meets the water on its height fields in one pass. Runs when the
// camera, the surfaces or the receivers' maps change.
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/ReceiverMaps.h"
#include "render/stages/SurfaceLayers.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <vector>

namespace eikon::render {

// Near and far planes (metres) of a raster pass's projection from `eye`
// holding the sphere (centre, radius) its surfaces lie in: just before and
// past the sphere, whatever the scene's scale (fixed planes at 1 mm and 1 km
// lost the surfaces of a scene larger or smaller than that). From inside the
// sphere the near plane is a thousandth of its radius (1 mm in a 1 m scene,
// as the fixed plane was).
glm::dvec2 rasterPlanes(const glm::dvec3& eye, const glm::dvec3& centre, double radius);

class ImageSpaceView {
public:
    ImageSpaceView(const Scene& scene, const ReceiverMaps& receivers, SurfaceRaster& raster, bool recordExit = false);

    void run(const FieldTextures& fields);
    void setCamera(const CameraDesc& camera) { camera_ = camera; }

    // The linear image (HdrImage) as a buffer texture, for the tone map.
    const gl::BufferTexture& hdrTexels() const { return hdrTexels_; }
    std::vector<float> downloadHdr() const;  // RGBA per pixel, row 0 at the top
    // Per pixel: the direction the refracted (else reflected) branch left in; w = 1 environment, 2 receiver.
    std::vector<glm::vec4> downloadExits() const;

private:
    void drawThroughLayers(const Viewpoint& view);  // passes 0 and 1

    const ReceiverMaps& receivers_;
    SurfaceRaster& raster_;
    RenderDesc render_;
    CameraDesc camera_;
    glm::dvec3 gridCentre_;  // the sphere around the grid, where the surfaces are (rasterPlanes)
    double gridRadius_;
    // With layers (SurfaceRaster::hasLayerSurfaces): image_space_view.comp's
    // pass 0 (listingProgram_) lists the pixels that see a surface, pass 1
    // (surfaceProgram_) draws them; without, pass 2 (surfaceProgram_) draws
    // every pixel, and the listing program and buffers stay empty.
    std::optional<SurfaceLayers> layers_;
    gl::Program listingProgram_, surfaceProgram_;
    gl::Buffer surfacePixels_, surfacePixelCount_;
    gl::Buffer cameraBlock_;
    gl::Buffer hdr_;
    gl::BufferTexture hdrTexels_;
    gl::Buffer exits_;
    gl::Texture2D environment_;
};

}  // namespace eikon::render
