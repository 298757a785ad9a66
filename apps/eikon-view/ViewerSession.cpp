#include "apps/eikon-view/ViewerSession.h"

#include "bridge/core/Error.h"
#include "bridge/scene/ImageSpaceScope.h"

#include <algorithm>

namespace eikon::view {

namespace {

// The image-space preview's caustic maps, photons per light edge: shown only
// while the camera moves, they need not match the refined frame's accuracy
// (the default scene's caustic is 2.8% off inside its disk at 128², 1.7% at
// the 256² of image-space scenes) and cost about half as much.
constexpr int kPreviewCausticMapTexels = 128;

// The scene's fields with its fluid solver and water placed (before the
// frame source sizes its field ring for where the solver writes).
std::unique_ptr<sim::SceneFields> placedFields(const Scene& scene, bool hardwareGpu) {
    auto fields = std::make_unique<sim::SceneFields>(scene);
    fields->placeFluidSolver(hardwareGpu);
    fields->placeWater(hardwareGpu);
    return fields;
}

}  // namespace

ViewerSession::ViewerSession(const Scene& scene, bool hardwareGpu)
    : scene_(scene),
      fields_(placedFields(scene, hardwareGpu)),
      source_(std::make_unique<app::FrameSource>(scene_, *fields_, render::RendererOptions{.photons = {}, .progressiveView = true},
                                                 false, app::ExportNeeds())),
      followed_(fields_->followedVolume()) {
    if (scene.render.method == RenderDesc::Method::Eikonal && imageSpaceOmissions(scene).empty()) {
        imageSpaceScene_ = scene;
        imageSpaceScene_->render.method = RenderDesc::Method::ImageSpace;
        imageSpaceScene_->render.causticMapTexels = kPreviewCausticMapTexels;
    }
}

bool ViewerSession::nextStepReady() {
    if (!followed_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - lastLook_).count() < scene_.volume->follow->pollSeconds) return false;
    lastLook_ = now;
    return followed_->followNext(false);
}

std::string ViewerSession::followedStep() const { return followed_ ? followed_->currentFile() : ""; }

std::vector<sim::SkippedStep> ViewerSession::skippedBefore() const {
    return followed_ ? followed_->skippedBefore() : std::vector<sim::SkippedStep>{};
}

bool ViewerSession::canAdvanceInBackground() const {
    return source_->throughRing() && fields_->fluidDevice() != "gpu" && !following() &&
           !source_->renderer().photonStage();
}

void ViewerSession::beginBackgroundAdvance() {
    EIKON_CHECK_MSG(canAdvanceInBackground() && !advancingInBackground_, "one background advance of a CPU solver at a time");
    source_->setPipelined(true);
    source_->beginNext();
    advancingInBackground_ = true;
}

bool ViewerSession::showBackgroundAdvance() {
    if (!advancingInBackground_ || !source_->nextReady()) return false;
    source_->waitNext();
    source_->publishNext();
    advancingInBackground_ = false;
    return true;
}

render::FrameResult ViewerSession::renderImageSpacePreview(bool advance, int scale) {
    std::unique_ptr<render::FrameRenderer>& preview = imageSpace_[scale];
    if (!preview) {
        Scene scaled = *imageSpaceScene_;
        scaled.render.width = std::max(1, scaled.render.width / scale);
        scaled.render.height = std::max(1, scaled.render.height / scale);
        render::RendererOptions options;
        options.temporalMean = false;  // shown only while the camera moves: one frame's maps are enough
        preview = std::make_unique<render::FrameRenderer>(scaled, fields_->fields(), options);
    }
    const render::FrameRenderer& eikonal = renderer();
    preview->setCamera(eikonal.scene().camera);
    for (std::size_t i = 0; i < eikonal.scene().lights.size(); ++i)
        if (eikonal.scene().lights[i] != preview->scene().lights[i]) preview->setLight(i, eikonal.scene().lights[i]);
    preview->setExposure(eikonal.scene().render.exposureEv);
    render::FrameResult result = preview->render(source_->hostFields());
    if (advance) {  // host fields only: a scene of surfaces has no fluid solver
        fields_->keepSharpCoverage(false);  // until an eikonal frame needs it again
        source_->beginNext();
        source_->waitNext();
        source_->publishNext();
    }
    return result;
}

render::FrameResult ViewerSession::renderFrame(bool advance, bool pipelined) {
    EIKON_CHECK_MSG(!(advance && advancingInBackground_), "the background advance shown before the next");
    fields_->keepSharpCoverage(sim::SceneFields::needsSharpCoverage(scene_));
    if (!advance) return source_->render();
    // A solver on the GPU queues its passes on this context: nothing to overlap on a thread.
    source_->setPipelined(pipelined && fields_->fluidDevice() != "gpu");
    source_->beginNext();
    render::FrameResult result = source_->render();
    source_->waitNext();
    source_->publishNext();
    return result;
}

}  // namespace eikon::view
