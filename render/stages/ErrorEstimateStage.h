// Each frame's estimate of its own error, from its two sources
// (docs/accuracy.md, "Per-frame error estimates"):
//
// - noise: the photon pass traces its even and odd photons as two
//   independent batches (PhotonSettings::evenHalf). With X the frame's output
//   and X_A the even half's, scaled to the whole pass's power,
//   E|X_A − X|² = Var X per texel, pixel or cell, so
//   ‖X_A − X‖₂ / ‖X‖₂ estimates the relative RMS error that the photon count
//   leaves. The image's is that of a small view drawn with the half's maps
//   and fluence beside one drawn with the whole pass's. The wavefront is
//   deterministic and has none.
// - discretisation: a stratified subset of the photons (every k-th, k prime)
//   is traced again with the scene's own integrator and steps and with a
//   reference march — RK4, steps of half the scene's smallest (at most half a
//   voxel) wherever the index or extinction varies at all, one flight only
//   through exactly uniform nodes (StepStructureStage::enableReference), where
//   a straight line is exact. Where they end is compared. Receivers: the
//   frame's map is moved by the displacement field the probe's landings
//   sample (MapDisplacement.h), and its relative L1 change taken, plus the
//   power of photons that end differently or change power. Fluence: the
//   relative L1 change its photons would make if their displacements in
//   voxels did not cancel (an upper bound; discretisationOfPhotons). The
//   image's is the relative L1 change of a small view drawn with the scene's
//   step and with the reference's. A step that jumps the medium shows at
//   once; an error both marches share (the grid's resolution, the smoothing)
//   does not.
#pragma once

#include "bridge/scene/Scene.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/PhotonStage.h"
#include "render/stages/ReceiverMaps.h"
#include "render/stages/StepStructureStage.h"
#include "render/stages/ViewStage.h"

#include <glm/vec2.hpp>

#include <memory>
#include <optional>

namespace eikon::render {

// Relative errors per output; unset where the frame has no such output.
struct OutputErrors {
    std::optional<double> receivers, image, fluence;
    // A diagnostic's measurements (render/stages/DiagnosticErrorEstimate.h).
    std::optional<double> deflection, opticalPathDifference, displacement;
    // The largest of those set (0 where none is).
    double worst() const;
};

struct ErrorEstimate {
    bool noiseEstimated = false;  // false for the wavefront (deterministic) and shared passes
    OutputErrors noise;           // relative RMS
    OutputErrors discretisation;  // relative change against the reference march
    long long probePhotons = 0;
    double referenceStepVoxels = 0.0;
    double milliseconds = 0.0;    // what the estimate cost, the halved pass's share excluded
};

class ErrorEstimateStage {
public:
    // referenceSteps: the step structure whose reference labels the probe's
    // reference march uses (the caller enables and runs it).
    ErrorEstimateStage(const Scene& scene, const FieldTextures& fields, const ReceiverMaps& receivers,
                       bool sceneHasStepStructure);

    // Half a step of the scene's smallest (camera or photon), at most half a
    // voxel, in voxels: what enableReference is given.
    static double referenceStepVoxels(const Scene& scene);
    // The scene drawn small for the image's estimates: 8 times narrower, one
    // ray a pixel.
    static Scene smallViewScene(const Scene& scene);

    // The receivers of the even half: PhotonSettings::evenHalf, where noise
    // is estimated (a whole photon pass).
    ReceiverMaps* evenHalf() { return noiseByBatches_ ? &evenHalf_ : nullptr; }

    struct Inputs {
        const PhotonStage* photons = nullptr;          // the frame's light pass, traced with evenHalf()
        const gl::Texture3D* sceneSteps = nullptr;      // the scene's step structure, if any
        const gl::Texture3D* referenceSteps = nullptr;  // StepStructureStage::referenceStepTexture
        PhotonSettings settings;                        // the frame's
    };
    // After the frame's light pass; draws its own small views.
    ErrorEstimate run(const FieldTextures& fields, const Inputs& inputs);

private:
    double discretisationOfPhotons(const std::vector<PhotonEnd>& scene, const std::vector<PhotonEnd>& reference,
                                   bool onReceivers) const;
    glm::dvec2 texelOnMap(unsigned receiver, const glm::vec3& position) const;

    const ReceiverMaps& receivers_;
    bool noiseByBatches_ = false;
    bool hasFluence_ = false;
    double voxel_ = 0.0;
    double referenceStep_ = 0.0;  // metres
    long long probePhotons_ = 0;
    ReceiverMaps evenHalf_;
    ReceiverMaps probeReceivers_, referenceReceivers_;
    std::unique_ptr<PhotonStage> probe_, reference_;
    std::unique_ptr<ViewStage> view_, halfView_, referenceView_;
};

}  // namespace eikon::render
