#include "render/stages/DiagnosticStage.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlContext.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/PhotonStage.h"
#include "render/stages/ViewStage.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace eikon::render {

namespace {

// EIKON_INSTRUMENT of shaders/common/diagnostic_instruments.glsl.
enum class Instrument : int { Interferometer = 0, KnifeEdge = 1, CircularFilter = 2, ColourFilter = 3 };

Instrument instrumentOf(const DiagnosticDesc& diagnostic) {
    if (diagnostic.type == DiagnosticDesc::Type::Interferometry) return Instrument::Interferometer;
    switch (diagnostic.cutoff) {
        case DiagnosticDesc::Cutoff::KnifeEdge: return Instrument::KnifeEdge;
        case DiagnosticDesc::Cutoff::Circular: return Instrument::CircularFilter;
        case DiagnosticDesc::Cutoff::Colour: return Instrument::ColourFilter;
    }
    return Instrument::KnifeEdge;
}

}  // namespace

DiagnosticStage::DiagnosticStage(const Scene& scene, const FieldTextures& fields)
    : render_(scene.render), diagnostic_(scene.diagnostic.value_or(DiagnosticDesc{})) {
    EIKON_CHECK_MSG(scene.diagnostic && scene.camera.orthographic(),
                    "a diagnostic looks through an orthographic camera (io/scene/DiagnosticParser)");
    stepLength_ = scene.render.stepVoxels * fields.grid().smallestVoxelEdge();
    maxSteps_ = defaultMaxSteps(fields.grid(), stepLength_);
    program_ = gl::compileComputeProgram(
        "diagnostic_rays.comp", {{"EIKON_INSTRUMENT", std::to_string(static_cast<int>(instrumentOf(diagnostic_)))},
                                 {"EIKON_HAS_EXTINCTION", fields.hasExtinction() ? "1" : "0"},
                                 {"EIKON_LOOP_BUDGET", std::to_string(gl::currentLoopBudget())}});
    const layout::GpuCamera block = cameraBlock(scene.camera, scene.render);
    camera_ = gl::Buffer(sizeof block, &block, GL_DYNAMIC_STORAGE_BIT);
    rays_ = pixelBuffer(scene, "the diagnostic's measurements");
    hdr_ = pixelBuffer(scene, "the diagnostic's linear picture");
    ldr_ = gl::Buffer(static_cast<std::size_t>(render_.width) * static_cast<std::size_t>(render_.height) * 4,
                      gl::GpuResource{"render.width × render.height", "the diagnostic's picture"});
}

void DiagnosticStage::setCamera(const CameraDesc& camera) {
    const layout::GpuCamera block = cameraBlock(camera, render_);
    camera_.upload(&block, sizeof block);
}

Image8 DiagnosticStage::run(const FieldTextures& fields) {
    fields.bindForTracing();
    camera_.bindUniform(layout::kCameraBlock);
    rays_.bindStorage(layout::kDiagnosticRays);
    hdr_.bindStorage(layout::kHdrImage);
    ldr_.bindStorage(layout::kLdrImage);
    program_.use();
    glUniform1f(program_.uniform("step_length"), static_cast<float>(stepLength_));
    glUniform1ui(program_.uniform("max_steps"), maxSteps_);
    const double sensitivity = diagnostic_.focalLength / diagnostic_.sourceHeight;  // f/a
    switch (instrumentOf(diagnostic_)) {
        case Instrument::Interferometer:
            glUniform1f(program_.uniform("phase_per_metre"),
                        static_cast<float>(std::numbers::pi / (diagnostic_.wavelengthNm * 1e-9)));
            glUniform1f(program_.uniform("tilt_phase"), static_cast<float>(std::numbers::pi * diagnostic_.fringeTilt));
            break;
        case Instrument::KnifeEdge: {
            // The knife's normal, 90° counter-clockwise from its edge: deflections toward it brighten.
            const double angle = glm::radians(diagnostic_.knifeAngleDeg);
            glUniform1f(program_.uniform("sensitivity"), static_cast<float>(sensitivity));
            glUniform2f(program_.uniform("knife_normal"), static_cast<float>(-std::sin(angle)),
                        static_cast<float>(std::cos(angle)));
            break;
        }
        case Instrument::CircularFilter:
        case Instrument::ColourFilter: glUniform1f(program_.uniform("sensitivity"), static_cast<float>(sensitivity));
    }
    program_.dispatchCovering(static_cast<std::size_t>(render_.width), static_cast<std::size_t>(render_.height), 1, 8,
                              8, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    Image8 image{render_.width, render_.height,
                 std::vector<std::uint8_t>(static_cast<std::size_t>(render_.width) * render_.height * 4)};
    ldr_.download(image.rgba.data(), image.rgba.size());
    gl::checkpoint("diagnostic stage");
    return image;
}

std::vector<float> DiagnosticStage::downloadHdr() const { return hdr_.downloadAll<float>(); }

std::vector<glm::vec4> DiagnosticStage::downloadRays() const { return rays_.downloadAll<glm::vec4>(); }

DiagnosticMeasurements DiagnosticStage::downloadMeasurements() const {
    const std::vector<glm::vec4> rays = downloadRays();
    DiagnosticMeasurements measured{render_.width, render_.height, {}, {}};
    measured.deflection.reserve(2 * rays.size());
    measured.opticalPathDifference.reserve(rays.size());
    for (const glm::vec4& ray : rays) {
        measured.deflection.push_back(ray.x);
        measured.deflection.push_back(ray.y);
        measured.opticalPathDifference.push_back(ray.z);
    }
    return measured;
}

}  // namespace eikon::render
