// The fields of the frame `eikon converge` studies, made once per grid and
// kept for the rungs that share it: the photons and the step change the
// light, not the fields. A scene whose frames depend on each other (a fluid
// solver, moving objects) reaches frame K only by simulating frames 1 … K,
// on every grid it is rendered on; the study times the first frame before
// it starts, refuses a budget that cannot hold the simulation, and stops
// with the figure where the simulation runs past its deadline all the same.
#pragma once

#include "bridge/scene/Scene.h"
#include "sim/SceneFields.h"

#include <chrono>
#include <memory>
#include <vector>

namespace eikon::converge {

class StudyFields {
public:
    using Clock = std::chrono::steady_clock;

    // Makes the fields of `scene`'s own grid; where reaching `frame` needs
    // a simulation, simulates its first frame and times it.
    StudyFields(const Scene& scene, int frame, double budgetSeconds);
    ~StudyFields();

    // Seconds that reaching the frame on `scene`'s grid is predicted to
    // take: the first frame's time × the frames left × the ratio of cells;
    // 0 where the fields are at hand or need no simulation.
    double secondsToReach(const Scene& scene) const;
    // InputError (--budget-s) where simulating to the frame on each of
    // these grids is predicted to take more than half the budget.
    void requireSimulationFits(const std::vector<const Scene*>& grids) const;
    // The fields of `scene`'s grid at the frame. Simulating there: an
    // InputError (--budget-s) with the measured figure as soon as it would
    // end past `deadline`.
    const sim::SceneFields& at(const Scene& scene, Clock::time_point deadline);

private:
    struct Made;  // one grid's fields, and how far they have been simulated
    std::unique_ptr<Made> make(const Scene& scene) const;
    void advance(Made& made, int frame, Clock::time_point deadline) const;
    [[noreturn]] void refuse(double secondsPerFrame, int framesMeasured, double secondsNeeded) const;

    int frame_;
    double budgetSeconds_;
    long long ownCells_;
    double secondsPerFrame_ = 0.0;  // the first simulated frame on the scene's own grid; 0: none needed
    std::unique_ptr<Made> own_;    // the scene's own grid, kept
    std::unique_ptr<Made> other_;  // the last other grid asked for
};

}  // namespace eikon::converge
