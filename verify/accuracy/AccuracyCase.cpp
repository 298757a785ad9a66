#include "verify/accuracy/AccuracyCase.h"

#include "verify/accuracy/Cases.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace eikon::accuracy {

std::vector<std::unique_ptr<AccuracyCase>> allCases() {
    std::vector<std::unique_ptr<AccuracyCase>> cases;
    cases.push_back(makePointLightCase());
    cases.push_back(makeBeerLambertCase());
    cases.push_back(makeLinearSlabCase());
    cases.push_back(makeCatenaryMapCase());
    cases.push_back(makeMirageCase());
    cases.push_back(makeMirageMapCase());
    cases.push_back(makeLuneburgCase());
    cases.push_back(makeLuneburgMapCase());
    cases.push_back(makeFishEyeCase());
    cases.push_back(makeFishEyeMapCase());
    cases.push_back(makeGlassSphereCase());
    cases.push_back(makeGlassSphereMapCase());
    cases.push_back(makeHeatShimmerCase());
    return cases;
}

std::vector<RunSettings> standardSweep(bool quick, const SweepKnobs& knobs) {
    using I = TracerDesc::Integrator;
    using P = TracerDesc::StepPolicy;
    // Steps up to 4 voxels, so that leapfrog and RK4 show their order above the grid's floor.
    const std::vector<double> steps = quick ? std::vector<double>{4.0, 2.0, 1.0, 0.5, 0.25, 0.125}
                                            : std::vector<double>{4.0, 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625};
    const std::vector<double> minSteps = quick ? std::vector<double>{1.0, 0.5, 0.25}
                                               : std::vector<double>{1.0, 0.5, 0.25, 0.125};
    std::vector<RunSettings> runs;
    RunSettings base;
    base.smoothingVoxels = knobs.baseSmoothing;
    const std::vector<I> integrators =
        knobs.integrators ? std::vector<I>{I::Euler, I::Leapfrog, I::Rk4} : std::vector<I>{I::Leapfrog};
    for (I integrator : knobs.steps ? integrators : std::vector<I>{})
        for (double step : steps) {
            RunSettings run = base;
            run.integrator = integrator;
            run.stepVoxels = step;
            runs.push_back(run);
        }
    if (knobs.octree)
        for (I integrator : knobs.integrators ? std::vector<I>{I::Leapfrog, I::Rk4} : std::vector<I>{I::Leapfrog})
            for (double step : minSteps) {
                RunSettings run = base;
                run.integrator = integrator;
                run.stepPolicy = P::Octree;
                run.stepVoxels = step;
                runs.push_back(run);
            }
    if (knobs.grid)
        for (double scale : quick ? std::vector<double>{0.5, 2.0} : std::vector<double>{0.5, 1.5, 2.0}) {
            RunSettings run = base;
            run.integrator = I::Rk4;
            run.stepVoxels = 0.25;
            run.gridScale = scale;
            run.sweep = "grid";
            runs.push_back(run);
        }
    if (knobs.smoothing)
        for (double width : quick ? std::vector<double>{0.5, 2.0} : std::vector<double>{0.5, 1.5, 2.0, 3.0}) {
            RunSettings run = base;
            run.integrator = I::Rk4;
            run.stepVoxels = 0.25;
            run.smoothingVoxels = width;
            run.sweep = "smoothing";
            runs.push_back(run);
        }
    if (knobs.tolerances) {
        struct Tolerance {
            double epsilon, epsilonPrime, cap;
        };
        // The default; [Sun08]'s ε = 0.005, ε′ = 0.02 of a unit range with an
        // 8-voxel cap (0.01, 0.04 of a glass sphere's); a capped middle tier; tighter.
        for (Tolerance t : {Tolerance{0.002, 0.002, 8}, Tolerance{0.01, 0.04, 8}, Tolerance{0.002, 0.008, 4},
                            Tolerance{0.0005, 0.0005, 8}}) {
            RunSettings run = base;
            run.stepPolicy = P::Octree;
            run.stepVoxels = 0.5;
            run.epsilon = t.epsilon;
            run.epsilonPrime = t.epsilonPrime;
            run.maxStepVoxels = t.cap;
            run.sweep = "octree";
            runs.push_back(run);
        }
    }
    if (knobs.wavefront)
        for (double split : quick ? std::vector<double>{3.0, 1.5, 0.75} : std::vector<double>{4.0, 3.0, 2.0, 1.5, 1.0, 0.75}) {
            RunSettings run = base;
            run.stepPolicy = P::Octree;
            run.estimator = TracerDesc::Estimator::Wavefront;
            run.splitTexels = split;
            run.sweep = "wavefront";
            runs.push_back(run);
        }
    if (knobs.photons)
        for (int log2 : quick ? std::vector<int>{14, 16, 18, 20} : std::vector<int>{14, 16, 18, 20, 22}) {
            RunSettings run = base;
            run.stepPolicy = P::Octree;
            run.photons = 1LL << log2;
            run.sweep = "photons";
            runs.push_back(run);
        }
    return runs;
}

