#include "verify/converge/ConvergeLadder.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace eikon::converge {

namespace {

bool byWavefront(const Scene& scene) { return scene.tracer.estimator == TracerDesc::Estimator::Wavefront; }

// The grid knob changes the cells the simulation runs on, which is the
// simulation's own convergence, not the renderer's.
bool hasGridKnob(const Scene& scene) { return !scene.sim.has_value(); }

std::string joined(const std::vector<std::string>& parts) {
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : ", ") + part;
    return text.empty() ? "the scene's own settings" : text;
}

}  // namespace

double finestWavefrontRefinement(const Scene& scene) {
    const TracerDesc::Wavefront& w = scene.tracer.wavefront;
    return std::min({w.splitTexels, w.tearTexels, w.splitVoxels}) / kLeastWavefrontThreshold;
}

Rung refinedRung(const Scene& scene, const std::string& knob, const Refinement& refinement) {
    Rung rung{knob, refinement, "", {}, scene};
    Scene& s = rung.scene;
    std::vector<std::string> changed;
    const auto set = [&](const std::string& key, double value) {
        rung.overrides.push_back(key + "=" + formatNumber(value));
        return formatNumber(value);
    };
    if (refinement.photons != 1.0) {
        if (byWavefront(scene)) {
            const auto refined = [&](double own) { return std::max(kLeastWavefrontThreshold, own / refinement.photons); };
            TracerDesc::Wavefront& w = s.tracer.wavefront;
            w.splitTexels = refined(scene.tracer.wavefront.splitTexels);
            w.tearTexels = refined(scene.tracer.wavefront.tearTexels);
            w.splitVoxels = refined(scene.tracer.wavefront.splitVoxels);
            // The reflected branches' split on their starting power refines
            // with the rest, coarsening at most to 1 (no such split, the
            // most the scene file holds); at 1 it stays off.
            if (scene.tracer.wavefront.reflectionSplit < 1.0)
                w.reflectionSplit = std::min(1.0, scene.tracer.wavefront.reflectionSplit / refinement.photons);
            changed.push_back("tracer.wavefront.split_texels=" + set("tracer.wavefront.split_texels", w.splitTexels) +
                              ", tear_texels=" + set("tracer.wavefront.tear_texels", w.tearTexels) +
                              ", split_voxels=" + set("tracer.wavefront.split_voxels", w.splitVoxels) +
                              ", reflection_split=" +
                              set("tracer.wavefront.reflection_split", w.reflectionSplit));
        } else {
            // Within kFinestReference of a count the scene file could hold: no overflow.
            s.render.photons = std::max(1LL, std::llround(static_cast<double>(scene.render.photons) * refinement.photons));
            changed.push_back("render.photons=" + set("render.photons", static_cast<double>(s.render.photons)));
        }
    }
    if (refinement.step != 1.0) {
        s.tracer.stepVoxels = scene.tracer.stepVoxels / refinement.step;
        s.tracer.maxStepVoxels = std::max(s.tracer.stepVoxels, scene.tracer.maxStepVoxels / refinement.step);
        s.render.stepVoxels = scene.render.stepVoxels / refinement.step;
        set("tracer.max_step_voxels", s.tracer.maxStepVoxels);
        changed.push_back("tracer.step_voxels=" + set("tracer.step_voxels", s.tracer.stepVoxels) +
                          ", render.step_voxels=" + set("render.step_voxels", s.render.stepVoxels));
    }
    if (refinement.grid != 1.0) {
        const glm::dvec3 cells = glm::dvec3(scene.grid.resolution) * refinement.grid;
        s.grid.resolution = glm::max(glm::ivec3(glm::round(cells)), glm::ivec3(4));
        const std::string resolution = "[" + std::to_string(s.grid.resolution.x) + "," +
                                       std::to_string(s.grid.resolution.y) + "," +
                                       std::to_string(s.grid.resolution.z) + "]";
        rung.overrides.push_back("grid.resolution=" + resolution);
        changed.push_back("grid.resolution=" + resolution);
    }
    rung.setting = joined(changed);
    return rung;
}

