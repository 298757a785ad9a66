#include "apps/common/FrameReport.h"

#include "apps/common/LatticeWarning.h"
#include "apps/common/WavefrontCostWarning.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::app {

namespace {

nlohmann::json rgbJson(const Rgb& rgb) { return {rgb.r, rgb.g, rgb.b}; }

nlohmann::json photonsJson(const render::PhotonStats& p) {
    nlohmann::json json = {{"estimator", p.byWavefront ? "wavefront" : "photons"},
            {"power_w",
             {{"emitted", rgbJson(p.emitted)},
              {"absorbed", rgbJson(p.absorbed)},
              {"escaped", rgbJson(p.escaped)},
              {"received", rgbJson(p.received)},
              {"cut_off", rgbJson(p.cutOff)},
              {"blocked", rgbJson(p.blocked)},
              {"reflected", rgbJson(p.reflected)},
              {"roulette_gain", rgbJson(p.rouletteGain)},
              {"unfollowed", rgbJson(p.unfollowed)},
              {"stated", rgbJson(p.stated)}}},
            {"count",
             {{"escaped", p.photonsEscaped},
              {"received", p.photonsReceived},
              {"cut_off", p.photonsCutOff},
              {"blocked", p.photonsBlocked}}},
            {"surface_events", {{"reflected", p.surfaceReflections}, {"transmitted", p.surfaceTransmissions}}},
            {"emitted", p.photons},
            {"energy_balance_error", p.balanceError()},
            {"emission_error", p.emissionError()},
            {"steps", p.steps},
            {"mean_steps_per_photon",
             p.photons > 0 ? static_cast<double>(p.steps) / static_cast<double>(p.photons) : 0.0},
            {"voxel_deposits", p.voxelDeposits},
            {"max_invariant_error", p.maxInvariantError},
            {"mean_invariant_error", p.meanInvariantError},
            {"resumed", {{"photons", p.photonsResumed}, {"dispatches", p.resumeDispatches}}}};
    if (p.byWavefront) {
        json["wavefront"] = {{"patches", p.wavefront.patches},
                             {"splits", p.wavefront.splits},
                             {"patches_at_limit", p.wavefront.atLimit},
                             {"rays", p.wavefront.rays},
                             {"tubes", p.wavefront.tubes},
                             {"start_patches", p.wavefront.startPatches}};
        const std::string warning = describeWavefrontStart(p.wavefront.startPatches);
        if (!warning.empty()) json["wavefront"]["cost_warning"] = warning;
    }
    return json;
}

// Voxels beyond the lattice's depth limit, and the warning they give.
nlohmann::json depthLimitJson(const render::LatticeDepth& depth) {
    nlohmann::json json = {{"optical_depth_per_voxel", depth.limit}, {"voxels_beyond", depth.thickVoxels}};
    if (depth.thickVoxels > 0) {
        json["deepest_beyond"] = depth.deepest;
        json["warning"] = describeDepthLimit(depth);
    }
    return json;
}

// Scattering voxels coarser than the lattice's validated resolution, and the warning they give.
nlohmann::json resolutionJson(const render::LatticeResolution& resolution) {
    nlohmann::json json = {{"validated_reduced_depth", resolution.validated},
                           {"coarse_voxels", resolution.coarseVoxels},
                           {"coarsest_reduced_depth", resolution.coarsest}};
    if (resolution.coarseVoxels > 0) json["warning"] = describeResolution(resolution);
    return json;
}

// The lattice's steps and ledger per channel (render/stages/LatticeScattering.h).
nlohmann::json latticeJson(const render::LatticeStats& lattice) {
    auto perChannel = [&](auto value) {
        nlohmann::json values = nlohmann::json::array();
        for (const render::LatticeChannel& channel : lattice.channels) values.push_back(value(channel));
        return values;
    };
    // A channel the probes never saw converge reports its change as null (JSON has no infinity).
    auto finite = [](double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); };
    return {{"method", "lbm"},
            {"directions", lattice.directions},
            {"warm_start", lattice.warmStart},
            {"iterations", perChannel([](const render::LatticeChannel& c) { return c.iterations; })},
            {"capped", lattice.capped()},
            {"converged", lattice.converged()},
            {"depth_limit", depthLimitJson(lattice.depth)},
            {"voxel_resolution", resolutionJson(lattice.resolution)},
            {"change_per_iteration", perChannel([&](const render::LatticeChannel& c) { return finite(c.change); })},
            {"estimated_remaining", perChannel([&](const render::LatticeChannel& c) { return finite(c.remaining); })},
            {"power_w",
             {{"source", perChannel([](const render::LatticeChannel& c) { return c.source; })},
              {"absorbed", perChannel([](const render::LatticeChannel& c) { return c.absorbed; })},
              {"escaped", perChannel([](const render::LatticeChannel& c) { return c.escapedTotal(); })},
              {"undelivered", perChannel([](const render::LatticeChannel& c) { return c.undelivered(); })}}},
            {"energy_balance_error", lattice.balanceError()}};
}

nlohmann::json outputErrorsJson(const render::OutputErrors& errors) {
    nlohmann::json json = nlohmann::json::object();
    if (errors.receivers) json["receivers"] = *errors.receivers;
    if (errors.image) json["image"] = *errors.image;
    if (errors.fluence) json["fluence"] = *errors.fluence;
    if (errors.deflection) json["deflection"] = *errors.deflection;
    if (errors.opticalPathDifference) json["optical_path_difference"] = *errors.opticalPathDifference;
    if (errors.displacement) json["displacement"] = *errors.displacement;
    return json;
}

