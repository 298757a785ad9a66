#include "verify/converge/ConvergeStudy.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "verify/converge/StudyFields.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace eikon::converge {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Rendered {
    double seconds = 0.0;
    std::vector<float> maps, image, fluence;
    glm::ivec3 grid{0};
};

Rendered render(Scene scene, const sim::SceneFields& fields) {
    scene.render.writeHdr = true;  // the image is compared in linear radiance
    render::FrameRenderer renderer(scene, fields.fields());
    const render::FrameResult result = renderer.render(fields.fields());
    Rendered rendered;
    for (const auto& stage : result.stages) rendered.seconds += stage.milliseconds / 1000.0;
    for (unsigned r = 0; r < renderer.receivers().count(); ++r) {
        const std::vector<float> map = renderer.receivers().download(r);
        rendered.maps.insert(rendered.maps.end(), map.begin(), map.end());
    }
    for (std::size_t i = 0; i + 3 < result.hdr.size(); i += 4)
        rendered.image.insert(rendered.image.end(), result.hdr.begin() + static_cast<std::ptrdiff_t>(i),
                              result.hdr.begin() + static_cast<std::ptrdiff_t>(i + 3));
    if (renderer.photonStage() && renderer.photonStage()->storesFluence())
        rendered.fluence = renderer.photonStage()->downloadFluence();
    rendered.grid = scene.grid.resolution;
    return rendered;
}

std::optional<double> relativeL1(const std::vector<float>& values, const std::vector<float>& reference) {
    if (values.size() != reference.size() || reference.empty()) return std::nullopt;
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        difference += std::abs(static_cast<double>(values[i]) - reference[i]);
        norm += std::abs(static_cast<double>(reference[i]));
    }
    return norm > 0.0 ? std::optional(difference / norm) : std::nullopt;
}

// How the run time grows with each knob, t ∝ f^a, from the ladder's rungs
// rendered so far (the finest of each knob against the scene's own), a in
// [0, 1.5]; 1 where a knob has no rung finer than the scene's.
Refinement costExponents(const std::vector<Rendered>& rendered, const std::vector<Rung>& rungs, double sceneSeconds) {
    Refinement exponents{1.0, 1.0, 1.0};
    for (double Refinement::*knob : {&Refinement::photons, &Refinement::step, &Refinement::grid}) {
        double finest = 1.0, seconds = sceneSeconds;
        for (std::size_t i = 0; i < rungs.size(); ++i) {
            const Refinement& r = rungs[i].refinement;
            const bool alone = (r.photons == 1.0) + (r.step == 1.0) + (r.grid == 1.0) == 2;
            if (alone && r.*knob > finest && rendered[i].seconds > 0.0) finest = r.*knob, seconds = rendered[i].seconds;
        }
        if (finest > 1.0)
            exponents.*knob = std::clamp(std::log(seconds / sceneSeconds) / std::log(finest), 0.0, 1.5);
    }
    return exponents;
}

double predictedSeconds(const Refinement& refinement, const Refinement& exponents, double sceneSeconds) {
    return sceneSeconds * std::pow(refinement.photons, exponents.photons) * std::pow(refinement.step, exponents.step) *
           std::pow(refinement.grid, exponents.grid);
}

// The default reference: up to 16× the photons, a quarter of the step and
// 1.5× the grid, made coarser while it is predicted to end past the budget,
// but never below twice the ladder's finest rung in a knob.
Refinement referenceFor(double secondsLeft, const Refinement& exponents, double sceneSeconds, bool gridKnob) {
    Refinement reference = kDefaultReference;
    if (!gridKnob) reference.grid = 1.0;
    const auto fits = [&] { return predictedSeconds(reference, exponents, sceneSeconds) * 1.2 <= secondsLeft; };
    while (!fits() && reference.photons > 8.0) reference.photons /= 2.0;
    return reference;
}

// The reference `rung` describes, as the scene loader makes it. One asked
// for must be as fine as it says: the wavefront's thresholds held at their
// least value would make it coarser.
Rung loadedReference(Rung rung, const Scene& scene, const StudyOptions& options) {
    const double finest = finestWavefrontRefinement(scene);
    if (options.reference && scene.tracer.estimator == TracerDesc::Estimator::Wavefront &&
        options.reference->photons > finest)
        throw InputError("--reference",
                         "photons=F with F at most " + formatNumber(finest) +
                             " for this scene (its wavefront split and tear thresholds, refined further, stay at " +
                             formatNumber(kLeastWavefrontThreshold) + ")",
                         "photons=" + formatNumber(options.reference->photons));
    rung.scene = options.loadedScene(rung);
    return rung;
}

}  // namespace

