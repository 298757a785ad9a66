#include "verify/accuracy/AccuracyReport.h"

#include "io/files/AtomicFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace eikon::accuracy {

namespace {

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

std::string percent(double error) {
    if (!std::isfinite(error)) return "—";
    if (error >= 1e-5) return format("%.2g%%", 100.0 * error);
    return format("%.1e", error);
}

// The tracer knobs of a run, without the case-specific grid and smoothing.
std::string tracerKey(const RunSettings& s) {
    std::string key = curveLabel(s) + (s.stepPolicy == TracerDesc::StepPolicy::Uniform ? " Δs=" : " Δs_min=") +
                      format("%g", s.stepVoxels);
    if (s.stepPolicy == TracerDesc::StepPolicy::Octree)
        key += format(" ε=%g", s.epsilon) + format(" ε′=%g", s.epsilonPrime) + format(" cap=%g", s.maxStepVoxels);
    return key;
}

std::vector<std::string> casesInOrder(const std::vector<RunRecord>& records) {
    std::vector<std::string> names;
    for (const auto& r : records)
        if (std::find(names.begin(), names.end(), r.measurement.caseName) == names.end())
            names.push_back(r.measurement.caseName);
    return names;
}

// The runs of case `name` by `method`: the tracer's tables and fronts are the
// eikonal runs', image space has its own (its truth may differ).
std::vector<const RunRecord*> ofCase(const std::vector<RunRecord>& records, const std::string& name,
                                     RenderDesc::Method method = RenderDesc::Method::Eikonal) {
    std::vector<const RunRecord*> out;
    for (const auto& r : records)
        if (r.measurement.caseName == name && r.settings.method == method) out.push_back(&r);
    return out;
}

const RunRecord* cheapestWithin(const std::vector<const RunRecord*>& runs, double budget) {
    const RunRecord* best = nullptr;
    for (const RunRecord* r : runs)
        if (r->measurement.samples > 0 && r->measurement.error <= budget &&
            (!best || r->runtimeSeconds < best->runtimeSeconds))
            best = r;
    return best;
}

std::string cheapestCell(const std::vector<const RunRecord*>& runs, double budget) {
    const RunRecord* r = cheapestWithin(runs, budget);
    if (!r) return "not reached";
    return settingsLabel(*r) + ": " + format("%.3g s", r->runtimeSeconds) + ", " + percent(r->measurement.error);
}

// The error the case converges to in the step: RK4 with uniform steps at the
// finest step on the base grid.
const RunRecord* floorRun(const std::vector<const RunRecord*>& runs) {
    const RunRecord* floor = nullptr;
    for (const RunRecord* r : runs)
        if (r->settings.sweep == "step" && r->settings.integrator == TracerDesc::Integrator::Rk4 &&
            r->settings.stepPolicy == TracerDesc::StepPolicy::Uniform &&
            (!floor || r->settings.stepVoxels < floor->settings.stepVoxels))
            floor = r;
    return floor;
}

// Each image-space run (render.method "image_space") beside the cheapest
// eikonal run of its case that is as accurate; nothing without any.
void writeImageSpaceSection(std::ostringstream& md, const std::vector<RunRecord>& records) {
    using M = RenderDesc::Method;
    std::vector<std::string> withImageSpace;
    for (const auto& name : casesInOrder(records))
        if (!ofCase(records, name, M::ImageSpace).empty()) withImageSpace.push_back(name);
    if (withImageSpace.empty()) return;
    md << "\n### Image space beside the eikonal tracer\n\n"
       << "Image space (`render.method: \"image_space\"`) over the size of what it rasterizes; its run time is one "
          "frame of the stages the measure needs (the caustic maps, or the view), the faster of two after a first "
          "frame. Its error is taken against the truth of what it draws (below the table), which may differ from "
          "the eikonal rows'; so it has no place in the tables above or the Pareto fronts below.\n\n"
       << "| case | image-space run | run time (s) | error | the eikonal tracer's cheapest run as accurate |\n"
       << "| --- | --- | --- | --- | --- |\n";
    for (const auto& name : withImageSpace) {
        const auto eikonal = ofCase(records, name, M::Eikonal);
        for (const RunRecord* r : ofCase(records, name, M::ImageSpace))
            md << "| " << name << " | " << settingsLabel(*r) << " | " << format("%.3g", r->runtimeSeconds) << " | "
               << percent(r->measurement.error) << " | " << cheapestCell(eikonal, r->measurement.error) << " |\n";
    }
    md << "\n";
    for (const auto& name : withImageSpace)
        md << "- " << name << ": " << ofCase(records, name, M::ImageSpace).front()->measurement.metric << ".\n";
}

}  // namespace