nlohmann::json errorEstimateJson(const render::ErrorEstimate& estimate) {
    nlohmann::json noise = estimate.noiseEstimated ? outputErrorsJson(estimate.noise) : nlohmann::json::object();
    noise["method"] = estimate.noiseEstimated ? "two batches (even and odd photons), relative RMS"
                                              : "none (a deterministic wavefront or diagnostic, or a light pass shared among ranks)";
    nlohmann::json discretisation = outputErrorsJson(estimate.discretisation);
    discretisation["method"] = "against the reference march (RK4, steps of reference_step_voxels)";
    discretisation["reference_step_voxels"] = estimate.referenceStepVoxels;
    discretisation["probe_photons"] = estimate.probePhotons;
    return {{"noise", noise}, {"discretisation", discretisation}, {"ms", estimate.milliseconds}};
}

// The fluid solver's frame (sim/fluid/FrameReport.h): its substeps, the
// fastest crossing, and each scalar's budget where the CPU kept one.
nlohmann::json fluidJson(const sim::FluidFrameReport& fluid) {
    nlohmann::json json = {{"substeps", fluid.substeps}, {"cells_per_substep", fluid.cellsPerSubstep}};
    if (!fluid.fastFlow.empty()) json["fast_flow_warning"] = fluid.fastFlow;
    if (fluid.budgetsKept) {
        auto budget = [](const sim::ScalarBudget& b, const char* unit) {
            return nlohmann::json{{"unit", unit}, {"sources", b.sources}, {"advection", b.advection}, {"total", b.total}};
        };
        json["budgets"] = {{"heat", budget(fluid.heat, "K m3")},
                           {"concentration", budget(fluid.concentration, "m3")},
                           {"dye", budget(fluid.dye, "m3")}};
    }
    return json;
}

}  // namespace

double renderMilliseconds(const render::FrameResult& result) {
    double ms = 0.0;
    for (const auto& stage : result.stages) ms += stage.milliseconds;
    return ms;
}

const char* distributionName(Distribution distribution) {
    switch (distribution) {
        case Distribution::None: return "none";
        case Distribution::Photons: return "photons";
        case Distribution::Frames: return "frames";
    }
    return "none";
}

std::string frameReportJson(int frame, const ProducedFrame& produced, bool simulated,
                            const render::FrameResult& result, const LoopTiming& timing, bool pipelined,
                            Distribution distribution, int ranks) {
    nlohmann::json stages = nlohmann::json::array();
    if (simulated) {
        stages.push_back({{"name", "simulate"}, {"ran", produced.simulated}, {"ms", produced.simulateMs}});
        stages.push_back({{"name", "write_fields"}, {"ran", true}, {"ms", produced.writeFieldsMs}});
    }
    for (const auto& stage : result.stages) {
        stages.push_back({{"name", stage.name},
                          {"ran", stage.ran},
                          {"ms", stage.milliseconds},
                          {"device", render::stageDeviceName(stage.device)}});
        if (!stage.skippedBecause.empty()) stages.back()["reason"] = stage.skippedBecause;
        if (!stage.deviceReason.empty()) stages.back()["device_reason"] = stage.deviceReason;
    }
    nlohmann::json report{{"frame", frame},
                          {"time_s", produced.time},
                          {"stages", stages},
                          {"host_bytes_copied", result.copied.host},
                          {"gpu_bytes_copied", result.copied.gpu},
                          {"loop",
                           {{"pipelined", pipelined},
                            {"frame_ms", timing.frameMs},
                            {"render_ms", timing.renderMs},
                            {"produce_next_ms", timing.produceNextMs}}}};
    const bool tracesPhotons = std::any_of(result.stages.begin(), result.stages.end(),
                                           [](const render::StageReport& stage) { return stage.name == "photons"; });
    if (tracesPhotons) report["photons"] = photonsJson(result.photons);
    const bool diffuses = std::any_of(result.stages.begin(), result.stages.end(), [](const render::StageReport& stage) {
        return stage.name == "multiple_scattering" && stage.ran;
    });
    if (diffuses && result.lattice) report["multiple_scattering"] = latticeJson(*result.lattice);
    if (result.errorEstimate) report["error_estimate"] = errorEstimateJson(*result.errorEstimate);
    // The estimate sees the light pass's errors, not the lattice's resolution: said beside it.
    if (result.errorEstimate && result.lattice && result.lattice->resolution.coarseVoxels > 0)
        report["error_estimate"]["multiple_scattering"] = resolutionJson(result.lattice->resolution);
    if (result.imageSpace)
        report["image_space"] = {{"frames_averaged", result.imageSpace->framesAveraged},
                                 {"dropped", result.imageSpace->dropped}};
    if (result.diagnosticLost) report["diagnostic"] = {{"lost", *result.diagnosticLost}};
    if (distribution != Distribution::None)
        report["distribution"] = {{"mode", distributionName(distribution)}, {"ranks", ranks}};
    if (simulated) {
        nlohmann::json phases = nlohmann::json::array();
        for (const auto& phase : produced.phases)
            phases.push_back({{"phase", phase.phase},
                              {"ms", phase.milliseconds},
                              {"iterations", phase.iterations},
                              {"residual", phase.residual}});
        report["simulation"] = phases;
        if (produced.fluid && produced.simulated) report["fluid"] = fluidJson(*produced.fluid);
        if (!produced.simulationDevice.empty()) report["simulation_device"] = produced.simulationDevice;
    }
    // Everything that crossed between host and GPU memory for this frame:
    // uploads, the fields written into the mapped ring, what the solver moved.
    report["bus_bytes"] = result.copied.host + produced.busBytes;
    return report.dump();
}

}  // namespace eikon::app