RunRecord makeRecord(const Scene& scene, const RunSettings& settings, const GpuTrace& trace, Measurement measurement,
                     double arcLength) {
    RunRecord record;
    record.settings = settings;
    const glm::ivec3 r = scene.grid.resolution;
    record.grid = std::to_string(r.x) + "x" + std::to_string(r.y) + "x" + std::to_string(r.z);
    record.photons = settings.estimator == TracerDesc::Estimator::Photons ? scene.render.photons : 0;  // the wavefront has none
    record.runtimeSeconds = trace.runtimeSeconds;
    record.stats = trace.stats;
    record.measurement = std::move(measurement);
    if (arcLength > 0.0 && settings.stepPolicy == TracerDesc::StepPolicy::Uniform) {
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const double steps = arcLength / (settings.stepVoxels * h);
        const auto k = static_cast<std::size_t>(std::lround(steps));
        if (std::abs(steps - static_cast<double>(k)) < 1e-6)
            for (std::size_t p = 0; p < trace.paths.size(); ++p) {
                const PhotonPath& path = trace.paths[p];
                std::size_t entry = 0;
                while (entry < path.size() && !grid.contains(path[entry])) ++entry;
                // Vertex entry + k, if the photon was still marching in the grid then.
                bool marching = k > 0 && entry + k + 1 < path.size();
                for (std::size_t v = entry; marching && v <= entry + k + 1; ++v) marching = grid.contains(path[v]);
                if (marching)
                    record.positionsAtArc[trace.pathIndex[p]] = {
                        path[entry + k] / h, glm::normalize(path[entry + k + 1] - path[entry + k - 1])};
            }
    }
    return record;
}

RunRecord makeImageSpaceRecord(const RunSettings& settings, double runtimeSeconds, Measurement measurement) {
    RunRecord record;
    record.settings = settings;
    record.runtimeSeconds = runtimeSeconds;
    record.measurement = std::move(measurement);
    return record;
}

void measureStepErrors(std::vector<RunRecord>& records) {
    for (RunRecord& record : records) {
        if (record.positionsAtArc.empty()) continue;
        const RunRecord* finest = nullptr;
        for (const RunRecord& other : records)
            if (other.measurement.caseName == record.measurement.caseName && other.grid == record.grid &&
                other.settings.smoothingVoxels == record.settings.smoothingVoxels && !other.positionsAtArc.empty() &&
                other.settings.integrator == TracerDesc::Integrator::Rk4 &&
                (!finest || other.settings.stepVoxels < finest->settings.stepVoxels))
                finest = &other;
        if (!finest || finest == &record || finest->settings.stepVoxels >= record.settings.stepVoxels) continue;
        std::vector<double> distances;
        for (const auto& [photon, position] : record.positionsAtArc) {
            const auto it = finest->positionsAtArc.find(photon);
            if (it == finest->positionsAtArc.end()) continue;
            const glm::dvec3 offset = position.position - it->second.position;
            distances.push_back(glm::length(offset - glm::dot(offset, it->second.tangent) * it->second.tangent));
        }
        if (!distances.empty()) record.stepErrorVoxels = rms(distances);
    }
}

long long pathCasePhotons(bool quick) { return quick ? 1LL << 15 : 1LL << 17; }

TraceRequest pathRequest(const Scene& scene, double pathLengthVoxels, double stepVoxels) {
    TraceRequest request;
    request.recordedPhotons = kRecordedPhotons;
    request.recordStride = static_cast<int>(std::max<long long>(1, scene.render.photons / kRecordedPhotons));
    request.pathVertices = static_cast<int>(std::ceil(1.5 * pathLengthVoxels / stepVoxels)) + 16;
    return request;
}

double rms(const std::vector<double>& values) {
    if (values.empty()) return 0.0;
    double sum = 0.0;
    for (double v : values) sum += v * v;
    return std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace eikon::accuracy
