#include "apps/viewer/ViewPreview.h"

#include <algorithm>
#include <cmath>

namespace eikon::view {

int ViewPreview::strideFor(bool cameraMoved, double nowSeconds) {
    if (cameraMoved) {
        lastMoveSeconds_ = nowSeconds;
        moved_ = true;
    }
    if (!cameraMoving(nowSeconds) || fullViewMs_ <= settings_.targetViewMs) return 1;
    // A k×k stride traces 1/k² of the rays.
    const int stride = static_cast<int>(std::ceil(std::sqrt(fullViewMs_ / settings_.targetViewMs)));
    return std::clamp(stride, 1, settings_.largestStride);
}

bool ViewPreview::cameraMoving(double nowSeconds) const {
    return moved_ && nowSeconds - lastMoveSeconds_ < settings_.refineDelaySeconds;
}

void ViewPreview::measured(int stride, double viewMs) {
    if (viewMs > 0.0) fullViewMs_ = viewMs * stride * stride;
}

int ViewPreview::imageSpaceScale() const {
    if (fullImageSpaceViewMs_ <= settings_.targetViewMs) return 1;
    // 1/k of the size in each direction draws 1/k² of the pixels.
    const int scale = static_cast<int>(std::ceil(std::sqrt(fullImageSpaceViewMs_ / settings_.targetViewMs)));
    return std::clamp(scale, 1, settings_.largestImageSpaceScale);
}

void ViewPreview::measuredImageSpace(int scale, double viewMs) {
    if (viewMs > 0.0) fullImageSpaceViewMs_ = viewMs * scale * scale;
}

}  // namespace eikon::view
