#include "apps/common/FrameSource.h"

#include "bridge/core/Error.h"

namespace eikon::app {

FrameSource::FrameSource(const Scene& scene, sim::SceneFields& fields, const render::RendererOptions& options,
                         bool pipelined, ExportNeeds exports)
    : fields_(fields), exports_(std::move(exports)) {
    if (fields.simulatesFluid()) {
        live_ = std::make_unique<LiveFrames>(fields, pipelined, exports_);
        renderer_ = std::make_unique<render::FrameRenderer>(scene, live_->ring(), options);
    } else {
        host_.time = fields.time();
        host_.simulationDevice = fields.waterDevice();
        if (fields.gpuWater()) host_.busBytes = fields.gpuWater()->setupBytes();
        host_.phases = fields.lastTimings();
        if (exports_.exportsFrame(0)) captureForExport(fields_, exports_, host_);
        renderer_ = std::make_unique<render::FrameRenderer>(scene, fields.fields(), options);
    }
}

void FrameSource::setPipelined(bool pipelined) {
    if (live_) live_->setPipelined(pipelined);
}

void FrameSource::beginNext() {
    if (live_) live_->beginNext();
}

render::FrameResult FrameSource::render() {
    return live_ ? renderer_->render(live_->ring()) : renderer_->render(hostFields());
}

render::FieldUpload FrameSource::hostFields() const {
    EIKON_CHECK_MSG(!live_, "a fluid solver's frames come through the ring");
    render::FieldUpload upload = render::hostUpload(fields_.fields());
    if (const sim::gpu::GpuWaterBody* water = fields_.gpuWater()) {
        auto onGpu = [](const render::FieldSource& host, GLuint buffer) {
            return host.floats ? render::FieldSource{nullptr, buffer, host.floats} : host;
        };
        upload.surfaceNodes = onGpu(upload.surfaceNodes, water->surfaceNodes().id());
        upload.surfaceTriangles = onGpu(upload.surfaceTriangles, water->surfaceTriangles().id());
        upload.extinction = onGpu(upload.extinction, water->extinction());
        upload.scattering = onGpu(upload.scattering, water->scattering());
        upload.anisotropy = onGpu(upload.anisotropy, water->anisotropy());
    }
    return upload;
}

bool FrameSource::nextReady() const { return !live_ || live_->nextReady(); }

const ProducedFrame& FrameSource::waitNext() {
    return live_ ? live_->waitNext() : host_;
}

void FrameSource::publishNext() {
    if (live_) {
        live_->publishNext();
        return;
    }
    if (!fields_.changesOverTime()) return;
    const auto start = std::chrono::steady_clock::now();
    fields_.advanceFrame();
    host_.busBytes = 0;  // a water body on the GPU moves nothing after its set-up
    host_.simulated = true;
    host_.simulateMs = millisecondsSince(start);
    host_.time = fields_.time();
    host_.phases = fields_.lastTimings();
    if (exports_.exportsFrame(++hostFrame_)) captureForExport(fields_, exports_, host_);
}

void FrameSource::seekFrame(int frame) {
    EIKON_CHECK_MSG(!live_ && fields_.framesAreIndependent(), "seekFrame on a scene whose frames depend on each other");
    const auto start = std::chrono::steady_clock::now();
    fields_.seekFrame(frame);
    host_.simulated = frame > 0 && fields_.changesOverTime();
    host_.simulateMs = millisecondsSince(start);
    host_.time = fields_.time();
    host_.phases = fields_.lastTimings();
    hostFrame_ = frame;
    if (exports_.exportsFrame(frame)) captureForExport(fields_, exports_, host_);
}

const ProducedFrame& FrameSource::current() const { return live_ ? live_->current() : host_; }

ConstFieldViews FrameSource::currentViews() const {
    return live_ ? live_->currentViews() : viewsOf(fields_.fields());
}

}  // namespace eikon::app
