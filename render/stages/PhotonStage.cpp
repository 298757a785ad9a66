#include "render/stages/PhotonStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "render/gl/GlDebug.h"
#include "render/gl/ShaderLibrary.h"
#include "render/stages/PhotonEmission.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace eikon::render {

namespace {

constexpr std::size_t kBatchPhotons = std::size_t{1} << 20;

Rgb tallyOf(const layout::GpuPhotonStats& gpu, layout::PowerTally tally, const Rgb& unit) {
    Rgb watts;
    for (int c = 0; c < 3; ++c) {
        const std::uint64_t units = (std::uint64_t{gpu.power[tally][c][1]} << 32) | gpu.power[tally][c][0];
        watts[c] = static_cast<double>(units) * unit[c];
    }
    return watts;
}

}  // namespace

double PhotonStats::balanceError() const {
    const Rgb accounted = absorbed + escaped + received + cutOff + blocked;
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        if (emitted[c] > 0.0) worst = std::max(worst, std::abs(emitted[c] - accounted[c]) / emitted[c]);
    return worst;
}

unsigned defaultMaxSteps(const GridSpec& grid, double stepLength) {
    const glm::dvec3 extent = grid.extent();
    return static_cast<unsigned>(std::ceil(4.0 * (extent.x + extent.y + extent.z) / stepLength));
}

PhotonStage::PhotonStage(const Scene& scene, const FieldTextures& fields, ReceiverMaps& receivers,
                         int recordPathVertices, int recordedPhotons)
    : receivers_(receivers) {
    gl::ShaderDefines defines{{"EIKON_HAS_EXTINCTION", fields.hasExtinction() ? "1" : "0"},
                              {"EIKON_HAS_SCATTERING", fields.hasScattering() ? "1" : "0"},
                              {"EIKON_RECORD_PATHS", std::to_string(recordPathVertices)},
                              {"EIKON_RECORDED_PHOTONS", std::to_string(recordedPhotons)}};
    program_ = gl::compileComputeProgram("photon_trace.comp", defines);
    const auto emitters = buildEmitters(scene.lights, emissionRegion(scene), scene.render.photons);
    for (const auto& emitter : emitters)
        for (int c = 0; c < 3; ++c) powerUnit_[c] = std::max(powerUnit_[c], emitter.photonPower[c]);
    for (int c = 0; c < 3; ++c)
        powerUnit_[c] = std::max(powerUnit_[c] / static_cast<float>(layout::kPowerUnitsPerPhoton), 1e-38f);
    emitterCount_ = static_cast<unsigned>(emitters.size());
    emitters_ = gl::Buffer(emitters.size() * sizeof(layout::GpuEmitter), emitters.data());
    if (fields.hasScattering()) fluence_ = gl::Buffer(3 * fields.grid().cellCount() * sizeof(float));
    stats_ = gl::Buffer(sizeof(layout::GpuPhotonStats));
    paths_ = gl::Buffer(static_cast<std::size_t>(recordPathVertices) * static_cast<std::size_t>(recordedPhotons) *
                        sizeof(glm::vec4));
}

PhotonStats PhotonStage::run(const FieldTextures& fields, const PhotonSettings& settings) {
    fields.bindForTracing();
    receivers_.bind();
    receivers_.clear();
    emitters_.bindStorage(layout::kEmitters);
    stats_.clearToZero();
    stats_.bindStorage(layout::kPhotonStats);
    paths_.clearToZero();
    paths_.bindStorage(layout::kPhotonPaths);
    if (fields.hasScattering()) {
        fluence_.clearToZero();
        fluence_.bindStorage(layout::kFluence);
    }
    program_.use();
    glUniform1ui(program_.uniform("emitter_count"), emitterCount_);
    glUniform1ui(program_.uniform("receiver_count"), receivers_.count());
    glUniform1ui(program_.uniform("seed"), settings.seed);
    glUniform1f(program_.uniform("step_length"), static_cast<float>(settings.stepLength));
    glUniform1ui(program_.uniform("max_steps"), settings.maxSteps);
    glUniform1f(program_.uniform("power_cutoff"), static_cast<float>(settings.powerCutoff));
    glUniform3f(program_.uniform("power_unit"), powerUnit_.r, powerUnit_.g, powerUnit_.b);
    const auto total = static_cast<std::size_t>(settings.photons);
    for (std::size_t offset = 0; offset < total; offset += kBatchPhotons) {
        const std::size_t batch = std::min(kBatchPhotons, total - offset);
        glUniform1ui(program_.uniform("photon_offset"), static_cast<GLuint>(offset));
        glUniform1ui(program_.uniform("batch_size"), static_cast<GLuint>(batch));
        program_.dispatchCovering(batch, 1, 1, 64, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    gl::checkpoint("photon stage");

    const auto gpu = stats_.downloadAs<layout::GpuPhotonStats>();
    PhotonStats stats;
    const Rgb unit(powerUnit_);
    stats.emitted = tallyOf(gpu, layout::kEmitted, unit);
    stats.absorbed = tallyOf(gpu, layout::kAbsorbed, unit);
    stats.escaped = tallyOf(gpu, layout::kEscaped, unit);
    stats.received = tallyOf(gpu, layout::kReceived, unit);
    stats.cutOff = tallyOf(gpu, layout::kCutOff, unit);
    stats.blocked = tallyOf(gpu, layout::kBlocked, unit);
    stats.photonsEscaped = gpu.photons.x;
    stats.photonsReceived = gpu.photons.y;
    stats.photonsCutOff = gpu.photons.z;
    stats.photonsBlocked = gpu.photons.w;
    stats.steps = (std::uint64_t{gpu.steps.y} << 32) | gpu.steps.x;
    float maxError = 0.0f;
    std::memcpy(&maxError, &gpu.steps.z, sizeof maxError);
    stats.maxInvariantError = maxError;
    return stats;
}

std::vector<glm::vec4> PhotonStage::downloadPaths() const {
    std::vector<glm::vec4> vertices(paths_.bytes() / sizeof(glm::vec4));
    if (!vertices.empty()) paths_.download(vertices.data(), vertices.size() * sizeof(glm::vec4));
    return vertices;
}

}  // namespace eikon::render
