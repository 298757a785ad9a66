// eikon::Renderer's state (include/eikon/eikon.h), shared by the renderer
// (Renderer.cpp) and the view that re-renders it as the user moves the
// camera (View.cpp).
#pragma once

#include "eikon/eikon.h"

#include "apps/common/FrameSource.h"
#include "apps/library/GpuFieldPass.h"
#include "gl/GlContext.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace eikon {

// The optional fields a frame renderer's stages are made for (their
// textures and programs): a frame that adds or drops one needs another.
using FieldLayout = std::tuple<bool, bool, bool, bool>;

struct Renderer::Impl {
    // The context outlives everything that holds GL objects.
    std::shared_ptr<gl::GlContext> context;
    Scene scene;
    // The scene as the frame renderer sees it: the caller's fields are an
    // imported volume to it, which may fill the whole grid (the region
    // photons are sent toward, render/stages/PhotonEmission.h), as a
    // volume file's would.
    Scene renderScene;
    std::unique_ptr<sim::SceneFields> fields;
    // Made at the first render, for the fields' layout then; made again
    // where a frame changes it.
    std::unique_ptr<app::FrameSource> source;
    FieldLayout sourceLayout{};
    bool fieldsRendered = true;  // false after a refusal that left refused fields (SceneFields::writeCallerFields)
    std::optional<render::FrameResult> last;
    std::string report;
    int frame = -1;
    std::uint64_t copiedBytes = 0;  // of the caller's fields for the frame to render
    double takeMs = 0.0;            // checking and mapping them
    std::vector<std::string> given;  // their names
    // The GPU path: the caller's buffers taken (δn mapped by the pass; κ,
    // σs where they lie), and the version their textures take them as — a
    // range of its own, so that each setFields naming them uploads them
    // anew (render/stages/FieldTextures.h).
    std::unique_ptr<library::GpuFieldPass> gpuPass;  // made at the first buffer
    library::GpuFieldPass::Taken onGpu;
    std::uint64_t bufferVersion = std::uint64_t{1} << 63;
    // κ and σs in GL buffers stand on the host as zeros (the medium has
    // none there), so that the frame keeps their textures.
    std::vector<float> noCoefficients;

    explicit Impl(Scene parsed);
    ~Impl() {
        if (context) context->makeCurrent();  // GL objects go with their context current
        source.reset();
        fields.reset();
    }

    // The view's changes (eikon::View), kept in renderScene so that a frame
    // renderer made again keeps them: the camera, the lights, exposure and photon count,
    // and the pixel stride of its preview (apps/viewer/ViewPreview.h). The
    // frame renderer takes them with the renderers' context current (no
    // window's may be: eikon::View releases its own first).
    void setCamera(const CameraDesc& camera) {
        renderScene.camera = camera;
        if (source) context->makeCurrent(), source->renderer().setCamera(camera);
    }
    void setLight(std::size_t index, const LightDesc& light) {
        renderScene.lights[index] = light;
        if (source) context->makeCurrent(), source->renderer().setLight(index, light);
    }
    void setExposure(double exposureEv) {
        renderScene.render.exposureEv = exposureEv;
        if (source) context->makeCurrent(), source->renderer().setExposure(exposureEv);
    }
    void setPhotonCount(long long photons) {
        renderScene.render.photons = photons;
        if (source) context->makeCurrent(), source->renderer().setPhotonCount(photons);
    }
    int pixelStride = 1;
    void setPixelStride(int stride) {
        pixelStride = stride;
        if (source) context->makeCurrent(), source->renderer().setPixelStride(stride);
    }

    const render::FrameResult& lastFrame() const {
        if (!last) throw Error("eikon::Renderer: no frame rendered yet (call render())");
        return *last;
    }
};

}  // namespace eikon
