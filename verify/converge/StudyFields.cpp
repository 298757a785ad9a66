#include "verify/converge/StudyFields.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

namespace eikon::converge {

namespace {

long long cellsOf(const Scene& scene) {
    const glm::ivec3 r = scene.grid.resolution;
    return static_cast<long long>(r.x) * r.y * r.z;
}

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof text, value >= 100.0 ? "%.0f" : "%.3g", value);
    return text;
}

}  // namespace

struct StudyFields::Made {
    explicit Made(const Scene& scene) : grid(scene.grid.resolution), fields(scene) {}
    glm::ivec3 grid;
    sim::SceneFields fields;
    int reached = 0;         // the frame the fields are at
    double simulated = 0.0;  // seconds spent simulating frames 1 … reached
};

std::unique_ptr<StudyFields::Made> StudyFields::make(const Scene& scene) const {
    auto made = std::make_unique<Made>(scene);
    if (made->fields.framesAreIndependent()) {
        made->fields.seekFrame(frame_);
        made->reached = frame_;
    }
    return made;
}

void StudyFields::advance(Made& made, int frame, Clock::time_point deadline) const {
    while (made.reached < frame) {
        const auto start = Clock::now();
        made.fields.advanceFrame();
        ++made.reached;
        made.simulated += std::chrono::duration<double>(Clock::now() - start).count();
        if (Clock::now() > deadline && made.reached < frame)
            refuse(made.simulated / made.reached, made.reached, made.simulated / made.reached * frame_);
    }
}

StudyFields::StudyFields(const Scene& scene, int frame, double budgetSeconds)
    : frame_(frame), budgetSeconds_(budgetSeconds), ownCells_(cellsOf(scene)), own_(make(scene)) {
    advance(*own_, std::min(frame_, 1), Clock::time_point::max());
    secondsPerFrame_ = own_->simulated;
}

StudyFields::~StudyFields() = default;

double StudyFields::secondsToReach(const Scene& scene) const {
    int reached = 0;
    for (const Made* made : {own_.get(), other_.get()})
        if (made && made->grid == scene.grid.resolution) reached = made->reached;
    return secondsPerFrame_ * (frame_ - reached) * static_cast<double>(cellsOf(scene)) / static_cast<double>(ownCells_);
}

void StudyFields::requireSimulationFits(const std::vector<const Scene*>& grids) const {
    std::set<std::tuple<int, int, int>> seen;
    double needed = 0.0;
    for (const Scene* scene : grids) {
        const glm::ivec3 r = scene->grid.resolution;
        if (seen.insert({r.x, r.y, r.z}).second)
            needed += secondsPerFrame_ * frame_ * static_cast<double>(cellsOf(*scene)) / static_cast<double>(ownCells_);
    }
    if (needed > 0.5 * budgetSeconds_) refuse(secondsPerFrame_, 1, needed);
}

const sim::SceneFields& StudyFields::at(const Scene& scene, Clock::time_point deadline) {
    std::unique_ptr<Made>& slot = scene.grid.resolution == own_->grid ? own_ : other_;
    if (!slot || slot->grid != scene.grid.resolution) slot = make(scene);
    advance(*slot, frame_, deadline);
    return slot->fields;
}

void StudyFields::refuse(double secondsPerFrame, int framesMeasured, double secondsNeeded) const {
    const long long reachable = static_cast<long long>(0.5 * budgetSeconds_ / std::max(secondsPerFrame, 1e-9));
    throw InputError("--budget-s",
                     "at least " + seconds(std::ceil(2.0 * secondsNeeded)) + " s for --frame " +
                         std::to_string(frame_) + ", or a --frame below " + std::to_string(reachable) +
                         " (the scene's frames depend on each other, so the study first simulates frames 1 to " +
                         std::to_string(frame_) + " on each grid it renders: " + seconds(secondsPerFrame) +
                         " s a frame, measured over " +
                         (framesMeasured == 1 ? "frame 1" : "frames 1 to " + std::to_string(framesMeasured)) + ", " +
                         seconds(secondsNeeded) + " s in all, which may take at most half the budget)",
                     seconds(budgetSeconds_) + " s");
}

}  // namespace eikon::converge
