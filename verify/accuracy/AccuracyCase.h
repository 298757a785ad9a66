// The accuracy cases of `eikon accuracy` (docs/accuracy.md): each builds an
// analytic scene, voxelizes it, traces it on the GPU under one setting of the
// tracer's knobs and measures the error against its ground truth.
#pragma once

#include "verify/accuracy/AccuracyRun.h"

#include <memory>
#include <string>
#include <vector>

namespace eikon::accuracy {

class AccuracyCase {
public:
    virtual ~AccuracyCase() = default;
    virtual std::string name() const = 0;
    // The settings this case is run under (fewer with `quick`).
    virtual std::vector<RunSettings> sweep(bool quick) const = 0;
    // One GPU trace under `settings`; one record per error measure the case takes.
    virtual std::vector<RunRecord> run(const RunSettings& settings, bool quick) const = 0;
};

// Every case, in report order.
std::vector<std::unique_ptr<AccuracyCase>> allCases();

// Which knobs a case sweeps besides the step of each integrator.
struct SweepKnobs {
    bool steps = true;         // uniform steps over Δs
    bool integrators = true;   // Euler, leapfrog and RK4 (else leapfrog only)
    bool octree = true;        // octree steps over Δs_min
    bool grid = true;          // grid resolution at a fine step
    bool smoothing = false;    // interface smoothing width at a fine step
    bool photons = false;      // photon count
    bool tolerances = false;   // octree ε, ε′ and step cap
    bool wavefront = false;    // the wavefront estimator over its split size (receiver cases)
    double baseSmoothing = 0.0;
};
std::vector<RunSettings> standardSweep(bool quick, const SweepKnobs& knobs);

// Fills the common parts of a record from a trace; with `arcLength` > 0 (m)
// and uniform steps, also the positions at that arc length.
RunRecord makeRecord(const Scene& scene, const RunSettings& settings, const GpuTrace& trace, Measurement measurement,
                     double arcLength = 0.0);

// The record of an image-space run: its settings, time and measurement (no
// grid, photons or tracer statistics).
RunRecord makeImageSpaceRecord(const RunSettings& settings, double runtimeSeconds, Measurement measurement);

// Fills stepErrorVoxels of every record that has positions at arc length,
// against the finest-step RK4 uniform run of its case, grid and smoothing.
void measureStepErrors(std::vector<RunRecord>& records);

// Photons traced by a path case and how many of them are recorded.
long long pathCasePhotons(bool quick);
constexpr int kRecordedPhotons = 1024;
TraceRequest pathRequest(const Scene& scene, double pathLengthVoxels, double stepVoxels);

// Root mean square of `values` (0 when empty).
double rms(const std::vector<double>& values);

}  // namespace eikon::accuracy