Rung referenceRung(const Scene& scene, const Refinement& refinement) {
    Refinement finest = refinement;
    if (!hasGridKnob(scene)) finest.grid = 1.0;
    Rung rung = refinedRung(scene, "reference", finest);
    rung.scene.render.seed = scene.render.seed + 7919;  // unsigned: wraps within the seeds a scene may hold
    rung.overrides.push_back("render.seed=" + std::to_string(rung.scene.render.seed));
    return rung;
}

Ladder buildLadder(const Scene& scene, const Refinement& reference) {
    Ladder ladder;
    ladder.rungs.push_back(refinedRung(scene, "scene", {}));
    const std::string lightKnob = byWavefront(scene) ? "refinement" : "photons";
    for (double f : {0.125, 0.25, 0.5, 2.0, 4.0}) ladder.rungs.push_back(refinedRung(scene, lightKnob, {f, 1.0, 1.0}));
    for (double f : {0.25, 0.5, 2.0}) ladder.rungs.push_back(refinedRung(scene, "step", {1.0, f, 1.0}));
    if (hasGridKnob(scene)) {
        for (double f : {0.5, 0.75, 1.25}) ladder.rungs.push_back(refinedRung(scene, "grid", {1.0, 1.0, f}));
    } else {
        ladder.leftOut.push_back("grid: the fluid solver runs on the render grid (its convergence is the solver's)");
    }
    for (int level : {-1, 1, 2}) {
        const double f = std::pow(2.0, level);
        ladder.rungs.push_back(refinedRung(scene, "all", {f, f, hasGridKnob(scene) ? std::pow(1.25, level) : 1.0}));
    }
    ladder.reference = referenceRung(scene, reference);
    const Refinement& finest = ladder.reference.refinement;
    // Every rung stays coarser than the reference in each knob it refines.
    const auto finer = [&](const Rung& rung) {
        const Refinement& r = rung.refinement;
        return (r.photons > 1.0 && r.photons >= finest.photons) || (r.step > 1.0 && r.step >= finest.step) ||
               (r.grid > 1.0 && r.grid >= finest.grid);
    };
    for (const Rung& rung : ladder.rungs)
        if (finer(rung)) ladder.leftOut.push_back(rung.knob + " at " + rung.setting + ": not coarser than the reference");
    ladder.rungs.erase(std::remove_if(ladder.rungs.begin(), ladder.rungs.end(), finer), ladder.rungs.end());
    ladder.leftOut.push_back("smoothing: its width is a model choice, not a discretisation that converges");
    return ladder;
}

Refinement parseReference(const std::string& text, const std::string& where) {
    Refinement refinement;
    std::stringstream items(text);
    for (std::string item; std::getline(items, item, ',');) {
        const auto equals = item.find('=');
        const std::string key = item.substr(0, equals);
        double value = 0.0;
        bool read = false;
        if (equals != std::string::npos) {
            std::stringstream number(item.substr(equals + 1));
            read = static_cast<bool>(number >> value) && number.eof() && std::isfinite(value);
        }
        double Refinement::*knob = key == "photons" ? &Refinement::photons : key == "step" ? &Refinement::step
                                                      : key == "grid" ? &Refinement::grid : nullptr;
        if (!knob || !read)
            throw InputError(where, "photons=F, step=F or grid=F (how many times finer), comma-separated",
                             "\"" + item + "\"");
        if (value < 1.0)
            throw InputError(where, "a reference finer than every rung of the study: " + key +
                                        "=F with F >= 1 (the rung \"scene\", the scene's own settings, has " + key +
                                        "=1)", item);
        if (value > kFinestReference.*knob)
            throw InputError(where, key + "=F with F at most " + formatNumber(kFinestReference.*knob), item);
        refinement.*knob = value;
    }
    if (refinement.predictedCost() == 1.0)
        throw InputError(where, "a reference finer than the scene's own settings (the rung \"scene\") in at least one "
                                "knob", "\"" + text + "\"");
    return refinement;
}

}  // namespace eikon::converge
