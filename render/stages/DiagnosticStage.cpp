#include "render/stages/DiagnosticStage.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlContext.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/PhotonStage.h"
#include "render/stages/DiagnosticNodeSteps.h"
#include "render/stages/GaussianKernel.h"
#include "render/stages/PixelSamples.h"
#include "render/stages/ViewStage.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace eikon::render {

namespace {

// EIKON_INSTRUMENT of shaders/common/diagnostic_instruments.glsl.
enum class Instrument : int {
    Interferometer = 0,
    KnifeEdge = 1,
    CircularFilter = 2,
    ColourFilter = 3,
    Shadowgraph = 4,
    BackgroundOriented = 5
};

Instrument instrumentOf(const DiagnosticDesc& diagnostic) {
    if (diagnostic.type == DiagnosticDesc::Type::Interferometry) return Instrument::Interferometer;
    if (diagnostic.type == DiagnosticDesc::Type::Shadowgraph) return Instrument::Shadowgraph;
    if (diagnostic.type == DiagnosticDesc::Type::Bos) return Instrument::BackgroundOriented;
    switch (diagnostic.cutoff) {
        case DiagnosticDesc::Cutoff::KnifeEdge: return Instrument::KnifeEdge;
        case DiagnosticDesc::Cutoff::Circular: return Instrument::CircularFilter;
        case DiagnosticDesc::Cutoff::Colour: return Instrument::ColourFilter;
    }
    return Instrument::KnifeEdge;
}

// BOS's background image, repeated both ways across the plane.
gl::Texture2D patternTexture(const FloatImage& image) {
    GLint largest = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
    if (image.width > largest || image.height > largest)
        throw InputError("diagnostic.pattern",
                         "an image at most " + std::to_string(largest) + " pixels a side (GL_MAX_TEXTURE_SIZE)",
                         std::to_string(image.width) + " × " + std::to_string(image.height));
    gl::Texture2D texture(image.width, image.height, image.rgba.data(), {"diagnostic.pattern", "the BOS background"});
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    return texture;
}

}  // namespace

