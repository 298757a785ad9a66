// While the camera moves, the viewer draws a preview: one camera ray per
// k×k block of pixels (FrameRenderer::setPixelStride), k chosen so that the
// view pass keeps to a target time; once the camera has rested for the
// refine delay it draws the full image, the same frame `eikon run` renders.
// A scene of surfaces is previewed in image space instead, drawn at 1/k of
// the image's size in each direction where its view pass at full size would
// miss the same target. The policy is plain arithmetic on times, so it is
// tested without a window.
#pragma once

namespace eikon::view {

struct PreviewSettings {
    double targetViewMs = 40.0;       // view-pass time to keep while the camera moves
    double refineDelaySeconds = 0.25;  // rest before the full image is drawn
    int largestStride = 16;
    int largestImageSpaceScale = 4;
};

class ViewPreview {
public:
    explicit ViewPreview(PreviewSettings settings = {}) : settings_(settings) {}

    // Once a frame, before it is rendered: whether the camera moved for this
    // frame, and the time now (s, any steady origin). Returns the pixel
    // stride to draw with: 1 for the full image.
    int strideFor(bool cameraMoved, double nowSeconds);
    // Whether the camera moved within the refine delay before `nowSeconds`
    // (as strideFor last saw it): the viewer is in its interactive mode,
    // whether or not the view needs a stride to keep to its target.
    bool cameraMoving(double nowSeconds) const;
    // After a frame whose view pass ran at `stride`, its time and the rays
    // it traced for each pixel (block) it drew (render.samples_per_pixel for
    // a full image, 1 for a preview): the cost per ray it implies sets the
    // next preview's stride.
    void measured(int stride, double viewMs, int raysPerPixel = 1);
    // The image-space preview's downscale k (1: full size) while the camera
    // moves, and after such a preview at scale k, its view pass's time.
    int imageSpaceScale() const;
    void measuredImageSpace(int scale, double viewMs);

private:
    PreviewSettings settings_;
    double oneRayViewMs_ = 0.0;  // estimated view-pass time of one ray a pixel; 0: not yet measured
    int fullRaysPerPixel_ = 1;   // the rays a pixel of the full image, as last measured
    double fullImageSpaceViewMs_ = 0.0;  // the same for the image-space preview
    double lastMoveSeconds_ = 0.0;
    bool moved_ = false;  // the camera has moved at least once
};

}  // namespace eikon::view
