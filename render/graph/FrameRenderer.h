// One frame of the render half: upload → prepare → step structure → photons
// → multiple scattering → view → post; with a `diagnostic`, the diagnostic
// stage draws the picture in place of view and post; in image space
// (render.method "image_space") upload → caustic maps → image-space view → post. A stage runs only when one of its inputs changed since it
// last ran (field versions, camera); stages the scene does not need are not
// created (uniform steps → no step structure, no receivers → no maps, no
// scattering → no fluence and no lattice, neither receivers nor scattering →
// no photons); stages whose output has a closed form for the frame's fields
// are not run (a uniform medium: render/graph/UniformMedium.h).
// Each frame reports every stage it has with whether it ran, its wall time
// and, for a stage not run though its inputs changed, why.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"
#include "render/stages/DiagnosticErrorEstimate.h"
#include "render/stages/DiagnosticStage.h"
#include "render/stages/ErrorEstimateStage.h"
#include "render/stages/FieldRing.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/ImageSpaceCaustics.h"
#include "render/stages/ImageSpaceView.h"
#include "render/stages/LatticeScattering.h"
#include "render/stages/PhotonStage.h"
#include "render/stages/PostStage.h"
#include "render/stages/PrepareStage.h"
#include "render/stages/ReceiverMaps.h"
#include "render/stages/StepStructureStage.h"
#include "render/stages/ViewStage.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon::render {

struct StageReport {
    std::string name;
    bool ran = false;
    double milliseconds = 0.0;  // wall time with glFinish (GPU timer queries read 0 on llvmpipe)
    // Why a stage whose inputs changed did not run (render/graph/UniformMedium.h);
    // empty where it ran or nothing it reads changed. `milliseconds` is then
    // the time of what was written in its place.
    std::string skippedBecause;    // Compute shaders, or native loops over the same kernels (the grid
    // passes under render.device, render/stages/StageDevice.h).
    StageDevice device = StageDevice::Gpu;
    // Why a stage that render.device sent to the CPU ran as a compute shader
    // (the photons: nativePhotonRefusal); empty otherwise.
    std::string deviceReason;
};

// Of an image-space frame (render.method "image_space").
struct ImageSpaceStats {
    int framesAveraged = 0;             // frames in the caustic maps' temporal mean (0: no receivers)
    std::vector<std::string> dropped;   // what of the scene it does not show (bridge/scene/ImageSpaceScope.h)
};

struct FrameResult {
    Image8 image;
    std::vector<float> hdr;       // linear RGBA radiance, when the scene writes HDR
    PhotonStats photons;          // of the latest photon pass
    std::optional<LatticeStats> lattice;  // of the latest multiple-scattering pass, where the scene has one
    std::vector<StageReport> stages;
    UploadBytes copied;           // host bytes the driver read, bytes copied on the GPU
    std::optional<ErrorEstimate> errorEstimate;  // with RendererOptions::estimateErrors
    int pixelStride = 1;  // of the image: 1 the full image, k a preview of one ray per k×k pixels
    int viewSamples = 1;  // camera rays averaged in each pixel of the image (0: a preview)
    std::optional<ImageSpaceStats> imageSpace;  // where the scene renders in image space
    std::optional<int> diagnosticLost;  // a diagnostic through sharp surfaces: DiagnosticStage::lostRays
};

struct RendererOptions {
    PhotonProgramOptions photons;
    bool recordViewExits = false;  // keep each pixel's exit direction (tests)
    bool tracePhotons = false;     // a photon stage even with nothing to light (tallies, paths, benchmarks)
    // A light pass shared among processes (LightPassShare.h): this one's
    // share and the exchange that combines the shares' tallies.
    PassShare share{};
    LightPassExchange* exchange = nullptr;
    // False for a share that only traces light: no view and post stages,
    // and the frame's image stays empty (another process draws it).
    bool drawsImage = true;
    // Estimate each frame's noise and discretisation error (an
    // "error_estimate" stage, ErrorEstimateStage.h, or a diagnostic's,
    // DiagnosticErrorEstimate.h); `eikon run` sets it
    // from render.error_estimate. Where the light pass is shared among
    // processes, the noise is not estimated.
    bool estimateErrors = false;
    // Image space: while nothing changes, refine the caustic maps over
    // kTemporalFrames frames (ImageSpaceCaustics.h); false keeps the first
    // (the viewer's preview, drawn only while the camera moves).
    bool temporalMean = true;
    // The viewer's progressive view: a frame that changed is drawn as `eikon
    // run` draws it (render.samples_per_pixel), and each frame after it in
    // which nothing changes adds a pass of the next finer sample grid
    // (ViewStage::refine), up to the kProgressiveFinestGrid² grid whole.
    bool progressiveView = false;
};

// The finest grid (a side of k cells) the progressive view refines to.
constexpr int kProgressiveFinestGrid = 5;

// Whether a scene's frames trace light (photons or the wavefront): to light
// receivers or in-scattering, or to keep the fluence it asks for.
bool tracesLight(const Scene& scene, bool scatters);

class FrameRenderer {
public:
    FrameRenderer(const Scene& scene, const FieldSet& fields, RendererOptions options = {});
    // Fields from the ring's current slot, which also gives the layout.
    FrameRenderer(const Scene& scene, FieldRing& ring, RendererOptions options = {});