DiagnosticStage::DiagnosticStage(const Scene& scene, const FieldTextures& fields, TracerDesc::Integrator integrator)
    : render_(scene.render), diagnostic_(scene.diagnostic.value_or(DiagnosticDesc{})), cameraDesc_(scene.camera),
      grid_(fields.grid()), surfaces_(scene), sampleSide_(sampleGridSide(scene.render.samplesPerPixel)),
      // A voxel's δn reaches as far as the smoothing carries it, one voxel
      // more by the central differences, and the trilinear filter reads it
      // up to a voxel from its centre; one voxel more for rounding.
      varyingReach_(static_cast<double>(
                        gaussianHalfKernel(scene.grid.smoothingSigmaVoxels, scene.grid.smoothingWindowVoxels).size()) -
                    1 + 1 + 1.5 + 1),
      varyingLow_(grid_.boundsMin), varyingHigh_(grid_.boundsMax),
      nodeSteps_(integrator == TracerDesc::Integrator::Leapfrog), nodeEpsilon_(scene.tracer.epsilon),
      extinctionChannels_(fields.hasExtinction() ? 3 : 1), screenChannels_(extinctionChannels_) {
    EIKON_CHECK_MSG(sampleSide_ > 0, "render.samples_per_pixel a square (io/scene/SceneParser)");
    const bool bos = diagnostic_.type == DiagnosticDesc::Type::Bos;
    EIKON_CHECK_MSG(scene.diagnostic && scene.camera.orthographic() != bos,
                    "BOS looks through a perspective camera, the other diagnostics through an orthographic one "
                    "(io/scene/DiagnosticParser)");
    stepLength_ = scene.render.stepVoxels * fields.grid().smallestVoxelEdge();
    maxSteps_ = defaultMaxSteps(fields.grid(), stepLength_);
    EIKON_CHECK_MSG(integrator != TracerDesc::Integrator::Euler, "a diagnostic marches by leapfrog or RK4");
    const std::string loopBudget = std::to_string(gl::currentLoopBudget());
    program_ = gl::compileComputeProgram(
        "diagnostic_rays.comp", {{"EIKON_INSTRUMENT", std::to_string(static_cast<int>(instrumentOf(diagnostic_)))},
                                 {"EIKON_HAS_EXTINCTION", fields.hasExtinction() ? "1" : "0"},
                                 {"EIKON_BOS_IMAGE", diagnostic_.patternImage ? "1" : "0"},
                                 {"EIKON_INTEGRATOR", integrator == TracerDesc::Integrator::Rk4 ? "2" : "1"},
                                 {"EIKON_NODE_STEPS", nodeSteps_ ? "1" : "0"},
                                 {"EIKON_BRICK_VOXELS", std::to_string(BrickRanges::kVoxels)},
                                 surfaces_.kindsOption(),
                                 {"EIKON_LOOP_BUDGET", loopBudget}});
    const layout::GpuCamera block = cameraBlock(scene.camera, scene.render);
    camera_ = gl::Buffer(sizeof block, &block, GL_DYNAMIC_STORAGE_BIT);
    const auto width = static_cast<std::size_t>(render_.width), height = static_cast<std::size_t>(render_.height);
    if (diagnostic_.type == DiagnosticDesc::Type::Shadowgraph) {
        // Without extinction T = 1 in every channel, and the screen tallies one.
        const std::string extinction = fields.hasExtinction() ? "1" : "0";
        deposit_ = gl::compileComputeProgram(
            "shadowgraph_screen.comp",
            {{"EIKON_SCREEN_PASS", "0"}, {"EIKON_HAS_EXTINCTION", extinction}, {"EIKON_LOOP_BUDGET", loopBudget}});
        resolve_ = gl::compileComputeProgram("shadowgraph_screen.comp",
                                             {{"EIKON_SCREEN_PASS", "1"}, {"EIKON_HAS_EXTINCTION", extinction}});
        const std::size_t corners = beamCorners(width, sampleSide_) * beamCorners(height, sampleSide_);
        rays_ = gl::Buffer(corners * sizeof(glm::vec4),
                           gl::GpuResource{"render.width × render.height", "the shadowgraph's rays"});
        landing_ = gl::Buffer(2 * corners * sizeof(glm::vec4),
                              gl::GpuResource{"render.width × render.height", "where the shadowgraph's rays land"});
        screen_ = gl::Buffer(6 * width * height * sizeof(std::uint32_t),
                             gl::GpuResource{"render.width × render.height", "the shadowgraph's screen"});
    } else {
        rays_ = pixelBuffer(scene, "the diagnostic's measurements");
    }
    if (bos) {
        landing_ = pixelBuffer(scene, "the background's displacement");
        reference_ = gl::Buffer(width * height * 4,
                                gl::GpuResource{"render.width × render.height", "the background without the medium"});
        // The background's height as the scene's camera sees it.
        const double seen = planeDepth(scene.camera) * 2.0 * std::tan(glm::radians(scene.camera.fovDeg) / 2);
        // Three pixels' width.
        dotDiameter_ = diagnostic_.dotDiameter.value_or(3.0 * seen / static_cast<double>(render_.height));
        if (const FloatImage* image = diagnostic_.patternImage.get()) {
            pattern_ = patternTexture(*image);
            const double aspect = static_cast<double>(render_.width) / static_cast<double>(render_.height);
            const double patternWidth = diagnostic_.patternWidth.value_or(seen * aspect);
            patternSize_ = {patternWidth, patternWidth * image->height / image->width};
        }
    }
    hdr_ = pixelBuffer(scene, "the diagnostic's linear picture");
    ldr_ = gl::Buffer(static_cast<std::size_t>(render_.width) * static_cast<std::size_t>(render_.height) * 4,
                      gl::GpuResource{"render.width × render.height", "the diagnostic's picture"});
}

void DiagnosticStage::setCamera(const CameraDesc& camera) {
    const layout::GpuCamera block = cameraBlock(camera, render_);
    camera_.upload(&block, sizeof block);
    cameraDesc_ = camera;
}

