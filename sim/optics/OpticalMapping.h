// From the solver's temperature, concentration and dye to what the tracer
// needs: δn = n − n_ref (float32; docs/architecture.md, Conventions),
// extinction κ and scattering σs per RGB channel, resampled trilinearly from
// the solver grid onto the render grid (they may differ; render cells
// outside the solver box see the ambient fluid). Air: Gladstone–Dale in
// temperature (AirOptics.h); liquid: the two liquids mixed by concentration
// (LiquidOptics.h); dye: κ = κ_dye·dye, σs = σ_dye·dye per channel
// (Beer–Lambert coefficients linear in concentration). sim::SceneFields
// applies it to the fluid solver's scalars (sim/field/SolverScalars.h).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/scene/Scene.h"
#include "sim/field/SolverScalars.h"
#include "sim/optics/AirOptics.h"

namespace eikon::sim {

class OpticalModel {
public:
    explicit OpticalModel(const SimDesc& desc);

    double index(double temperature, double concentration) const;
    Rgb extinction(double dye) const { return dyeExtinction_ * dye; }
    Rgb scattering(double dye) const { return dyeScattering_ * dye; }
    bool absorbs() const;    // some κ_dye channel > 0
    bool scatters() const;   // some σ_dye channel > 0

private:
    SimDesc::Fluid fluid_;
    GladstoneDale air_;
    double pressure_;
    double indexA_, indexB_;
    SimDesc::Mixing mixing_;
    Rgb dyeExtinction_, dyeScattering_;
};

// δn = n − n_ref of the ambient fluid (ambient temperature, concentration 0):
// what render cells outside the solver's box hold.
double ambientDeltaIndex(const SimDesc& desc, double referenceIndex);

// Writes δn (and κ, σs where `fields` has them) of every render cell straight
// into `fields`' memory, with n_ref = fields.referenceIndex. Versions and
// validation are the caller's.
void mapOpticalFields(const OpticalModel& model, const SolverScalars& scalars, const FieldViews& fields);

// Fills fields.deltaIndex, .extinction, .scattering on fields.grid (κ and σs
// left empty when the model has none) with n_ref = fields.referenceIndex, and
// increments each field's version only where its values changed. Validation
// is the caller's (SceneFields, which knows the scene's keys).
void writeOpticalFields(const OpticalModel& model, const SolverScalars& scalars, FieldSet& fields);

}  // namespace eikon::sim
