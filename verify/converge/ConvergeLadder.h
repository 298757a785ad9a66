// The settings `eikon converge` renders the user's scene at: one ladder per
// knob the scene has — the photon count (or the wavefront's split
// threshold), the step (photons' and camera rays' together), the grid
// resolution — each varying that knob alone about the scene's own value,
// one ladder refining all of them together, and a reference finer than
// every rung in every knob, rendered with another seed so that its noise is
// independent of theirs.
#pragma once

#include "bridge/scene/Scene.h"

#include <string>
#include <vector>

namespace eikon::converge {

// How much finer than the scene's own setting each knob is: photons (or
// wavefront refinement) multiply, steps divide, the grid's cells per axis
// multiply. 1 is the scene as written.
struct Refinement {
    double photons = 1.0;
    double step = 1.0;
    double grid = 1.0;
    // Run time relative to the scene's own, as the light pass scales:
    // photons × steps per ray (1/step, and the grid's cells per axis).
    double predictedCost() const { return photons * step * grid; }
};

struct Rung {
    std::string knob;     // "photons", "refinement", "step", "grid", "all", or "reference"
    Refinement refinement;
    std::string setting;  // what changed, as scene keys ("render.photons=4194304")
    Scene scene;
};

struct Ladder {
    std::vector<Rung> rungs;  // the scene's own settings first, then by knob
    Rung reference;
    std::vector<std::string> leftOut;  // knobs the scene has no ladder for, and why
};

// The scene's ladders; `reference` as parsed by parseReference (or the
// default: 16× the photons, a quarter of the step, 1.5× the grid).
Ladder buildLadder(const Scene& scene, const Refinement& reference);

// "photons=8,step=4,grid=1.5" (any of the three, each > 0; step = 4 is a
// quarter of the step): an InputError at `where` otherwise.
Refinement parseReference(const std::string& text, const std::string& where);

// The scene refined by `refinement` and the setting it describes.
Rung refinedRung(const Scene& scene, const std::string& knob, const Refinement& refinement);

}  // namespace eikon::converge
