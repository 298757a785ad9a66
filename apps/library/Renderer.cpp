// eikon::Renderer (include/eikon/eikon.h): the frame of `eikon run` — the
// scene's fields (sim::SceneFields) through the frame source it shares
// with the viewer (apps/common/FrameSource.h) into the frame renderer —
// with the caller as the producer of the fields, in the place of a volume
// file (SceneFields::writeCallerFields).
#include "eikon/eikon.h"

#include "apps/common/FrameReport.h"
#include "apps/common/FrameSource.h"
#include "apps/library/FieldIntake.h"
#include "apps/library/RendererImpl.h"
#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"
#include "gl/GlContext.h"
#include "gl/GpuMemory.h"
#include "io/scene/SceneParser.h"
#include "render/graph/MemoryEstimate.h"
#include "render/stages/FieldTextures.h"
#include "sim/SceneFields.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <optional>
#include <tuple>

namespace eikon {

namespace {

// Runs `work`; eikon's own refusals leave as eikon::Error with their words.
template <typename Work>
auto refusalsAsErrors(Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const InputError& error) {
        throw Error(error.what());
    } catch (const NumericalBreakdown& error) {
        throw Error(error.what());
    } catch (const gl::GpuMemoryError& error) {
        throw Error(error.what());
    }
}

FieldLayout layoutOf(const FieldSet& fields) {
    return {fields.hasExtinction(), fields.hasScattering(), fields.hasAnisotropy(), fields.hasEmission()};
}

// One OpenGL context for every renderer of the process, made with the
// first and ended with the last: a headless context's end terminates its
// EGL display (gl/EglContext.cpp), which every context made on it shares.
std::shared_ptr<gl::GlContext> sharedContext() {
    static std::weak_ptr<gl::GlContext> shared;
    std::shared_ptr<gl::GlContext> context = shared.lock();
    if (context) return context;
    try {
        context = gl::createHeadlessContext();
    } catch (const std::runtime_error& error) {
        throw Error(std::string("eikon::Renderer: no OpenGL 4.5 context: ") + error.what());
    }
    shared = context;
    return context;
}

// The caller's temperature against the unit it is read in (`optics`: the
// scene's volume keys with the declared unit), as the scene parser and the
// optics check a volume file's: a scale only above ambient, and no absolute
// temperature read as above ambient by default (a GL buffer's smallest
// nonzero sample where all are as large, from the GPU pass).
void checkTemperatureUnit(const VolumeDesc& optics, const library::FieldIntake& intake,
                          std::optional<float> smallestOnGpu) {
    const std::string field = "eikon::Renderer::setFields: field \"temperature\": expected ";
    if (intake.temperatureUnit && optics.temperatureUnit != VolumeDesc::TemperatureUnit::KelvinAboveAmbient &&
        optics.temperatureScale != 1.0)
        throw Error(field + "no volume.temperature_scale with an absolute unit (it scales a temperature above "
                            "ambient), found the scene's temperature_scale " + formatRounded(optics.temperatureScale));
    const bool readAboveAmbient =
        optics.implicitTemperatureUnit && optics.temperatureUnit == VolumeDesc::TemperatureUnit::KelvinAboveAmbient;
    if (const std::optional<float> smallest =
            readAboveAmbient && smallestOnGpu ? smallestOnGpu : sim::absoluteLookingTemperature(optics, intake.samples))
        throw Error(field + "a temperature above ambient (read so without a declared unit), within " +
                    formatRounded(sim::kAbsoluteTemperatureLooking) +
                    " K of 0 somewhere; for an absolute temperature declare its unit \"kelvin\" or \"celsius\" "
                    "(eikon::Field::unit; temperature_unit= in Python), found every nonzero value at least " +
                    formatRounded(*smallest) + " (an absolute temperature?)");
}

FloatArray rgbOf(const std::vector<float>& rgba, std::size_t height, std::size_t width, const std::string& unit) {
    FloatArray array{{height, width, 3}, std::vector<float>(height * width * 3), unit};
    for (std::size_t p = 0; p < height * width; ++p)
        for (std::size_t c = 0; c < 3; ++c) array.values[3 * p + c] = rgba[4 * p + c];
    return array;
}

}  // namespace

