// Image-space caustics (shaders/image_space_caustics.comp; [Wyman06] §3,
// [Hu07]'s caustic maps): for each light, its surface layers are drawn over
// the scene's refractors (LightFrames.h: a perspective frustum from a point
// or spot light, an orthographic box along a directional light's
// direction), every texel becomes a photon with the power of its solid angle,
// refracts through two interfaces and lands on a receiver; neighbouring
// photons bound caustic polygons that carry the power between them onto the
// receivers (CausticPolygons.h); the light no refractor intercepts reaches
// each receiver texel in closed form.
// The receivers' maps then hold W/m², like the eikonal photons'.
//
// Temporal filtering ([Wyman06] §3.2.3, four frames): while neither the
// surfaces nor the lights change, each frame adds photons offset by a
// different quarter of a texel to the tallies, and the maps are their mean
// over up to kTemporalFrames frames. A change starts the mean again, so a
// moving scene shows no lag (the paper's filter blends moving frames).
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/CausticPolygons.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/LightFrames.h"
#include "render/stages/ReceiverMaps.h"
#include "render/stages/SurfaceLayers.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace eikon::render {

constexpr int kTemporalFrames = 4;

class ImageSpaceCaustics {
public:
    ImageSpaceCaustics(const Scene& scene, ReceiverMaps& receivers, SurfaceRaster& raster);

    // changed: the surfaces or lights changed since the last run (the mean starts again).
    void run(const FieldTextures& fields, bool changed);
    // Whether another frame would refine the temporal mean.
    bool refining() const { return frames_ < kTemporalFrames; }
    void setLight(std::size_t index, const LightDesc& light);
    int framesAveraged() const { return frames_; }

private:
    // Every light's frame over the refractors as they are now.
    std::vector<LightFrame> lightFramesNow(const FieldTextures& fields) const;

    Scene scene_;
    ReceiverMaps& receivers_;
    SurfaceRaster& raster_;
    std::vector<LightDesc> lights_;
    std::vector<std::unique_ptr<SurfaceLayers>> layers_;  // one per light
    // The lights' frames their layers were drawn in; empty: none drawn yet.
    // Both hold while neither the surfaces nor the lights change, so the
    // frames of one temporal mean draw the layers once.
    std::vector<LightFrame> lightFrames_;
    gl::Program directProgram_, photonProgram_;
    CausticPolygons polygons_;
    glm::vec3 powerUnit_{1.0f};
    int frames_ = 0;
};

}  // namespace eikon::render
