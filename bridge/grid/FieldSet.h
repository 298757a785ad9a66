// The optical fields of one frame on a dense grid, as the simulation hands
// them to the renderer: index offset δn = n − n_ref (docs/architecture.md,
// Conventions: a mirage lives on Δn ≈ 1e-5, which float32 n would round
// away), extinction κ and scattering σs in 1/m per RGB channel. Each field carries a version that
// changes whenever its values do, so stages can skip unchanged inputs.
#pragma once

#include "bridge/grid/GridSpec.h"

#include <cstdint>
#include <string>
#include <vector>

namespace eikon {

constexpr std::size_t kSurfaceBoundsFloats = 6;  // per sharp-surface layer: min xyz, max xyz

struct FieldSet {
    GridSpec grid;
    double referenceIndex = 1.0;      // n_ref
    std::vector<float> deltaIndex;    // one per cell
    std::vector<float> extinction;    // three per cell (RGB), empty when κ = 0 everywhere
    std::vector<float> scattering;    // three per cell (RGB), empty when σs = 0 everywhere
    std::vector<float> anisotropy;    // Henyey–Greenstein g, one per cell, empty when g = 0 everywhere
    // The sharp mesh and water surfaces (sim/voxelize/MeshCoverage.h), one
    // layer per object in scene order: φ at every cell centre in metres,
    // negative inside, exact within a narrow band of the surface and clamped
    // to its edge beyond, layer after layer (empty when the scene has none);
    // and per layer the box outside which φ is positive (min xyz, max xyz).
    std::vector<float> surfaceDistance;
    std::vector<float> surfaceBounds;
    std::uint64_t indexVersion = 0;
    std::uint64_t extinctionVersion = 0;
    std::uint64_t scatteringVersion = 0;  // σs and g together
    std::uint64_t surfaceVersion = 0;     // surface distances and bounds together

    bool hasExtinction() const { return !extinction.empty(); }
    bool hasScattering() const { return !scattering.empty(); }
    bool hasAnisotropy() const { return !anisotropy.empty(); }
    std::size_t surfaceLayers() const { return surfaceBounds.size() / kSurfaceBoundsFloats; }
};

// Replaces `current` with `next` and bumps `version` if their values differ.
void publishField(std::vector<float>& current, std::vector<float>&& next, std::uint64_t& version);

// Throws InputError naming the field and cell of the first value that is not
// finite or out of range (n ≤ 0, κ < 0, σs < 0, σs > κ, φ not finite): fields are checked
// where they enter the bridge, never traced silently.
void validateFields(const FieldSet& fields, const std::string& source);

}  // namespace eikon