void DiagnosticStage::setVaryingVoxels(const VaryingVoxels& varying) {
    screenChannels_ = varying.greyExtinction ? 1 : extinctionChannels_;
    uniformDelta_ = varying.uniformDelta;
    uniformExtinction_ = varying.uniformExtinction;
    nodeLevelsSet_ = nodeSteps_ && !varying.bricks.empty();
    if (nodeLevelsSet_) {
        const glm::ivec3 count = varying.bricks.count;
        if (!nodeLevels_.id())
            nodeLevels_ = gl::Texture3D(GL_R32F, count.x, count.y, count.z,
                                        gl::gridResource("the diagnostic's nearly uniform nodes", count.x, count.y, count.z));
        const std::vector<float> levels = nearlyUniformNodeLevels(varying.bricks, varyingReach_, nodeEpsilon_);
        nodeLevels_.upload(GL_RED, GL_FLOAT, levels.data());
    }
    if (!surfaces_.empty()) {  // sharp surfaces bend rays wherever they lie: the march covers the grid
        varyingLow_ = glm::vec3(grid_.boundsMin);
        varyingHigh_ = glm::vec3(grid_.boundsMax);
        return;
    }
    if (varying.box.empty()) {  // a uniform medium: every ray crosses straight
        varyingLow_ = glm::vec3(grid_.boundsMax);
        varyingHigh_ = glm::vec3(grid_.boundsMin);
        return;
    }
    const double reach = varyingReach_;
    const glm::dvec3 h = grid_.voxelSize();
    varyingLow_ = glm::vec3(glm::max(grid_.boundsMin, grid_.boundsMin + (glm::dvec3(varying.box.lowest) - reach) * h));
    varyingHigh_ =
        glm::vec3(glm::min(grid_.boundsMax, grid_.boundsMin + (glm::dvec3(varying.box.highest) + 1.0 + reach) * h));
}

void DiagnosticStage::setPixelStride(int stride) {
    EIKON_CHECK_MSG(stride >= 1, "a pixel stride of at least 1");
    pixelStride_ = stride;
}

std::size_t DiagnosticStage::beamCorners(std::size_t pixels, int side) {
    return static_cast<std::size_t>(side) * (pixels + 2 * kBeamMargin) + 1;
}

