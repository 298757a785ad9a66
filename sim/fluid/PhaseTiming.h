// Wall time of one solver phase summed over the substeps of the last frame,
// with the solver iterations it took (diffusion: Gauss–Seidel sweeps or CG
// iterations, summed over the fields; pressure: PCG iterations) and the worst
// relative residual they reached. Both backends report their phases so
// (the GPU backend's times come from GL timer queries).
#pragma once

#include <string>

namespace eikon::sim {

struct PhaseTiming {
    std::string phase;  // "sources", "advection", "diffusion", "projection"
    double milliseconds = 0.0;
    int iterations = 0;
    double residual = 0.0;
};

}  // namespace eikon::sim
