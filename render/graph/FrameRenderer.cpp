#include "render/graph/FrameRenderer.h"

#include "bridge/core/Error.h"
#include "bridge/scene/ImageSpaceScope.h"
#include "render/graph/UniformMedium.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace eikon::render {

namespace {

// Runs `work` if `needed`, timing it to completion on the GPU.
template <typename Work>
StageReport runStage(const char* name, bool needed, Work&& work) {
    StageReport report{name, needed, 0.0, {}, StageDevice::Gpu, {}};
    if (!needed) return report;
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    report.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return report;
}

// A stage whose output has a closed form for these fields: `fill` writes it
// in place of `work`, and the report says why the stage did not run.
template <typename Work, typename Fill>
StageReport runOrFill(const char* name, bool needed, const char* closedForm, Work&& work, Fill&& fill) {
    if (!closedForm) return runStage(name, needed, std::forward<Work>(work));
    StageReport report = runStage(name, needed, std::forward<Fill>(fill));
    if (report.ran) report.skippedBecause = closedForm;
    report.ran = false;
    return report;
}

StageReport onDevice(StageDevice device, StageReport report) {
    report.device = device;
    return report;
}

}  // namespace

bool tracesLight(const Scene& scene, bool scatters) {
    return !scene.receivers.empty() || scatters || scene.tracer.storeFluence;
}

FrameRenderer::FrameRenderer(const Scene& scene, const FieldSet& fields, RendererOptions options)
    : FrameRenderer(scene, hostUpload(fields), nullptr, options) {}

FrameRenderer::FrameRenderer(const Scene& scene, FieldRing& ring, RendererOptions options)
    : FrameRenderer(scene, ring.current(), &ring, options) {}

FrameRenderer::FrameRenderer(const Scene& scene, const FieldUpload& fields, FieldRing* ring, RendererOptions options)
    : scene_(scene), receivers_(scene.receivers), post_(scene.render.width, scene.render.height) {
    try {
        buildStages(fields, ring, options);
    } catch (const InputError& error) {  // a size the GL limits refuse: the stages know the key, not the file
        throw InputError(scene.sourcePath + ": " + error.what());
    }
}

void FrameRenderer::buildStages(const FieldUpload& fields, FieldRing* ring, const RendererOptions& options) {
    const Scene& scene = scene_;
    pendingUpload_ = fields_.upload(fields);  // before the stages: they compile for the fields present
    if (ring) ring->fenceCurrent();
    if (scene.render.method == RenderDesc::Method::ImageSpace) {
        temporalMean_ = options.temporalMean;
        imageSpaceDropped_ = imageSpaceOmissions(scene_);
        raster_ = std::make_unique<SurfaceRaster>(scene_);
        if (!scene.receivers.empty())
            imageSpaceCaustics_ = std::make_unique<ImageSpaceCaustics>(scene_, receivers_, *raster_);
        if (options.drawsImage)
            imageSpaceView_ = std::make_unique<ImageSpaceView>(scene_, receivers_, *raster_, options.recordViewExits);
        return;  // none of the eikonal stages
    }
    gridDevice_ = gridPassDevice(scene.render.device);
    prepare_ = std::make_unique<PrepareStage>(scene.grid, fields_, gridDevice_);
    // Photons light receivers and in-scattering; a scene with neither has no
    // photon stage unless the caller asks for the photons' tallies.
    const bool photonsWanted = tracesLight(scene, fields_.hasScattering()) || options.tracePhotons;
    // The octree steps photons and the view; a diagnostic marches in fixed steps.
    const bool drawsView = options.drawsImage && !scene.diagnostic;
    if (scene.tracer.stepPolicy == TracerDesc::StepPolicy::Octree && (photonsWanted || drawsView))
        stepStructure_ = std::make_unique<StepStructureStage>(fields.grid, scene.tracer, fields_.hasExtinction(),
                                                              fields_.hasEmission(), gridDevice_);
    if (photonsWanted) {
        PhotonProgramOptions photonOptions = options.photons;
        photonOptions.device = gridDevice_;
        photons_ = std::make_unique<PhotonStage>(scene_, fields_, receivers_, photonOptions);
    }
    // The lattice diffuses what the photons scattered, on the share that holds the whole pass.
    const bool holdsWholePass = !options.exchange || options.exchange->receivesTotals();
    if (photons_ && feedsLattice(scene, fields_) && holdsWholePass)
        lattice_ = std::make_unique<LatticeScattering>(fields.grid, fields_, LatticeSettings::of(scene.tracer),
                                                       buildSharpSurfaces(scene));
    if (options.drawsImage && scene.diagnostic)
        diagnostic_ = std::make_unique<DiagnosticStage>(scene_, fields_);
    else if (drawsView)
        view_ = std::make_unique<ViewStage>(scene_, fields_, receivers_, stepStructure_ != nullptr,
                                            lattice_ != nullptr, options.recordViewExits);
    progressiveView_ = view_ && options.progressiveView;
    const double voxel = fields.grid.smallestVoxelEdge();
    photonSettings_.seed = scene.render.seed;
    photonSettings_.stepLength = scene.tracer.stepVoxels * voxel;
    photonSettings_.maxSteps = scene.tracer.maxSteps > 0 ? static_cast<unsigned>(scene.tracer.maxSteps)
                                                          : defaultMaxSteps(fields.grid, photonSettings_.stepLength);
    photonSettings_.powerCutoff = scene.tracer.powerCutoff;
    photonSettings_.share = options.share;
    photonSettings_.exchange = options.exchange;
    if (options.estimateErrors && diagnostic_)
        diagnosticEstimate_ = std::make_unique<DiagnosticErrorEstimate>(scene_, fields_, *diagnostic_);
    if (options.estimateErrors && view_) {
        const double referenceStep = ErrorEstimateStage::referenceStepVoxels(scene) * voxel;
        if (stepStructure_) {
            stepStructure_->enableReference(referenceStep);
        } else {
            referenceSteps_ = std::make_unique<StepStructureStage>(fields.grid, scene.tracer, fields_.hasExtinction(),
                                                                   fields_.hasEmission(), gridDevice_);
            referenceSteps_->enableReference(referenceStep);
        }
        errorEstimate_ = std::make_unique<ErrorEstimateStage>(scene_, fields_, receivers_, stepStructure_ != nullptr);
        if (options.share.whole() && !options.exchange) photonSettings_.evenHalf = errorEstimate_->evenHalf();
    }
}

