// A light's frame over the scene's refractors for the image-space caustic
// maps (ImageSpaceCaustics.h): the view its surface layers are drawn in,
// and the frame of their texels. The texels' size is set by the
// refractors' bounding sphere — render.caustic_map_texels texels across it,
// seen from a point or spot light as a cone, along a directional light as
// a disc — and the layers then cover only as many of them as the
// refractors' own outline needs: spheres exactly, anything else by its box.
// A pool (a flat box) fits in 186² of 256² texels, the default scene's
// sphere in 142², where the bounding sphere of its box spent the other
// texels' photons, work and all, on nothing.
#pragma once

#include "bridge/scene/Scene.h"
#include "render/stages/SurfaceLayers.h"

#include <glm/vec3.hpp>

#include <vector>

namespace eikon::render {

// A refractor's extent: a sphere (centre, radius) or a box (low, high).
struct RefractorExtent {
    bool sphere = false;
    glm::dvec3 low{0.0}, high{0.0};  // a box's corners
    glm::dvec3 centre{0.0};          // a sphere's
    double radius = 0.0;

    static RefractorExtent ofBox(const glm::dvec3& low, const glm::dvec3& high) { return {false, low, high, {}, 0.0}; }
    static RefractorExtent ofSphere(const glm::dvec3& centre, double radius) { return {true, {}, {}, centre, radius}; }
};

struct LightFrame {
    Viewpoint view;
    glm::vec3 right{0.0f}, up{0.0f};
    double halfExtent = 1.0;  // perspective: tan of the half-angle; orthographic: half the width
    int texels = 1;           // the layers' edge it uses (at most render.caustic_map_texels)
};

// The frame of `light` over `refractors`, with texels as large as
// `mapTexels` of them across the refractors' bounding sphere.
LightFrame lightFrameOver(const LightDesc& light, const std::vector<RefractorExtent>& refractors, int mapTexels);

}  // namespace eikon::render
