#include "apps/eikon-view/ViewerSession.h"

namespace eikon::view {

ViewerSession::ViewerSession(const Scene& scene) : scene_(scene), fields_(std::make_unique<sim::SceneFields>(scene)) {
    if (fields_->simulatesFluid()) {
        live_ = std::make_unique<app::LiveFrames>(*fields_, false);
        renderer_ = std::make_unique<render::FrameRenderer>(scene_, live_->ring());
    } else {
        renderer_ = std::make_unique<render::FrameRenderer>(scene_, fields_->fields());
    }
}

render::FrameResult ViewerSession::renderFrame(bool advance, bool pipelined) {
    if (!live_) {
        if (advance) fields_->advanceFrame();
        return renderer_->render(fields_->fields());
    }
    if (!advance) return renderer_->render(live_->ring());
    live_->setPipelined(pipelined);
    live_->beginNext();
    render::FrameResult result = renderer_->render(live_->ring());
    live_->waitNext();
    live_->publishNext();
    return result;
}

}  // namespace eikon::view