const gl::Texture3D* FrameRenderer::stepTexture() const {
    return stepStructure_ ? &stepStructure_->stepTexture() : nullptr;
}

StageReport FrameRenderer::relight(PhotonStats& stats) {
    EIKON_CHECK_MSG(photons_, "relight of a scene without a photon stage");
    return runStage("photons", true, [&] { stats = photons_->run(fields_, stepTexture(), photonSettings_); });
}

void FrameRenderer::setCamera(const CameraDesc& camera) {
    scene_.camera = camera;
    if (view_) view_->setCamera(camera);
    if (diagnostic_) diagnostic_->setCamera(camera);
    if (diagnosticEstimate_) diagnosticEstimate_->setCamera(camera);
    if (imageSpaceView_) imageSpaceView_->setCamera(camera);
    cameraChanged_ = true;
}

void FrameRenderer::setPixelStride(int stride) {
    if (diagnostic_ && stride != diagnostic_->pixelStride()) {
        diagnostic_->setPixelStride(stride);
        cameraChanged_ = true;
    }
    if (!view_ || stride == view_->pixelStride()) return;
    view_->setPixelStride(stride);
    cameraChanged_ = true;
}

void FrameRenderer::setLight(std::size_t index, const LightDesc& light) {
    EIKON_CHECK_MSG(index < scene_.lights.size(), "no such light");
    scene_.lights[index] = light;
    if (photons_) photons_->setEmitters(scene_);
    if (imageSpaceCaustics_) imageSpaceCaustics_->setLight(index, light);
    lightsChanged_ = true;
}

void FrameRenderer::setPhotonCount(long long photons, bool retrace) {
    if (photons == scene_.render.photons) return;
    scene_.render.photons = photons;
    if (photons_) photons_->setEmitters(scene_);  // photons are shared among lights by power
    lightsChanged_ = lightsChanged_ || retrace;
}

void FrameRenderer::setExposure(double exposureEv) {
    if (exposureEv == scene_.render.exposureEv) return;
    scene_.render.exposureEv = exposureEv;
    exposureChanged_ = true;
}

FrameResult FrameRenderer::render(const FieldSet& fields) { return render(hostUpload(fields), nullptr); }

FrameResult FrameRenderer::render(FieldRing& ring) { return render(ring.current(), &ring); }

void FrameRenderer::markRendered(const FieldUpload& fields) {
    tracedIndexVersion_ = fields.indexVersion;
    tracedExtinctionVersion_ = fields.extinctionVersion;
    tracedScatteringVersion_ = fields.scatteringVersion;
    tracedSurfaceVersion_ = fields.surfaceVersion;
    cameraChanged_ = lightsChanged_ = exposureChanged_ = false;
}

