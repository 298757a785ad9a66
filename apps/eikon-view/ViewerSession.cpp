#include "apps/eikon-view/ViewerSession.h"

namespace eikon::view {

ViewerSession::ViewerSession(const Scene& scene)
    : scene_(scene),
      fields_(std::make_unique<sim::SceneFields>(scene)),
      source_(std::make_unique<app::FrameSource>(scene_, *fields_, render::RendererOptions{}, false, false)) {}

render::FrameResult ViewerSession::renderFrame(bool advance, bool pipelined) {
    if (!advance) return source_->render();
    source_->setPipelined(pipelined);
    source_->beginNext();
    render::FrameResult result = source_->render();
    source_->waitNext();
    source_->publishNext();
    return result;
}

}  // namespace eikon::view
