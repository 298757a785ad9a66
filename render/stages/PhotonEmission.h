// Photon emission set-up ([Sun08] §4.3, with the shadow-map trick
// replaced by a bounding cone): photons leave each light only toward the box
// that holds the non-empty medium and the receivers, and each carries the
// power of the solid angle (point, spot) or area (directional) it stands for,
// so the photons of a light sum to the power that light sends into that
// region (for a spot, in expectation over its profile).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace eikon::render {

struct Box {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
};

// Box around the part of the scene light must reach: each sphere and box
// and each paint stroke's reach clipped to the grid, and each receiver's
// square; the whole grid where the medium attenuates, where a fluid solver
// or an imported volume supplies it, or where a mesh or water object is, and
// when there is nothing else.
Box emissionRegion(const Scene& scene);

// A spot's intensity I0 on its axis (W/sr per channel): its intensity is
// I0·profile(θ), the profile 1 inside the inner cone and a smoothstep in
// cos θ down to 0 at the outer cone, so that the power inside the cone is
// the light's power: Φ = I0 · 2π [(1 − cos θi) + (cos θi − cos θo)/2]
// = I0 · π (vo + vi), v = 1 − cos θ the versines.
Rgb spotPeakIntensity(const LightDesc& light);

// A spot's outer and inner half-angles as versines 1 − cos θ = 2 sin²(θ/2),
// which keep their digits for cones too narrow for a float cosine.
glm::dvec2 spotVersines(const LightDesc& light);

// The power the lights (and a glowing volume of power glowPower) state they
// send into what the light pass samples — each light's cone or disk for
// photons, its gnomonic square, square or six cube faces for the wavefront —
// from their statements in double precision (a spot cut by its domain by a
// fine quadrature of its profile), not from the packets: the ledger's
// reference for the emitted power (PhotonStats::emissionError).
Rgb statedEmission(const std::vector<LightDesc>& lights, const Box& region, bool wavefront,
                   const Rgb& glowPower = Rgb(0.0));

// One emitter per light with non-zero power toward `region`, and one for a
// glowing volume of power `glowPower` (render/stages/VolumeGlow.h) where it
// is non-zero; photons are shared among them in proportion to that power
// (each at least one).
std::vector<layout::GpuEmitter> buildEmitters(const std::vector<LightDesc>& lights, const Box& region,
                                              long long photons, const Rgb& glowPower = Rgb(0.0));

}  // namespace eikon::render
