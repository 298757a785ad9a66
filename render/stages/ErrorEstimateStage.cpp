#include "render/stages/ErrorEstimateStage.h"

#include "render/stages/MapDisplacement.h"
#include "render/stages/RelativeChange.h"

#include "bridge/core/PrimeStride.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlContext.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace eikon::render {

namespace {

// Photons in the discretisation probe: each is traced twice, once with the
// reference march, so that the two traces of the probe cost well under a
// tenth of a frame of 2^20 photons while the estimate's own spread (the
// probe is a random sample of paths) stays near 1/√4096 of it.
constexpr long long kProbePhotons = 4096;
// The small views are this many times narrower than the frame.
constexpr int kViewShrink = 8;

// ‖a − b‖₂ / ‖b‖₂ over the RGB of every element (`stride` floats each).
double relativeRms(const std::vector<float>& a, const std::vector<float>& b, std::size_t stride) {
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i + 2 < b.size(); i += stride)
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = static_cast<double>(a[i + c]) - b[i + c];
            difference += d * d;
            norm += static_cast<double>(b[i + c]) * b[i + c];
        }
    return norm > 0.0 ? std::sqrt(difference / norm) : 0.0;
}

std::vector<float> allMaps(const ReceiverMaps& maps) {
    std::vector<float> texels;
    for (unsigned r = 0; r < maps.count(); ++r) {
        const std::vector<float> map = maps.download(r);
        texels.insert(texels.end(), map.begin(), map.end());
    }
    return texels;
}

double totalPower(const glm::vec3& power) { return static_cast<double>(power.r) + power.g + power.b; }

}  // namespace

double OutputErrors::worst() const {
    double worst = 0.0;
    for (const auto& error : {receivers, image, fluence, deflection, opticalPathDifference, displacement})
        if (error) worst = std::max(worst, *error);
    return worst;
}

double ErrorEstimateStage::referenceStepVoxels(const Scene& scene) {
    return 0.5 * std::min({scene.tracer.stepVoxels, scene.render.stepVoxels, 1.0});
}

Scene ErrorEstimateStage::smallViewScene(const Scene& scene) {
    Scene small = scene;
    small.render.width = std::max(16, scene.render.width / kViewShrink);
    small.render.height = std::max(
        1, static_cast<int>(std::lround(small.render.width * static_cast<double>(scene.render.height) /
                                        scene.render.width)));
    // The march's errors are the same in every ray of a pixel: one, through its centre.
    small.render.samplesPerPixel = 1;
    return small;
}

ErrorEstimateStage::ErrorEstimateStage(const Scene& scene, const FieldTextures& fields, const ReceiverMaps& receivers,
                                       bool sceneHasStepStructure)
    : receivers_(receivers), evenHalf_(scene.receivers), probeReceivers_(scene.receivers),
      referenceReceivers_(scene.receivers) {
    voxel_ = fields.grid().smallestVoxelEdge();
    referenceStep_ = referenceStepVoxels(scene) * voxel_;
    hasFluence_ = scene.tracer.storeFluence || fields.hasScattering();
    const bool lightPass = !scene.receivers.empty() || hasFluence_;
    noiseByBatches_ = lightPass && scene.tracer.estimator == TracerDesc::Estimator::Photons;
    if (lightPass) {
        probePhotons_ = std::min(kProbePhotons, scene.render.photons);
        const long long stride = largestPrimeAtMost(scene.render.photons / probePhotons_);
        Scene probeScene = scene;
        probeScene.tracer.estimator = TracerDesc::Estimator::Photons;  // the march the wavefront shares
        probeScene.tracer.storeFluence = false;
        const PhotonProgramOptions options{.recordedPhotons = static_cast<int>(probePhotons_),
                                           .recordStride = static_cast<int>(stride),
                                           .recordEnds = true};
        probe_ = std::make_unique<PhotonStage>(probeScene, fields, probeReceivers_, options);
        Scene referenceScene = probeScene;
        referenceScene.tracer.integrator = TracerDesc::Integrator::Rk4;
        referenceScene.tracer.stepPolicy = TracerDesc::StepPolicy::Octree;
        referenceScene.tracer.renormalize = false;
        reference_ = std::make_unique<PhotonStage>(referenceScene, fields, referenceReceivers_, options);
    }
    Scene viewScene = smallViewScene(scene);
    view_ = std::make_unique<ViewStage>(viewScene, fields, receivers_, sceneHasStepStructure, false);
    if (noiseByBatches_) halfView_ = std::make_unique<ViewStage>(viewScene, fields, evenHalf_, sceneHasStepStructure, false);
    viewScene.render.stepVoxels = referenceStepVoxels(scene);
    referenceView_ = std::make_unique<ViewStage>(viewScene, fields, receivers_, true, false);
}

