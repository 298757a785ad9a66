#include "apps/eikon-view/ViewerSession.h"

#include "bridge/scene/ImageSpaceScope.h"

namespace eikon::view {

namespace {

// The scene's fields with its fluid solver placed (before the frame source
// sizes its field ring for where the solver writes).
std::unique_ptr<sim::SceneFields> placedFields(const Scene& scene, bool hardwareGpu) {
    auto fields = std::make_unique<sim::SceneFields>(scene);
    fields->placeFluidSolver(hardwareGpu);
    return fields;
}

}  // namespace

ViewerSession::ViewerSession(const Scene& scene, bool hardwareGpu)
    : scene_(scene),
      fields_(placedFields(scene, hardwareGpu)),
      source_(std::make_unique<app::FrameSource>(scene_, *fields_, render::RendererOptions{}, false, false)) {
    if (scene.render.method == RenderDesc::Method::Eikonal && imageSpaceOmissions(scene).empty()) {
        Scene imageSpace = scene;
        imageSpace.render.method = RenderDesc::Method::ImageSpace;
        render::RendererOptions options;
        options.temporalMean = false;  // shown only while the camera moves: one frame's maps are enough
        imageSpace_ = std::make_unique<render::FrameRenderer>(imageSpace, fields_->fields(), options);
    }
}

render::FrameResult ViewerSession::renderImageSpacePreview(bool advance) {
    const render::FrameRenderer& eikonal = renderer();
    imageSpace_->setCamera(eikonal.scene().camera);
    for (std::size_t i = 0; i < eikonal.scene().lights.size(); ++i)
        if (eikonal.scene().lights[i] != imageSpace_->scene().lights[i])
            imageSpace_->setLight(i, eikonal.scene().lights[i]);
    imageSpace_->setExposure(eikonal.scene().render.exposureEv);
    render::FrameResult result = imageSpace_->render(fields_->fields());
    if (advance) {  // host fields only: a scene of surfaces has no fluid solver
        fields_->keepSharpCoverage(false);  // until an eikonal frame needs it again
        source_->beginNext();
        source_->waitNext();
        source_->publishNext();
    }
    return result;
}

render::FrameResult ViewerSession::renderFrame(bool advance, bool pipelined) {
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
