#include "apps/eikon/ErrorWarning.h"

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
        {"receivers", errors.receivers}, {"image", errors.image}, {"fluence", errors.fluence}};
    for (const auto& [name, error] : outputs)
        if (error && *error > worst.error) worst = {*error, name};
    return worst;
}

}  // namespace

void ErrorWarning::check(int frame, const render::FrameResult& result) {
    if (warned_ || !result.errorEstimate) return;
    const render::ErrorEstimate& estimate = *result.errorEstimate;
    const Worst noise = worstOf(estimate.noise);
    const Worst discretisation = worstOf(estimate.discretisation);
    const auto percent = [](double value) { return std::to_string(100.0 * value) + "%"; };
    if (discretisation.error > threshold_) {
        std::cerr << "eikon: warning: frame " << frame << ": the " << discretisation.output
                  << " change by " << percent(discretisation.error)
                  << " when traced with the reference march (RK4, steps of " << estimate.referenceStepVoxels
                  << " voxels where the index varies), above render.warn_error = " << percent(threshold_)
                  << ": the steps are too long for this medium (tracer.step_voxels, tracer.epsilon, "
                     "render.step_voxels); later frames are not reported here\n";
        warned_ = true;
    } else if (noise.error > threshold_) {
        std::cerr << "eikon: warning: frame " << frame << ": the " << noise.output << " have an estimated noise of "
                  << percent(noise.error) << " (relative RMS), above render.warn_error = " << percent(threshold_)
                  << ": more render.photons (the noise falls as 1/sqrt of their number), or tracer.estimator "
                     "\"wavefront\" where nothing scatters; later frames are not reported here\n";
        warned_ = true;
    }
}

}  // namespace eikon::app
