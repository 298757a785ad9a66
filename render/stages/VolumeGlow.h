// Emission lights (scene volume.emission_lights): the glowing cells of an
// imported volume as one photon emitter, kind 2 of layout::GpuEmitter
// (shaders/photon_trace.comp, emit_photon). A cell of emission ε
// (W/(m³·sr) per channel) and volume V radiates 4π·ε·V watts per channel,
// isotropically. A photon picks a cell with probability Σε(cell)/Σε(all),
// a point uniformly inside it and a direction uniformly over the sphere,
// and carries P/N · ε_c/Σε(cell) in channel c, P the volume's power summed
// over channels and N its photons: in expectation each channel emits
// 4π·V·Σ_cells ε_c. The view pass interpolates ε trilinearly; its integral
// over the grid is the same.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"

#include <vector>

namespace eikon::render {

struct GlowCells {
    std::vector<layout::GpuGlowCell> cells;  // those with Σε > 0, in cell order
    Rgb power{0.0};                          // W per channel, 4π·V·Σ ε
};

// The emitting cells of `emission` (RGB per cell, W/(m³·sr)) on `grid`.
GlowCells glowCells(const float* emission, const GridSpec& grid);

// The cells on the GPU, rebuilt whenever the emission changes.
class VolumeGlow {
public:
    void update(const float* emission, const GridSpec& grid);
    const Rgb& power() const { return power_; }
    bool glows() const { return power_.r + power_.g + power_.b > 0.0; }
    void bind() const;

private:
    gl::Buffer cells_;
    Rgb power_{0.0};
};

}  // namespace eikon::render
