#include "apps/eikon/ErrorWarning.h"

#include <cstdio>

#include <iostream>
#include <optional>
#include <string>

namespace eikon::app {

namespace {

struct Worst {
    double error = 0.0;
    const char* output = "";
};

Worst worstOf(const render::OutputErrors& errors) {
    Worst worst;
    const std::pair<const char*, std::optional<double>> outputs[] = {
        {"the receiver maps", errors.receivers}, {"the image", errors.image}, {"the fluence", errors.fluence},
        {"the deflection", errors.deflection}, {"the optical path difference", errors.opticalPathDifference},
        {"the displacement", errors.displacement}};
    for (const auto& [name, error] : outputs)
        if (error && *error > worst.error) worst = {*error, name};
    return worst;
}

// Three significant digits: a warning's figures are estimates.
std::string threeDigits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

}  // namespace

void ErrorWarning::check(int frame, const render::FrameResult& result) {
    if (warned_ || !result.errorEstimate) return;
    const render::ErrorEstimate& estimate = *result.errorEstimate;
    const Worst noise = worstOf(estimate.noise);
    const Worst discretisation = worstOf(estimate.discretisation);
    const auto percent = [](double value) { return threeDigits(100.0 * value) + "%"; };
    if (discretisation.error > threshold_) {
        std::cerr << "eikon: warning: frame " << frame << ": discretisation error of " << discretisation.output
                  << " estimated at " << percent(discretisation.error)
                  << " against the reference march (RK4, steps of " << threeDigits(estimate.referenceStepVoxels)
                  << " voxel where the index varies), above render.warn_error = " << percent(threshold_)
                  << ": the steps are too long for this medium (tracer.step_voxels, tracer.epsilon, "
                     "tracer.epsilon_prime, render.step_voxels); later frames are not reported here\n";
        warned_ = true;
    } else if (noise.error > threshold_) {
        std::cerr << "eikon: warning: frame " << frame << ": noise of " << noise.output << " estimated at "
                  << percent(noise.error) << " (relative RMS), above render.warn_error = " << percent(threshold_)
                  << ": more render.photons (the noise falls as 1/sqrt of their number), or tracer.estimator "
                     "\"wavefront\" where nothing scatters; later frames are not reported here\n";
        warned_ = true;
    }
}

}  // namespace eikon::app