double Measured::worst() const {
    double worst = -1.0;
    for (const auto& error : {receivers, image, fluence})
        if (error) worst = std::max(worst, *error);
    return worst < 0.0 ? std::numeric_limits<double>::infinity() : worst;
}

Outputs outputsOf(const Scene& scene) {
    Outputs outputs;
    outputs.receivers = !scene.receivers.empty();
    outputs.image = true;
    outputs.fluence = scene.tracer.storeFluence || sim::SceneFields(scene).fields().hasScattering();
    return outputs;
}

Study runStudy(const Scene& scene, const StudyOptions& options) {
    const auto start = Clock::now();
    const auto deadline = [&](double share) {
        const double seconds = share * options.budgetSeconds;
        if (seconds > 1e9) return Clock::time_point::max();  // beyond the clock's range: never reached
        return start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    };
    Study study;
    study.budgetSeconds = options.budgetSeconds;
    study.byWavefront = scene.tracer.estimator == TracerDesc::Estimator::Wavefront;
    study.integrator = scene.tracer.integrator;

    Ladder ladder = buildLadder(scene, options.reference.value_or(kDefaultReference));
    // The finest reference the study may render, checked before anything
    // renders (the default one only grows coarser).
    ladder.reference = loadedReference(ladder.reference, scene, options);
    StudyFields fields(scene, options.frame, options.budgetSeconds);
    fields.requireSimulationFits({&scene, &ladder.reference.scene});

    render(scene, fields.at(scene, deadline(0.5)));  // compiles the programs and warms the caches; not timed
    // A reference asked for renders first: one the machine cannot hold is
    // refused before the rungs take their time. Then the rungs, cheapest
    // first, within half the budget; then the default reference, as fine as
    // the time left allows, its cost predicted from how the rungs' grew;
    // then every rung against the reference.
    std::optional<Rendered> reference;
    if (options.reference) reference = render(ladder.reference.scene, fields.at(ladder.reference.scene, deadline(1.0)));
    study.leftOut = ladder.leftOut;
    std::vector<std::size_t> order(ladder.rungs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return ladder.rungs[a].refinement.predictedCost() < ladder.rungs[b].refinement.predictedCost();
    });
    std::vector<Rendered> rendered(ladder.rungs.size());
    std::vector<bool> done(ladder.rungs.size(), false);
    double sceneSeconds = 0.0;
    for (std::size_t i : order) {
        const Rung& rung = ladder.rungs[i];
        const double predicted = rung.refinement.predictedCost() * std::max(sceneSeconds, 1e-3) * 1.5 +
                                 fields.secondsToReach(rung.scene);
        if (rung.knob != "scene" && secondsSince(start) + predicted > 0.5 * options.budgetSeconds) {
            study.leftOut.push_back(rung.knob + " at " + rung.setting + ": predicted to end past the budget");
            continue;
        }
        rendered[i] = render(rung.scene, fields.at(rung.scene, deadline(0.5)));
        done[i] = true;
        if (rung.knob == "scene") sceneSeconds = rendered[i].seconds;
    }
    if (!options.reference) {
        const Refinement exponents = costExponents(rendered, ladder.rungs, sceneSeconds);
        const double left = options.budgetSeconds - secondsSince(start);
        const Refinement finest = referenceFor(left, exponents, sceneSeconds, !scene.sim);
        const double predicted = predictedSeconds(finest, exponents, sceneSeconds);
        if (predicted > left)
            study.leftOut.push_back("the budget: the coarsest reference finer than every rung was predicted to take " +
                                    std::to_string(static_cast<int>(std::ceil(predicted))) + " s of the " +
                                    std::to_string(static_cast<int>(left)) + " s left");
        ladder.reference = loadedReference(referenceRung(scene, finest), scene, options);
    }
    if (!reference) reference = render(ladder.reference.scene, fields.at(ladder.reference.scene, deadline(1.0)));
    study.reference = {ladder.reference, reference->seconds, {}, {}, {}};
    for (std::size_t i = 0; i < ladder.rungs.size(); ++i) {
        if (!done[i]) continue;
        Measured measured{ladder.rungs[i], rendered[i].seconds, {}, {}, {}};
        if (options.outputs.receivers) measured.receivers = relativeL1(rendered[i].maps, reference->maps);
        if (options.outputs.image) measured.image = relativeL1(rendered[i].image, reference->image);
        if (options.outputs.fluence && rendered[i].grid == reference->grid)
            measured.fluence = relativeL1(rendered[i].fluence, reference->fluence);
        if (options.onRung) options.onRung(measured);
        study.rungs.push_back(std::move(measured));
    }
    study.wallSeconds = secondsSince(start);
    return study;
}

}  // namespace eikon::converge