FrameResult FrameRenderer::renderImageSpace(const FieldUpload& fields, FieldRing* ring) {
    FrameResult result;
    const bool fieldsChanged = fields.indexVersion != tracedIndexVersion_ ||
                               fields.extinctionVersion != tracedExtinctionVersion_ ||
                               fields.scatteringVersion != tracedScatteringVersion_ ||
                               fields.surfaceVersion != tracedSurfaceVersion_;
    result.stages.push_back(runStage("upload", fieldsChanged, [&] {
        const UploadBytes bytes = fields_.upload(fields);
        result.copied = {std::exchange(pendingUpload_, {}).host + bytes.host, bytes.gpu};
    }));
    if (ring) ring->fenceCurrent();
    const bool lightChanged = fieldsChanged || lightsChanged_;
    const bool causticsNeeded = imageSpaceCaustics_ && (lightChanged || (temporalMean_ && imageSpaceCaustics_->refining()));
    if (imageSpaceCaustics_)
        result.stages.push_back(runStage("image_space_caustics", causticsNeeded,
                                         [&] { imageSpaceCaustics_->run(fields_, lightChanged); }));
    const bool viewNeeded = imageSpaceView_ && (fieldsChanged || causticsNeeded || cameraChanged_);
    if (imageSpaceView_) {
        result.stages.push_back(runStage("image_space_view", viewNeeded, [&] { imageSpaceView_->run(fields_); }));
        result.stages.push_back(runStage("post", viewNeeded || exposureChanged_, [&] {
            last_.image = post_.run(imageSpaceView_->hdrTexels(), scene_.render.exposureEv);
        }));
    }
    markRendered(fields);
    if (viewNeeded && scene_.render.writeHdr) last_.hdr = imageSpaceView_->downloadHdr();
    result.image = last_.image;
    result.hdr = last_.hdr;
    result.imageSpace = ImageSpaceStats{imageSpaceCaustics_ ? imageSpaceCaustics_->framesAveraged() : 0,
                                        imageSpaceDropped_};
    return result;
}