ErrorEstimate ErrorEstimateStage::run(const FieldTextures& fields, const Inputs& inputs) {
    const auto start = std::chrono::steady_clock::now();
    ErrorEstimate estimate;
    estimate.referenceStepVoxels = referenceStep_ / voxel_;
    estimate.probePhotons = probePhotons_;
    const bool fluence = inputs.photons && inputs.photons->storesFluence();
    estimate.noiseEstimated = noiseByBatches_ && inputs.photons && inputs.settings.evenHalf == &evenHalf_;

    const ViewInputs sceneView{fluence ? &inputs.photons->fluence() : nullptr,
                               fluence ? &inputs.photons->fluenceDirection() : nullptr, inputs.sceneSteps};
    view_->run(fields, sceneView);
    const std::vector<float> image = view_->downloadHdr();
    if (estimate.noiseEstimated) {
        if (receivers_.count() > 0) estimate.noise.receivers = relativeRms(allMaps(evenHalf_), allMaps(receivers_), 3);
        if (fluence)
            estimate.noise.fluence = relativeRms(inputs.photons->downloadHalfFluence(),
                                                 inputs.photons->downloadFluence(), 3);
        halfView_->run(fields, {fluence ? &inputs.photons->halfFluence() : nullptr,
                                fluence ? &inputs.photons->halfFluenceDirection() : nullptr, inputs.sceneSteps});
        estimate.noise.image = relativeRms(halfView_->downloadHdr(), image, 4);
    }
    referenceView_->run(fields, {sceneView.fluence, sceneView.fluenceDirection, inputs.referenceSteps});
    estimate.discretisation.image = relativeL1OfRgb(image, referenceView_->downloadHdr());

    if (probe_) {
        PhotonSettings settings = inputs.settings;
        settings.recordedOnly = true;
        settings.share = {};
        settings.exchange = nullptr;
        settings.evenHalf = nullptr;
        probe_->run(fields, inputs.sceneSteps, settings);
        settings.stepLength = referenceStep_;
        settings.maxSteps = defaultMaxSteps(fields.grid(), referenceStep_);
        reference_->run(fields, inputs.referenceSteps, settings);
        const std::vector<PhotonEnd> traced = probe_->downloadEnds();
        const std::vector<PhotonEnd> referenced = reference_->downloadEnds();
        if (receivers_.count() > 0) estimate.discretisation.receivers = discretisationOfPhotons(traced, referenced, true);
        if (hasFluence_) estimate.discretisation.fluence = discretisationOfPhotons(traced, referenced, false);
    }
    glFinish();
    estimate.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return estimate;
}

// One probe photon's part that no displacement field describes: a photon
// that ends only in one of the two maps (or on other receivers) adds its
// power once; a change of power, once.
//
// Receivers: the rest is the frame's map moved by the displacements the
// probe samples (MapDisplacement.h), so that neighbouring photons'
// displacements cancel as they do in the map.
//
// Fluence: a photon of power w that ends one voxel or more away takes w from
// one voxel and gives it to another, 2w of ‖M − M_ref‖₁; displaced by a
// fraction f of a voxel it crosses into the next with probability about f:
// the relative L1 change of the map if the displacements of neighbouring
// photons did not cancel, an upper bound.
double ErrorEstimateStage::discretisationOfPhotons(const std::vector<PhotonEnd>& traced,
                                                   const std::vector<PhotonEnd>& reference, bool onReceivers) const {
    double change = 0.0, referencePower = 0.0;
    std::vector<std::vector<LandingPair>> pairs(onReceivers ? receivers_.count() : 0);
    const auto counts = [&](const PhotonEnd& end) { return !onReceivers || end.fate == layout::kReceived; };
    for (std::size_t i = 0; i < std::min(traced.size(), reference.size()); ++i) {
        const PhotonEnd& a = traced[i];
        const PhotonEnd& b = reference[i];
        if (a.fate == 0 || b.fate == 0) continue;  // not traced
        const double powerA = counts(a) ? totalPower(a.power) : 0.0;
        const double powerB = counts(b) ? totalPower(b.power) : 0.0;
        referencePower += powerB;
        if (!counts(a) || !counts(b) || a.fate != b.fate || a.receiver != b.receiver) {
            change += powerA + powerB;
            continue;
        }
        change += std::abs(powerA - powerB);
        if (onReceivers) {
            const auto r = static_cast<unsigned>(a.receiver);
            pairs[r].push_back({texelOnMap(r, a.position), texelOnMap(r, b.position), std::min(powerA, powerB)});
            continue;
        }
        const double displacement = glm::length(glm::dvec3(a.position) - glm::dvec3(b.position)) / voxel_;
        change += 2.0 * std::min(powerA, powerB) * std::min(1.0, displacement);
    }
    double relative = referencePower > 0.0 ? change / referencePower : 0.0;
    if (onReceivers) {
        MapChange maps;
        for (unsigned r = 0; r < receivers_.count(); ++r) {
            const MapChange map =
                displacedMapChange(receivers_.download(r), static_cast<int>(receivers_.receiver(r).map.y), pairs[r]);
            maps.difference += map.difference;
            maps.norm += map.norm;
        }
        if (maps.norm > 0.0) relative += maps.difference / maps.norm;
    }
    return relative;
}

// Where `position` (on receiver r's plane) lies on its map, in texels.
glm::dvec2 ErrorEstimateStage::texelOnMap(unsigned r, const glm::vec3& position) const {
    const layout::GpuReceiver& receiver = receivers_.receiver(r);
    const glm::dvec3 offset = glm::dvec3(position) - glm::dvec3(receiver.origin);
    const glm::dvec2 uv(glm::dot(offset, glm::dvec3(receiver.axisU)), glm::dot(offset, glm::dvec3(receiver.axisV)));
    return (uv / static_cast<double>(receiver.origin.w) + 0.5) * static_cast<double>(receiver.map.y);
}

}  // namespace eikon::render
