// How much a receiver map changes when the photons that made it land
// elsewhere: the discretisation estimate's receivers figure
// (ErrorEstimateStage.h). A probe of photons traced with the scene's march
// and with the reference march samples the displacement of where they land;
// the frame's own map, its power moved by that displacement field, is the
// map the reference march would have made, to first order in the probe's
// sampling. Moving the map rather than the probe's few photons lets
// neighbouring displacements cancel as they do in the map: a caustic shifted
// by a few texels changes the map by its edges, not by twice its power.
#pragma once

#include <glm/vec2.hpp>

#include <vector>

namespace eikon::render {

// A probe photon that landed on the same receiver under both marches.
struct LandingPair {
    glm::dvec2 scene;      // where the scene's march landed, in texels (0 … resolution, texel centres at k + ½)
    glm::dvec2 reference;  // where the reference march landed
    double power = 0.0;    // its power, W (weights the displacement field)
};

// ‖M − M′‖₁ and ‖M′‖₁ over the RGB of every texel (their ratio is the
// relative change), with M the map (RGB per texel, rows along v) and M′ its
// power moved by the displacement field reference − scene that the pairs
// sample: their power-weighted Gaussian mean on a lattice of √(pairs/4)
// nodes a side (σ one node spacing; a node no pair comes within 3σ of takes
// its nearest pair's), bilinear between nodes. Each texel's power goes to
// its centre plus the displacement, shared bilinearly there; power moved off
// the map is lost. Zero without pairs.
struct MapChange {
    double difference = 0.0, norm = 0.0;
};
MapChange displacedMapChange(const std::vector<float>& map, int resolution, const std::vector<LandingPair>& pairs);

}  // namespace eikon::render
