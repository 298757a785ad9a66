// `eikon converge`: a self-convergence study of the user's own scene. Every
// rung of the ladder (ConvergeLadder.h) is rendered in this process and
// compared with the reference, output by output (relative L1: Σ|x − x_ref| /
// Σ|x_ref| over every texel, pixel or cell and channel), within a wall-time
// budget that the reference's refinement is scaled to.
#pragma once

#include "verify/converge/ConvergeLadder.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace eikon::converge {

struct Outputs {
    bool receivers = false, image = false, fluence = false;
};

// What each output's error is measured by (CSV headers, the report).
inline constexpr const char* kMetric = "relative L1";

struct Measured {
    Rung rung;
    double seconds = 0.0;  // the frame's render stages, upload to tone map
    std::optional<double> receivers, image, fluence;  // against the reference; unset where not compared
    // The largest error over the outputs compared (infinite where none is).
    double worst() const;
};

struct StudyOptions {
    double budgetSeconds = 300.0;
    int frame = 0;
    Outputs outputs;
    std::optional<Refinement> reference;  // unset: chosen to fit the budget
    std::function<void(const Measured&)> onRung;  // progress
    // The scene a reference rung describes, as the scene loader makes it of
    // the scene file with the rung's overrides (InputError where the file
    // could not hold them): the reference is checked so before the study
    // renders anything, and rendered as the loader makes it.
    std::function<Scene(const Rung&)> loadedScene;
};

struct Study {
    std::vector<Measured> rungs;  // in the ladder's order, those that were rendered
    Measured reference;
    std::vector<std::string> leftOut;
    double wallSeconds = 0.0;
    double budgetSeconds = 0.0;
    bool byWavefront = false;
    TracerDesc::Integrator integrator = TracerDesc::Integrator::Leapfrog;
};

// The outputs the scene has: receivers where it has any, the image always,
// fluence where it is stored (scattering, tracer.store_fluence).
Outputs outputsOf(const Scene& scene);

// InputError before anything renders where the reference cannot be
// rendered as asked (an explicit one held at a least value, or one the
// scene file could not hold) or the budget cannot hold the simulation to
// options.frame (StudyFields.h).
Study runStudy(const Scene& scene, const StudyOptions& options);

}  // namespace eikon::converge
