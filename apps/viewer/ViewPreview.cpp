#include "apps/viewer/ViewPreview.h"

#include <algorithm>
#include <cmath>

namespace eikon::view {

int ViewPreview::strideFor(bool cameraMoved, double nowSeconds) {
    if (cameraMoved) {
        lastMoveSeconds_ = nowSeconds;
        moved_ = true;
    }
    if (!cameraMoving(nowSeconds) || oneRayViewMs_ * fullRaysPerPixel_ <= settings_.targetViewMs) return 1;
    // A k×k stride traces one ray per k² pixels.
    const int stride = static_cast<int>(std::ceil(std::sqrt(oneRayViewMs_ / settings_.targetViewMs)));
    return std::clamp(stride, 2, std::max(settings_.largestStride, 2));
}

bool ViewPreview::cameraMoving(double nowSeconds) const {
    return moved_ && nowSeconds - lastMoveSeconds_ < settings_.refineDelaySeconds;
}

void ViewPreview::measured(int stride, double viewMs, int raysPerPixel) {
    if (viewMs <= 0.0 || raysPerPixel < 1) return;
    oneRayViewMs_ = viewMs * stride * stride / raysPerPixel;
    if (stride == 1) fullRaysPerPixel_ = raysPerPixel;
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