FrameResult FrameRenderer::render(const FieldUpload& fields, FieldRing* ring) {
    if (raster_) return renderImageSpace(fields, ring);
    FrameResult result;
    const bool indexChanged = fields.indexVersion != tracedIndexVersion_;
    const bool extinctionChanged = fields.extinctionVersion != tracedExtinctionVersion_;
    const bool fieldsChanged = indexChanged || extinctionChanged ||
                               fields.scatteringVersion != tracedScatteringVersion_ ||
                               fields.surfaceVersion != tracedSurfaceVersion_;
    result.stages.push_back(runStage("upload", fieldsChanged, [&] {
        const UploadBytes bytes = fields_.upload(fields);
        result.copied = {std::exchange(pendingUpload_, {}).host + bytes.host, bytes.gpu};
    }));
    if (ring) ring->fenceCurrent();  // the slot is free again once the copies issued so far ran
    if (photons_ && extinctionChanged && fields.emission.floats)
        photons_->setVolumeGlow(scene_, fields.emission.host, fields.grid);  // the glow lights the scene
    // A moved light matters only through the photons it sends.
    const bool photonsNeeded = photons_ && (fieldsChanged || lightsChanged_);
    if (indexChanged) uniformIndex_ = holdsOneValue(fields.deltaIndex, 1);
    if (indexChanged || extinctionChanged)
        uniformMedium_ = uniformIndex_ && holdsOneValue(fields.extinction, 3) && fields.emission.floats == 0;
    const float deltaIndex = fields.deltaIndex.host ? fields.deltaIndex.host[0] : 0.0f;
    const bool emptyOfExtinction =  // host κ is there where the medium is uniform
        uniformMedium_ && (fields.extinction.floats == 0 ||
                           std::max({fields.extinction.host[0], fields.extinction.host[1], fields.extinction.host[2]}) <= 0.0f);
    result.stages.push_back(onDevice(gridDevice_, runOrFill("prepare", indexChanged, uniformIndex_ ? kUniformIndexReason : nullptr,
                                                            [&] { prepare_->run(fields_); },
                                                            [&] { prepare_->fillUniform(fields_, deltaIndex); })));
    // Smoothing a uniform δn leaves it as it is.
    const gl::Texture3D& smoothedIndex = uniformIndex_ ? fields_.index() : prepare_->smoothedIndex(fields_);
    const char* uniformSteps = uniformMedium_ ? kUniformMediumReason : nullptr;
    if (stepStructure_)
        result.stages.push_back(onDevice(gridDevice_, runOrFill("step_structure", indexChanged || extinctionChanged,
                                                                uniformSteps,
                                                                [&] { stepStructure_->run(smoothedIndex, fields_); },
                                                                [&] { stepStructure_->fillUniform(emptyOfExtinction); })));
    if (referenceSteps_)
        result.stages.push_back(onDevice(gridDevice_, runOrFill("reference_steps", indexChanged || extinctionChanged,
                                                                uniformSteps,
                                                                [&] { referenceSteps_->run(smoothedIndex, fields_); },
                                                                [&] { referenceSteps_->fillUniform(emptyOfExtinction); })));
    if (photons_) {
        result.stages.push_back(onDevice(photons_->device(), runStage("photons", photonsNeeded, [&] {
            last_.photons = photons_->run(fields_, stepTexture(), photonSettings_);
        })));
        result.stages.back().deviceReason = photons_->deviceReason();
    }
    if (lattice_)
        result.stages.push_back(runStage("multiple_scattering", photonsNeeded, [&] {
            last_.lattice = lattice_->run(fields_, photons_->scatteredPower(),
                                          {&photons_->fluence(), &photons_->fluenceDirection()});
        }));
    const bool viewNeeded = view_ && (fieldsChanged || photonsNeeded || cameraChanged_);
    const ViewInputs viewInputs{photons_ ? &photons_->fluence() : nullptr,
                                photons_ ? &photons_->fluenceDirection() : nullptr, stepTexture(),
                                lattice_ ? &lattice_->fluence() : nullptr};
    if (view_) result.stages.push_back(runStage("view", viewNeeded, [&] { view_->run(fields_, viewInputs); }));
    // Nothing moved: the progressive view adds a pass to the image it shows.
    const bool refineNeeded = progressiveView_ && !viewNeeded && view_->refinable(kProgressiveFinestGrid);
    if (progressiveView_)
        result.stages.push_back(runStage("view_refine", refineNeeded, [&] { view_->refine(fields_, viewInputs); }));
    if (view_) result.stages.push_back(runStage("post", viewNeeded || refineNeeded || exposureChanged_, [&] {
        last_.image = post_.run(view_->hdrTexels(), scene_.render.exposureEv);
    }));
    // A diagnostic sees the index and, through its transmittance, the extinction.
    const bool diagnosticNeeded = diagnostic_ && (indexChanged || extinctionChanged || cameraChanged_);
    if (diagnostic_) result.stages.push_back(runStage("diagnostic", diagnosticNeeded, [&] {
        if (indexChanged || extinctionChanged) {
            const VaryingVoxels varying = varyingVoxels(fields);
            diagnostic_->setVaryingVoxels(varying);
            if (diagnosticEstimate_) diagnosticEstimate_->setVaryingVoxels(varying);
        }
        last_.image = diagnostic_->run(fields_);
        if (diagnostic_->crossesSharpSurfaces()) last_.diagnosticLost = diagnostic_->lostRays();
    }));
    if (diagnosticEstimate_)
        result.stages.push_back(runStage("error_estimate", diagnosticNeeded && diagnostic_->pixelStride() == 1,
                                         [&] { last_.errorEstimate = diagnosticEstimate_->run(fields_); }));
    // The estimate is of the full image, not of a preview.
    if (errorEstimate_) result.stages.push_back(runStage("error_estimate", viewNeeded && view_->pixelStride() == 1, [&] {
        const StepStructureStage& reference = referenceSteps_ ? *referenceSteps_ : *stepStructure_;
        last_.errorEstimate = errorEstimate_->run(
            fields_, {photons_.get(), stepTexture(), &reference.referenceStepTexture(), photonSettings_});
    }));
    markRendered(fields);
    if (viewNeeded && scene_.render.writeHdr) last_.hdr = view_->downloadHdr();
    if (diagnosticNeeded && scene_.render.writeHdr) last_.hdr = diagnostic_->downloadHdr();
    result.image = last_.image;
    result.hdr = last_.hdr;
    result.photons = last_.photons;
    result.lattice = last_.lattice;
    result.errorEstimate = last_.errorEstimate;
    result.diagnosticLost = last_.diagnosticLost;
    result.pixelStride = view_ ? view_->pixelStride() : diagnostic_ ? diagnostic_->drawnStride() : 1;
    result.viewSamples = view_ ? view_->samplesTaken() : diagnostic_ ? diagnostic_->raysPerPixel() : 1;
    return result;
}

}  // namespace eikon::render