double DiagnosticStage::planeDepth(const CameraDesc& camera) const {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    double farthest = -std::numeric_limits<double>::infinity();
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 point((corner & 1) ? grid_.boundsMax.x : grid_.boundsMin.x,
                               (corner & 2) ? grid_.boundsMax.y : grid_.boundsMin.y,
                               (corner & 4) ? grid_.boundsMax.z : grid_.boundsMin.z);
        farthest = std::max(farthest, glm::dot(point - camera.position, forward));
    }
    const double distance = diagnostic_.type == DiagnosticDesc::Type::Bos ? diagnostic_.backgroundDistance
                                                                          : diagnostic_.screenDistance;
    return farthest + distance;
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
    if (!surfaces_.empty()) {
        surfaces_.bind();
        glUniform1ui(program_.uniform("sharp_surface_count"), surfaces_.count());
    }
    glUniform3f(program_.uniform("varying_low"), varyingLow_.x, varyingLow_.y, varyingLow_.z);
    glUniform3f(program_.uniform("varying_high"), varyingHigh_.x, varyingHigh_.y, varyingHigh_.z);
    glUniform1f(program_.uniform("uniform_delta"), uniformDelta_);
    if (nodeSteps_) {
        glUniform1ui(program_.uniform("node_steps"), nodeLevelsSet_ ? 1u : 0u);
        if (nodeLevelsSet_) nodeLevels_.bindSampler(layout::kStepTexture);
    }
    glUniform3f(program_.uniform("uniform_extinction"), uniformExtinction_.x, uniformExtinction_.y,
                uniformExtinction_.z);
    const auto width = static_cast<std::size_t>(render_.width), height = static_cast<std::size_t>(render_.height);
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
        case Instrument::ColourFilter: glUniform1f(program_.uniform("sensitivity"), static_cast<float>(sensitivity)); break;
        case Instrument::Shadowgraph:
            glUniform1f(program_.uniform("plane_depth"), static_cast<float>(planeDepth(cameraDesc_)));
            glUniform1ui(program_.uniform("beam_margin"), kBeamMargin);
            glUniform1ui(program_.uniform("beam_subdivision"), static_cast<GLuint>(drawnSide()));
            landing_.bindStorage(layout::kDiagnosticLanding);
            break;
        case Instrument::BackgroundOriented: {
            glUniform1f(program_.uniform("plane_depth"), static_cast<float>(planeDepth(cameraDesc_)));
            if (pattern_.id()) {
                pattern_.bindSampler(layout::kBackgroundPatternTexture);
                glUniform2f(program_.uniform("pattern_size"), static_cast<float>(patternSize_.x),
                            static_cast<float>(patternSize_.y));
            } else {
                // One dot a cell: its share of the cell's area π·d²/4 / cell² is the dot density.
                const double cell = 0.5 * dotDiameter_ * std::sqrt(std::numbers::pi / diagnostic_.dotDensity);
                glUniform1ui(program_.uniform("dot_seed"), diagnostic_.seed);
                glUniform1f(program_.uniform("dot_cell"), static_cast<float>(cell));
                glUniform1f(program_.uniform("dot_diameter"), static_cast<float>(dotDiameter_));
            }
            landing_.bindStorage(layout::kDiagnosticLanding);
            reference_.bindStorage(layout::kDiagnosticReference);
            break;
        }
    }
    if (instrumentOf(diagnostic_) == Instrument::Shadowgraph) {
        const std::size_t cornersX = beamCorners(width, drawnSide()), cornersY = beamCorners(height, drawnSide());
        program_.dispatchCovering(cornersX, cornersY);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        screen_.clearToZero();
        screen_.bindStorage(layout::kDiagnosticScreen);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        deposit_.use();
        glUniform1ui(deposit_.uniform("beam_margin"), kBeamMargin);
        glUniform1ui(deposit_.uniform("beam_subdivision"), static_cast<GLuint>(drawnSide()));
        glUniform1i(deposit_.uniform("tallied_channels"), screenChannels_);
        deposit_.dispatchCovering(cornersX - 1, cornersY - 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        resolve_.use();
        glUniform1i(resolve_.uniform("tallied_channels"), screenChannels_);
        resolve_.dispatchCovering(width, height);
    } else {
        // k² passes, one ray a pixel each, averaged as the view's are; or
        // one pass of a ray a block, through the middle of its middle pixel.
        const int side = drawnSide();
        const std::size_t stride = static_cast<std::size_t>(pixelStride_);
        glUniform1ui(program_.uniform("pixel_stride"), static_cast<GLuint>(stride));
        for (int cell = 0; cell < side * side; ++cell) {
            const glm::vec2 offset = gridSampleOffset(cell, side);
            glUniform2f(program_.uniform("sample_offset"), offset.x, offset.y);
            glUniform1ui(program_.uniform("samples_before"), static_cast<GLuint>(cell));
            program_.dispatchCovering((width + stride - 1) / stride, (height + stride - 1) / stride);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    Image8 image{render_.width, render_.height,
                 std::vector<std::uint8_t>(static_cast<std::size_t>(render_.width) * render_.height * 4)};
    ldr_.download(image.rgba.data(), image.rgba.size());
    gl::checkpoint("diagnostic stage");
    return image;
}

std::vector<float> DiagnosticStage::downloadHdr() const { return hdr_.downloadAll<float>(); }

std::vector<glm::vec4> DiagnosticStage::downloadRays() const { return rays_.downloadAll<glm::vec4>(); }

int DiagnosticStage::lostRays() const {
    const std::vector<glm::vec4> rays = downloadRays();
    return static_cast<int>(std::count_if(rays.begin(), rays.end(), [](const glm::vec4& ray) { return ray.w == 3.0f; }));
}

Image8 DiagnosticStage::downloadReference() const {
    EIKON_CHECK_MSG(hasReference(), "only BOS draws a reference picture");
    Image8 image{render_.width, render_.height, std::vector<std::uint8_t>(reference_.bytes())};
    reference_.download(image.rgba.data(), image.rgba.size());
    return image;
}

DiagnosticMeasurements DiagnosticStage::downloadMeasurements() const {
    DiagnosticMeasurements measured{render_.width, render_.height, {}, {}, {}, {}};
    if (diagnostic_.type == DiagnosticDesc::Type::Shadowgraph) {
        const std::vector<float> hdr = downloadHdr();
        for (std::size_t i = 0; i < hdr.size(); i += 4) measured.irradiance.insert(measured.irradiance.end(), &hdr[i], &hdr[i + 3]);
        return measured;
    }
    if (diagnostic_.type == DiagnosticDesc::Type::Bos) {
        for (const glm::vec4& moved : landing_.downloadAll<glm::vec4>()) {
            measured.displacement.push_back(moved.x);
            measured.displacement.push_back(moved.y);
        }
    }
    const std::vector<glm::vec4> rays = downloadRays();
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