std::string curveLabel(const RunSettings& settings) {
    if (settings.method == RenderDesc::Method::ImageSpace) return methodName(settings.method);
    return std::string(integratorName(settings.integrator)) + " " + stepPolicyName(settings.stepPolicy);
}

std::string settingsLabel(const RunRecord& record) {
    const RunSettings& s = record.settings;
    if (s.method == RenderDesc::Method::ImageSpace) {
        const std::string pixels = std::to_string(s.imagePixels);
        return curveLabel(s) + (s.causticMapTexels > 0 ? " caustic map " + std::to_string(s.causticMapTexels) + "²"
                                                       : " view " + pixels + "x" + pixels);
    }
    std::string label = tracerKey(s) + " " + record.grid;
    if (s.smoothingVoxels > 0.0) label += format(" w=%g", s.smoothingVoxels);
    if (s.sweep == "photons") label += " " + std::to_string(record.photons) + " photons";
    if (s.estimator == TracerDesc::Estimator::Wavefront) label += format(" wavefront split=%g", s.splitTexels);
    return label;
}

std::vector<OrderEstimate> estimateOrders(const std::vector<RunRecord>& records, const std::string& caseName,
                                          bool selfConvergence) {
    const auto runs = ofCase(records, caseName);
    const RunRecord* floor = floorRun(runs);
    const double floorError = floor ? floor->measurement.error : 0.0;
    std::vector<OrderEstimate> estimates;
    for (auto integrator : {TracerDesc::Integrator::Euler, TracerDesc::Integrator::Leapfrog, TracerDesc::Integrator::Rk4}) {
        OrderEstimate estimate;
        estimate.integrator = integratorName(integrator);
        std::vector<const RunRecord*> sweep;
        for (const RunRecord* r : runs)
            if (r->settings.sweep == "step" && r->settings.integrator == integrator &&
                r->settings.stepPolicy == TracerDesc::StepPolicy::Uniform && r->measurement.samples > 0)
                sweep.push_back(r);
        if (sweep.size() < 2) continue;
        std::sort(sweep.begin(), sweep.end(),
                  [](auto* a, auto* b) { return a->settings.stepVoxels > b->settings.stepVoxels; });
        // Against the finest RK4 run where positions were recorded (the step's own
        // error); otherwise against the truth, floor included.
        if (selfConvergence) std::erase_if(sweep, [](auto* r) { return r->stepErrorVoxels < 0.0; });
        if (sweep.size() < 2) continue;
        estimate.selfConvergence = selfConvergence;
        double floorValue = floorError;
        if (selfConvergence) {
            floorValue = std::numeric_limits<double>::infinity();
            for (const RunRecord* r : runs)
                if (r->settings.integrator == TracerDesc::Integrator::Rk4 && r->stepErrorVoxels >= 0.0)
                    floorValue = std::min(floorValue, r->stepErrorVoxels);
        }
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        int n = 0;
        for (std::size_t i = 0; i < sweep.size(); ++i) {
            const double step = sweep[i]->settings.stepVoxels;
            const double error = selfConvergence ? sweep[i]->stepErrorVoxels : sweep[i]->measurement.error;
            estimate.steps.push_back(step);
            estimate.errors.push_back(error);
            if (i > 0) estimate.localOrders.push_back(std::log(estimate.errors[i - 1] / error) /
                                                      std::log(estimate.steps[i - 1] / step));
            if (error > 3.0 * floorValue && error > 0.0) {
                const double x = std::log(step), y = std::log(error);
                sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
            }
        }
        estimate.fittedOrder = n >= 2 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : std::numeric_limits<double>::quiet_NaN();
        estimates.push_back(estimate);
    }
    return estimates;
}

void writeCsv(const std::filesystem::path& file, const std::vector<RunRecord>& records) {
    std::ostringstream out;
    out << "case,integrator,step_policy,sweep,step_voxels,max_step_voxels,epsilon,epsilon_prime,smoothing_voxels,"
           "grid,photons,steps,runtime_s,error,error_voxels,error_metric,samples,step_error_voxels,invariant_max,"
           "invariant_mean,energy_balance,estimator,split_texels,method,caustic_map_texels,image_pixels\n";
    for (const RunRecord& r : records) {
        const RunSettings& s = r.settings;
        // Image space has none of the tracer's knobs and statistics: their cells stay empty.
        const auto tracer = [&](std::string cell) {
            return s.method == RenderDesc::Method::Eikonal ? cell : std::string();
        };
        const std::vector<std::string> cells = {
            r.measurement.caseName, tracer(integratorName(s.integrator)), tracer(stepPolicyName(s.stepPolicy)),
            s.sweep, tracer(format("%g", s.stepVoxels)), tracer(format("%g", s.maxStepVoxels)),
            tracer(format("%g", s.epsilon)), tracer(format("%g", s.epsilonPrime)), tracer(format("%g", s.smoothingVoxels)),
            r.grid, tracer(std::to_string(r.photons)), tracer(std::to_string(r.stats.steps)),
            format("%.6g", r.runtimeSeconds), format("%.6g", r.measurement.error),
            format("%.6g", r.measurement.errorVoxels), "\"" + r.measurement.metric + "\"",
            std::to_string(r.measurement.samples), format("%.6g", r.stepErrorVoxels),
            tracer(format("%.6g", r.stats.maxInvariantError)), tracer(format("%.6g", r.stats.meanInvariantError)),
            tracer(format("%.3g", r.stats.balanceError())),
            tracer(s.estimator == TracerDesc::Estimator::Wavefront ? "wavefront" : "photons"),
            tracer(format("%g", s.splitTexels)), methodName(s.method), std::to_string(s.causticMapTexels),
            std::to_string(s.imagePixels)};
        for (std::size_t c = 0; c < cells.size(); ++c) out << (c ? "," : "") << cells[c];
        out << "\n";
    }
    io::writeFileAtomically(file, out.str());
}