    // Renders fields from host memory (copied to the GPU where they changed).
    FrameResult render(const FieldSet& fields);
    // Renders the ring's current slot (no host copy) and fences it.
    FrameResult render(FieldRing& ring);
    // Renders fields from host memory or GL buffers (a simulation on the GPU
    // that writes its own: sim/gpu/GpuWaterBody.h).
    FrameResult render(const FieldUpload& fields) { return render(fields, nullptr); }
    void setCamera(const CameraDesc& camera);
    // Moves or re-powers light `index` of the scene: photons are traced anew.
    void setLight(std::size_t index, const LightDesc& light);
    // Photons per trace (the viewer lowers it while the user drags a light);
    // a changed count traces anew, or with `retrace` false, takes effect at
    // the next trace that runs for another reason (a moved light, new fields).
    void setPhotonCount(long long photons, bool retrace = true);
    // Exposure of the tone map: post runs again.
    void setExposure(double exposureEv);
    // 1: the full image; k > 1: a preview of one camera ray per k×k pixels
    // (the viewer while the camera moves; the view's and the diagnostic's,
    // DiagnosticStage::setPixelStride). A changed stride draws anew.
    void setPixelStride(int stride);
    const Scene& scene() const { return scene_; }
    // Traces the photons of the last rendered fields again (a relight, as
    // when a light moves), timed to completion; for benchmarks.
    StageReport relight(PhotonStats& stats);

    const ReceiverMaps& receivers() const { return receivers_; }
    // Null when the scene has nothing for photons to light (no receivers, no scattering).
    const PhotonStage* photonStage() const { return photons_.get(); }
    const ViewStage& viewStage() const { return *view_; }  // only where the renderer draws eikonal images of no diagnostic
    // Null unless the scene has a diagnostic and the renderer draws images.
    const DiagnosticStage* diagnosticStage() const { return diagnostic_.get(); }
    // Null unless the scene's render.method is image space and the renderer draws images.
    const ImageSpaceView* imageSpaceView() const { return imageSpaceView_.get(); }
    // Null unless the scene asks for multiple scattering and something scatters.
    const LatticeScattering* latticeStage() const { return lattice_.get(); }

private:
    const gl::Texture3D* stepTexture() const;  // null for uniform steps
    FrameRenderer(const Scene& scene, const FieldUpload& fields, FieldRing* ring, RendererOptions options);
    // The first upload and the stages the scene needs. Their InputErrors name
    // key paths; the constructor adds the scene file.
    void buildStages(const FieldUpload& fields, FieldRing* ring, const RendererOptions& options);
    // Uploads, then the stages that depend on what changed.
    FrameResult render(const FieldUpload& fields, FieldRing* ring);
    // The image-space frame (render.method "image_space"): layers, caustic maps, view, post.
    FrameResult renderImageSpace(const FieldUpload& fields, FieldRing* ring);
    // After a frame: its fields' versions are the ones traced, and no input is pending.
    void markRendered(const FieldUpload& fields);

    Scene scene_;
    FieldTextures fields_;
    ReceiverMaps receivers_;
    StageDevice gridDevice_ = StageDevice::Gpu;  // of prepare and the step structures
    std::unique_ptr<PrepareStage> prepare_;
    std::unique_ptr<StepStructureStage> stepStructure_;  // octree step policy only
    std::unique_ptr<PhotonStage> photons_;
    std::unique_ptr<LatticeScattering> lattice_;
    std::unique_ptr<ViewStage> view_;
    bool progressiveView_ = false;  // RendererOptions::progressiveView
    std::unique_ptr<DiagnosticStage> diagnostic_;  // in place of view_ where the scene has a diagnostic
    std::unique_ptr<DiagnosticErrorEstimate> diagnosticEstimate_;  // in place of errorEstimate_, with diagnostic_
    PostStage post_;
    // Image space only: the raster passes' surfaces, the caustic maps, the view.
    std::unique_ptr<SurfaceRaster> raster_;
    std::unique_ptr<ImageSpaceCaustics> imageSpaceCaustics_;
    std::unique_ptr<ImageSpaceView> imageSpaceView_;
    // With estimateErrors: the reference step labels (the scene's own step
    // structure's where it has one, else this one's) and the estimate.
    std::unique_ptr<StepStructureStage> referenceSteps_;
    // Of the last uploaded fields (render/graph/UniformMedium.h).
    bool uniformIndex_ = false, uniformMedium_ = false;
    std::unique_ptr<ErrorEstimateStage> errorEstimate_;
    PhotonSettings photonSettings_;

    std::uint64_t tracedIndexVersion_ = ~0ull, tracedExtinctionVersion_ = ~0ull, tracedScatteringVersion_ = ~0ull,
                  tracedSurfaceVersion_ = ~0ull;
    bool cameraChanged_ = true;
    bool lightsChanged_ = false;
    bool exposureChanged_ = false;
    UploadBytes pendingUpload_;  // uploaded while constructing, reported with the first frame
    bool temporalMean_ = true;
    std::vector<std::string> imageSpaceDropped_;  // what of the scene image space does not show
    FrameResult last_;
};

}  // namespace eikon::render
