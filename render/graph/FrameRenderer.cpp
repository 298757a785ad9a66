#include "render/graph/FrameRenderer.h"

#include <chrono>
#include <utility>

namespace eikon::render {

namespace {

// Runs `work` if `needed`, timing it to completion on the GPU.
template <typename Work>
StageReport runStage(const char* name, bool needed, Work&& work) {
    StageReport report{name, needed, 0.0};
    if (!needed) return report;
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    report.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace

FrameRenderer::FrameRenderer(const Scene& scene, const FieldSet& fields, RendererOptions options)
    : scene_(scene), receivers_(scene.receivers), post_(scene.render.width, scene.render.height) {
    pendingUploadBytes_ = fields_.upload(fields);  // before the stages: they compile for the fields present
    prepare_ = std::make_unique<PrepareStage>(scene.grid, fields_);
    if (scene.tracer.stepPolicy == TracerDesc::StepPolicy::Octree)
        stepStructure_ = std::make_unique<StepStructureStage>(fields.grid, scene.tracer, fields_.hasExtinction());
    photons_ = std::make_unique<PhotonStage>(scene_, fields_, receivers_, options.photons);
    view_ = std::make_unique<ViewStage>(scene_, fields_, receivers_, stepStructure_ != nullptr, options.recordViewExits);
    const double voxel = fields.grid.smallestVoxelEdge();
    photonSettings_.photons = scene.render.photons;
    photonSettings_.seed = scene.render.seed;
    photonSettings_.stepLength = scene.tracer.stepVoxels * voxel;
    photonSettings_.maxSteps = scene.tracer.maxSteps > 0 ? static_cast<unsigned>(scene.tracer.maxSteps)
                                                          : defaultMaxSteps(fields.grid, photonSettings_.stepLength);
    photonSettings_.powerCutoff = scene.tracer.powerCutoff;
}

const gl::Texture3D* FrameRenderer::stepTexture() const {
    return stepStructure_ ? &stepStructure_->stepTexture() : nullptr;
}

StageReport FrameRenderer::relight(PhotonStats& stats) {
    return runStage("photons", true, [&] { stats = photons_->run(fields_, stepTexture(), photonSettings_); });
}

void FrameRenderer::setCamera(const CameraDesc& camera) {
    scene_.camera = camera;
    view_->setCamera(camera);
    cameraChanged_ = true;
}

FrameResult FrameRenderer::render(const FieldSet& fields) {
    FrameResult result;
    result.stages.push_back(runStage("upload", true, [&] {
        result.hostBytesUploaded = std::exchange(pendingUploadBytes_, 0) + fields_.upload(fields);
    }));
    const bool indexChanged = fields.indexVersion != tracedIndexVersion_;
    const bool extinctionChanged = fields.extinctionVersion != tracedExtinctionVersion_;
    const bool fieldsChanged = indexChanged || extinctionChanged || fields.scatteringVersion != tracedScatteringVersion_;
    result.stages.push_back(runStage("prepare", indexChanged, [&] { prepare_->run(fields_); }));
    if (stepStructure_)
        result.stages.push_back(runStage("step_structure", indexChanged || extinctionChanged,
                                         [&] { stepStructure_->run(prepare_->smoothedIndex(fields_), fields_); }));
    result.stages.push_back(runStage("photons", fieldsChanged, [&] {
        last_.photons = photons_->run(fields_, stepTexture(), photonSettings_);
    }));
    const bool viewNeeded = fieldsChanged || cameraChanged_;
    result.stages.push_back(runStage("view", viewNeeded, [&] {
        view_->run(fields_, {&photons_->fluence(), &photons_->fluenceDirection(), stepTexture()});
    }));
    result.stages.push_back(runStage("post", viewNeeded, [&] {
        last_.image = post_.run(view_->hdrImage(), scene_.render.exposureEv);
    }));
    tracedIndexVersion_ = fields.indexVersion;
    tracedExtinctionVersion_ = fields.extinctionVersion;
    tracedScatteringVersion_ = fields.scatteringVersion;
    cameraChanged_ = false;
    if (viewNeeded && scene_.render.writeHdr) last_.hdr = view_->downloadHdr();
    result.image = last_.image;
    result.hdr = last_.hdr;
    result.photons = last_.photons;
    return result;
}

}  // namespace eikon::render