void writeMarkdown(const std::filesystem::path& file, const std::vector<RunRecord>& records, const ReportContext& context) {
    std::ostringstream md;
    const auto cases = casesInOrder(records);
    md << "Generated by `" << context.command << "` on " << context.renderer << ": " << records.size()
       << " measurements in " << format("%.0f", context.wallSeconds) << " s wall time. Run times are the photon pass, the "
       << "faster of two relights after a first frame (wall clock with glFinish; shader compilation, upload and the per-frame prepare "
       << "and step-structure stages excluded). Errors are dimensionless; lengths also in voxels of the run's grid.\n\n";
    if (!context.plotPath.empty())
        md << "![Error against run time, log–log, per case; one colour per integrator and step policy](" << context.plotPath
           << ")\n\n";

    md << "### Cheapest setting for an error budget\n\n"
       << "| case | error measure | floor (RK4, finest uniform step) | cheapest ≤ 1% | cheapest ≤ 0.1% |\n"
       << "| --- | --- | --- | --- | --- |\n";
    for (const auto& name : cases) {
        const auto runs = ofCase(records, name);
        if (runs.empty()) continue;
        const RunRecord* floor = floorRun(runs);
        std::string floorCell = "—";
        if (floor) {
            floorCell = percent(floor->measurement.error);
            if (floor->measurement.errorVoxels >= 0.0) floorCell += format(" (%.2g voxel)", floor->measurement.errorVoxels);
        }
        md << "| " << name << " | " << runs.front()->measurement.metric << " | " << floorCell << " | "
           << cheapestCell(runs, 0.01) << " | " << cheapestCell(runs, 0.001) << " |\n";
    }

    // One setting for all cases: the cheapest (total run time) that meets the
    // budget in every case where some setting does.
    md << "\nOne setting for every case (the least total run time among the settings run on all of them, "
          "meeting the budget wherever any setting does):\n\n";
    for (double budget : {0.01, 0.001}) {
        std::map<std::string, std::map<std::string, const RunRecord*>> byLabel;  // settings (no grid) → case → run
        std::set<std::string> reachable;
        for (const auto& r : records) {
            if (r.settings.sweep != "step" || r.measurement.samples == 0) continue;
            byLabel[tracerKey(r.settings)][r.measurement.caseName] = &r;
            if (r.measurement.error <= budget) reachable.insert(r.measurement.caseName);
        }
        std::string best;
        double bestTime = std::numeric_limits<double>::infinity();
        for (const auto& [label, perCase] : byLabel) {
            double total = 0.0;
            bool ok = !reachable.empty();
            for (const auto& name : reachable) {
                const auto it = perCase.find(name);
                if (it == perCase.end() || it->second->measurement.error > budget) ok = false;
                else total += it->second->runtimeSeconds;
            }
            if (ok && total < bestTime) bestTime = total, best = label;
        }
        md << "- " << percent(budget) << ": " << (best.empty() ? "no single setting" : "`" + best + "`") << " ("
           << reachable.size() << " of " << cases.size() << " cases reach it at all)\n";
    }

    auto orderTable = [&](bool selfConvergence) {
        md << "| case | Euler | leapfrog | RK4 |\n| --- | --- | --- | --- |\n";
        for (const auto& name : cases) {
            const auto estimates = estimateOrders(records, name, selfConvergence);
            if (estimates.empty()) continue;
            md << "| " << name;
            for (const auto& e : estimates) {
                md << " | **" << (std::isnan(e.fittedOrder) ? std::string("at floor") : format("%.2f", e.fittedOrder))
                   << "** (";
                for (std::size_t i = 0; i < e.localOrders.size(); ++i)
                    md << (i ? ", " : "") << format("%.1f", e.localOrders[i]);
                md << "); " << format("%.2g", e.errors.front()) << " at Δs = " << format("%g", e.steps.front()) << " → "
                   << format("%.2g", e.errors.back()) << " at " << format("%g", e.steps.back());
            }
            md << " |\n";
        }
    };
    md << "\n### Convergence order of the step (uniform steps, against the finest RK4 run)\n\n"
       << "The step's own error: each recorded photon's position at a fixed arc length (the vertex s/Δs, no "
          "interpolation), its distance across the path of the same photon in the finest-step RK4 run on the same "
          "grid (along the path the arc-length label of leapfrog drifts at first order, since it steps dσ = Δs/n "
          "with n from the step's start), RMS in voxels. "
          "Bold: fitted slope of log error against log Δs over the runs above 3× the smallest RK4 value (float32 "
          "round-off); in brackets the local order of each halving, log2(e(Δs)/e(Δs/2)), from the coarsest step; "
          "then the error at the coarsest and finest step. Expected: Euler 1, leapfrog 2, RK4 4.\n\n";
    orderTable(true);
    md << "\n### Against the truth: where the floor takes over\n\n"
       << "The same sweeps measured by each case's error against its closed form or the reference tracer "
          "(dimensionless). The error falls with the step until it meets the floor set by the grid and the "
          "smoothing (next table); local orders near 0 mark the floor, and a local order far above the "
          "integrator's is a coarse-step error cancelling part of the floor's.\n\n";
    orderTable(false);

    md << "\n### The floor: grid resolution and smoothing width (RK4, Δs = 0.25 voxel)\n\n"
       << "| case | grid: error | smoothing width (voxels): error |\n| --- | --- | --- |\n";
    for (const auto& name : cases) {
        const auto runs = ofCase(records, name);
        std::vector<const RunRecord*> grid, smoothing;
        for (const RunRecord* r : runs) {
            const bool fine = r->settings.integrator == TracerDesc::Integrator::Rk4 &&
                              r->settings.stepPolicy == TracerDesc::StepPolicy::Uniform && r->settings.stepVoxels == 0.25;
            if (!fine) continue;
            if (r->settings.sweep == "grid" || (r->settings.sweep == "step")) grid.push_back(r);
            if (r->settings.sweep == "smoothing" || (r->settings.sweep == "step" && r->settings.smoothingVoxels > 0))
                smoothing.push_back(r);
        }
        if (grid.size() < 2 && smoothing.size() < 2) continue;
        std::sort(grid.begin(), grid.end(), [](auto* a, auto* b) { return a->settings.gridScale < b->settings.gridScale; });
        std::sort(smoothing.begin(), smoothing.end(),
                  [](auto* a, auto* b) { return a->settings.smoothingVoxels < b->settings.smoothingVoxels; });
        md << "| " << name << " | ";
        for (std::size_t i = 0; i < grid.size(); ++i) md << (i ? ", " : "") << grid[i]->grid << ": " << percent(grid[i]->measurement.error);
        md << " | ";
        if (smoothing.size() >= 2)
            for (std::size_t i = 0; i < smoothing.size(); ++i)
                md << (i ? ", " : "") << format("%g", smoothing[i]->settings.smoothingVoxels) << ": "
                   << percent(smoothing[i]->measurement.error);
        else
            md << "—";
        md << " |\n";
    }

    writeImageSpaceSection(md, records);

    md << "\n### Per case: the Pareto front (no other run is both faster and more accurate)\n";
    for (const auto& name : cases) {
        auto runs = ofCase(records, name);
        std::sort(runs.begin(), runs.end(), [](auto* a, auto* b) { return a->runtimeSeconds < b->runtimeSeconds; });
        if (runs.empty()) continue;
        md << "\n**" << name << "** — " << runs.front()->measurement.metric << ".\n\n"
           << "| setting | run time (s) | error | error (voxels) | max invariant error | energy balance |\n"
           << "| --- | --- | --- | --- | --- | --- |\n";
        double bestSoFar = std::numeric_limits<double>::infinity();
        for (const RunRecord* r : runs) {
            if (r->measurement.samples == 0 || r->measurement.error >= bestSoFar) continue;
            bestSoFar = r->measurement.error;
            md << "| " << settingsLabel(*r) << " | " << format("%.3g", r->runtimeSeconds) << " | "
               << percent(r->measurement.error) << " | "
               << (r->measurement.errorVoxels >= 0.0 ? format("%.3g", r->measurement.errorVoxels) : std::string("—"))
               << " | " << format("%.2g", r->stats.maxInvariantError) << " | " << format("%.1g", r->stats.balanceError())
               << " |\n";
        }
    }
    io::writeFileAtomically(file, md.str());
}

}  // namespace eikon::accuracy
