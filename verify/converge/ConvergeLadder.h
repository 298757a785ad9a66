// The settings `eikon converge` renders the user's scene at: one ladder per
// knob the scene has — the photon count (or the wavefront's split
// thresholds, reflection_split among them), the step (photons' and camera
// rays' together), the grid resolution — each varying that knob alone
// about the scene's own value, one ladder refining all of them together,
// and a reference finer than every rung in every knob, rendered with
// another seed so that its noise is independent of theirs.
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

// The most --reference may refine each knob: the photons (or the
// wavefront's refinement) 1024×, the step 64×, the grid's cells per axis
// 4× — one reference frame 1024, 64 or 64–256 times the scene's own.
inline constexpr Refinement kFinestReference{1024.0, 64.0, 4.0};

struct Rung {
    std::string knob;     // "photons", "refinement", "step", "grid", "all", or "reference"
    Refinement refinement;
    std::string setting;  // what changed, as scene keys ("render.photons=4194304")
    std::vector<std::string> overrides;  // the same as --set assignments ("render.photons=4194304")
    Scene scene;
};

struct Ladder {
    std::vector<Rung> rungs;  // the scene's own settings first, then by knob
    Rung reference;
    std::vector<std::string> leftOut;  // knobs the scene has no ladder for, and why
};

// The default reference: 16× the photons, a quarter of the step, 1.5× the grid.
inline constexpr Refinement kDefaultReference{16.0, 4.0, 1.5};

// The scene's ladders; `reference` as parsed by parseReference (or
// kDefaultReference, the finest the study then chooses).
Ladder buildLadder(const Scene& scene, const Refinement& reference);

// "photons=8,step=4,grid=1.5" (any of the three; step = 4 is a quarter of
// the step; those not named stay the scene's own, 1). Each between 1 and
// kFinestReference's, and at least one above 1: the scene's own settings
// are the first rung, and a reference is finer than every rung (rungs finer
// in a knob are left out, ladder by ladder). An InputError at `where`
// otherwise.
Refinement parseReference(const std::string& text, const std::string& where);

// The least the ladders take the wavefront's split and tear thresholds
// to, texels (voxels): the least split_texels and split_voxels a scene
// file may hold.
inline constexpr double kLeastWavefrontThreshold = 0.05;
// The most those thresholds refine for this scene before they are held there.
double finestWavefrontRefinement(const Scene& scene);

// The scene refined by `refinement` and the setting it describes.
Rung refinedRung(const Scene& scene, const std::string& knob, const Refinement& refinement);
// The reference at `refinement` (with a grid knob only where the scene has
// one), traced with another seed so that its noise is independent of the
// rungs'.
Rung referenceRung(const Scene& scene, const Refinement& refinement);

}  // namespace eikon::converge