Renderer::Impl::Impl(Scene parsed) : scene(std::move(parsed)) {
    if (scene.sim)
        throw InputError(scene.sourcePath + ": sim",
                         "no `sim` section in a scene whose fields the library's caller hands in "
                         "(the solver would make its own)",
                         "a sim section");
    if (scene.volume) sim::checkVolumeFrames(*scene.volume, scene.grid.spec(), 1, scene.sourcePath);
    render::requireMemoryFits(scene);
    fields = std::make_unique<sim::SceneFields>(scene);
    renderScene = scene;
    if (!renderScene.volume) renderScene.volume = VolumeDesc{};
    context = sharedContext();
    context->makeCurrent();
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Renderer Renderer::fromFile(const std::string& path) {
    return refusalsAsErrors([&] { return Renderer(std::make_unique<Impl>(loadSceneFile(path))); });
}

Renderer Renderer::fromJson(const std::string& json, const std::string& folder) {
    return refusalsAsErrors([&] {
        const std::string source = (std::filesystem::path(folder) / "scene (JSON text)").string();
        return Renderer(std::make_unique<Impl>(parseSceneText(json, source)));
    });
}

void Renderer::makeContextCurrent() const { impl_->context->makeCurrent(); }

Grid Renderer::grid() const {
    const GridSpec spec = impl_->scene.grid.spec();
    return {{spec.resolution.x, spec.resolution.y, spec.resolution.z},
            {spec.boundsMin.x, spec.boundsMin.y, spec.boundsMin.z},
            {spec.boundsMax.x, spec.boundsMax.y, spec.boundsMax.z}};
}

void Renderer::setFields(const std::vector<Field>& fields) {
    Impl& impl = *impl_;
    const auto start = std::chrono::steady_clock::now();
    library::FieldIntake intake = library::takeFields(fields, impl.scene.grid.spec());
    const VolumeDesc optics = impl.fields->callerOptics(intake.temperatureUnit);
    library::GpuFieldPass::Taken onGpu;
    if (!intake.buffers.empty()) {
        impl.context->makeCurrent();
        if (!impl.gpuPass)
            impl.gpuPass = std::make_unique<library::GpuFieldPass>(impl.scene, impl.fields->fields().referenceIndex);
        onGpu = refusalsAsErrors([&] { return impl.gpuPass->take(intake.buffers, optics); });
    }
    checkTemperatureUnit(optics, intake, onGpu.absoluteLookingTemperature);
    if (onGpu.extinction || onGpu.scattering) {
        impl.noCoefficients.resize(3 * impl.scene.grid.spec().cellCount());
        if (onGpu.extinction) intake.samples.extinction = impl.noCoefficients;
        if (onGpu.scattering) intake.samples.scattering = impl.noCoefficients;
    }
    const FieldSet& current = impl.fields->fields();
    const auto versions = [&] {
        return std::tuple{current.indexVersion, current.extinctionVersion, current.scatteringVersion};
    };
    const auto before = versions();
    try {
        refusalsAsErrors(
            [&] {
                impl.fields->writeCallerFields(intake.samples, "the fields handed to eikon::Renderer::setFields",
                                               intake.temperatureUnit);
            });
    } catch (const Error&) {
        // A refusal after the mapping (of the objects composited over it)
        // leaves the refused fields, which no frame renders.
        if (versions() != before) impl.fieldsRendered = false;
        throw;
    }
    impl.fieldsRendered = true;
    impl.copiedBytes = intake.copiedBytes;
    impl.given = intake.names;
    if (impl.gpuPass) impl.gpuPass->keep();
    impl.onGpu = onGpu;
    if (!intake.buffers.empty()) ++impl.bufferVersion;
    impl.takeMs = app::millisecondsSince(start);
}

void Renderer::render() {
    Impl& impl = *impl_;
    if (!impl.fieldsRendered)
        throw Error("eikon::Renderer::render: expected fields to render, found the last ones refused (hand in others)");
    refusalsAsErrors([&] {
        impl.context->makeCurrent();
        const FieldLayout layout = layoutOf(impl.fields->fields());
        if (!impl.source || layout != impl.sourceLayout) {
            render::RendererOptions options;
            options.estimateErrors = impl.scene.render.errorEstimate;  // as `eikon run` (apps/eikon/FrameExport.h)
            impl.source.reset();
            impl.source =
                std::make_unique<app::FrameSource>(impl.renderScene, *impl.fields, options, false, app::ExportNeeds());
            impl.sourceLayout = layout;
            if (impl.pixelStride != 1) impl.source->renderer().setPixelStride(impl.pixelStride);
        }
        const auto start = std::chrono::steady_clock::now();
        const library::GpuFieldPass::Taken& onGpu = impl.onGpu;
        if (onGpu.deltaIndex || onGpu.extinction || onGpu.scattering) {
            // The host fields but those in GL buffers, which the textures copy on the GPU.
            render::FieldUpload upload = render::hostUpload(impl.fields->fields());
            const std::size_t cells = impl.scene.grid.spec().cellCount();
            if (onGpu.deltaIndex) {
                upload.deltaIndex = {nullptr, onGpu.deltaIndex, cells};
                upload.indexVersion = impl.bufferVersion;
            }
            if (onGpu.extinction) {
                upload.extinction = {nullptr, onGpu.extinction, 3 * cells};
                upload.extinctionVersion = impl.bufferVersion;
            }
            if (onGpu.scattering) {
                upload.scattering = {nullptr, onGpu.scattering, 3 * cells};
                upload.scatteringVersion = impl.bufferVersion;
            }
            impl.last = impl.source->renderer().render(upload);
        } else {
            impl.last = impl.source->render();
        }
        const double renderMs = app::renderMilliseconds(*impl.last);
        const app::LoopTiming timing{app::millisecondsSince(start), renderMs, 0.0};
        ++impl.frame;
        // eikon run's report line with the caller's fields as its last key,
        // spliced in rather than parsed and written again.
        impl.report = app::frameReportJson(impl.frame, impl.source->current(), false, *impl.last, timing, false);
        const nlohmann::json caller{
            {"names", impl.given}, {"host_bytes_copied", impl.copiedBytes}, {"set_fields_ms", impl.takeMs}};
        impl.report.pop_back();  // its closing brace
        impl.report += ",\"caller_fields\":" + caller.dump() + "}";
        impl.copiedBytes = 0;
        impl.takeMs = 0.0;
        impl.given.clear();
    });
}

ByteArray Renderer::image() const {
    const render::Image8& image = impl_->lastFrame().image;
    const auto height = static_cast<std::size_t>(image.height), width = static_cast<std::size_t>(image.width);
    ByteArray array{{height, width, 3}, std::vector<std::uint8_t>(height * width * 3)};
    for (std::size_t p = 0; p < height * width; ++p)
        for (std::size_t c = 0; c < 3; ++c) array.values[3 * p + c] = image.rgba[4 * p + c];
    return array;
}

FloatArray Renderer::radiance() const {
    const render::FrameResult& frame = impl_->lastFrame();
    impl_->context->makeCurrent();
    const render::FrameRenderer& renderer = impl_->source->renderer();
    const std::vector<float> rgba = !frame.hdr.empty()               ? frame.hdr
                                    : renderer.diagnosticStage()     ? renderer.diagnosticStage()->downloadHdr()
                                    : renderer.imageSpaceView()      ? renderer.imageSpaceView()->downloadHdr()
                                                                     : renderer.viewStage().downloadHdr();
    return rgbOf(rgba, static_cast<std::size_t>(frame.image.height), static_cast<std::size_t>(frame.image.width),
                 renderer.diagnosticStage() ? "1 (I/I0)" : "W/(m^2 sr)");
}

std::size_t Renderer::receiverCount() const { return impl_->scene.receivers.size(); }

FloatArray Renderer::receiver(std::size_t r) const {
    impl_->lastFrame();
    if (r >= receiverCount())
        throw Error("eikon::Renderer::receiver: expected a receiver index below " + std::to_string(receiverCount()) +
                    ", found " + std::to_string(r));
    impl_->context->makeCurrent();
    const render::ReceiverMaps& maps = impl_->source->renderer().receivers();
    const auto texels = static_cast<std::size_t>(maps.receiver(static_cast<unsigned>(r)).map.y);
    return {{texels, texels, 3}, maps.download(static_cast<unsigned>(r)), "W/m^2"};
}

FloatArray Renderer::fluence() const {
    impl_->lastFrame();
    const render::PhotonStage* photons = impl_->source->renderer().photonStage();
    if (!photons || !photons->storesFluence())
        throw Error("eikon::Renderer::fluence: expected a scene that keeps the fluence (a scattering medium, or "
                    "export.vtk asking for it), found none kept");
    impl_->context->makeCurrent();
    const Grid g = grid();
    return {{static_cast<std::size_t>(g.cells[2]), static_cast<std::size_t>(g.cells[1]),
             static_cast<std::size_t>(g.cells[0]), 3},
            photons->downloadFluence(),
            "W/m^2"};
}

std::string Renderer::report() const {
    impl_->lastFrame();
    return impl_->report;
}

}  // namespace eikon
