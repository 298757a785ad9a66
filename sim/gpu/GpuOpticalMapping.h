// sim/optics/OpticalMapping.h on the GPU: the solver's scalars, where the
// GPU backend keeps them, to δn, κ and σs on the render grid, written
// straight into GL buffers the renderer reads (the live field ring's
// device-local slots), so a frame simulated on the GPU never crosses the bus
// (shaders/sim/optical_mapping.comp).
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "sim/gpu/GpuField.h"

namespace eikon::sim::gpu {

// The buffers a mapping writes (GL names; 0 where the scene lacks the field).
struct OpticalTargets {
    GLuint deltaIndex = 0;  // float per render cell
    GLuint extinction = 0;  // RGB floats per render cell
    GLuint scattering = 0;  // RGB floats per render cell
};

class GpuOpticalMapping {
public:
    GpuOpticalMapping(const SimDesc& desc, const GridSpec& solverGrid, const GridSpec& renderGrid,
                      double referenceIndex);

    // Writes every render cell's δn (n_ref = the reference index), and κ and
    // σs where the model has them, from the temperature (stored as T − T_amb),
    // concentration and dye on the solver grid.
    void map(const GpuField& temperature, const GpuField& concentration, const GpuField& dye,
             const OpticalTargets& targets) const;

    bool absorbs() const { return absorbs_; }
    bool scatters() const { return scatters_; }

private:
    GridSpec solver_, render_;
    bool absorbs_, scatters_;
    gl::Program program_;
};

}  // namespace eikon::sim::gpu
