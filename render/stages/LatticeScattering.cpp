#include "render/stages/LatticeScattering.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "gl/GpuMemory.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/LatticePhase.h"
#include "shaders/common/cpp_shim.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

namespace eikon::render {

namespace {

constexpr int kLedgerValues = 8;  // per work group: source, absorbed, escaped through six faces (two vec4)

// The share of light born in a voxel of extinction σt that leaves its half
// link unscattered (collide in lattice_scattering.comp), in double.
double escapeShare(int directions, const glm::dvec3& voxelSize, double sigmaT) {
    double escape = 0.0;
    for (int i = 0; i < directions; ++i) {
        const int d = shader::lattice_link(i, directions);
        const double length = glm::length(glm::dvec3(shader::lattice_offset(d)) * voxelSize);
        escape += shader::lattice_weight(d, directions) * std::exp(-0.5 * sigmaT * length);
    }
    return escape;
}

}  // namespace

double latticeDepthLimit(int directions, const glm::dvec3& voxelSize) {
    const double edge = std::min(voxelSize.x, std::min(voxelSize.y, voxelSize.z));
    // The escape falls monotonically with σt: bisect on the depth across the shortest edge.
    double thin = 0.0, thick = 1000.0;
    for (int step = 0; step < 60; ++step) {
        const double middle = 0.5 * (thin + thick);
        (escapeShare(directions, voxelSize, middle / edge) > kMinRetention ? thin : thick) = middle;
    }
    return 0.5 * (thin + thick);
}

LatticeSettings LatticeSettings::of(const TracerDesc& tracer) {
    LatticeSettings settings;
    settings.directions = tracer.lattice.directions;
    settings.tolerance = tracer.lattice.tolerance;
    settings.maxIterations = tracer.lattice.maxIterations;
    return settings;
}

double LatticeChannel::escapedTotal() const { return std::accumulate(escaped.begin(), escaped.end(), 0.0); }

int LatticeStats::iterations() const {
    return channels[0].iterations + channels[1].iterations + channels[2].iterations;
}

bool LatticeStats::capped() const { return channels[0].capped || channels[1].capped || channels[2].capped; }

bool LatticeStats::converged() const { return !capped() && depth.thickVoxels == 0; }

double LatticeStats::balanceError() const {
    double worst = 0.0;
    for (const LatticeChannel& channel : channels)
        if (channel.source > 0.0) worst = std::max(worst, std::abs(channel.undelivered()) / channel.source);
    return worst;
}

LatticeScattering::LatticeScattering(const GridSpec& grid, const FieldTextures& fields, const LatticeSettings& settings,
                                     std::vector<layout::GpuSharpSurface> surfaces)
    : grid_(grid), settings_(settings), surfaces_(std::move(surfaces)) {
    EIKON_CHECK_MSG(settings.directions == 6 || settings.directions == 14 || settings.directions == 18,
                    "a lattice of 6, 14 or 18 links (io/scene)");
    EIKON_CHECK_MSG(fields.hasScattering(), "a lattice only where some voxel scatters (FrameRenderer)");
    const glm::ivec3 r = grid.resolution;
    const int stride = std::max(1, std::min(settings.probeStride, std::min(r.x, std::min(r.y, r.z)) / 2));
    settings_.probeStride = stride;
    probes_ = (r + stride - 1) / stride;

    const std::size_t cells = grid.cellCount();
    const std::size_t stateBytes = static_cast<std::size_t>(settings.directions) * cells * sizeof(float);
    GLint64 largestBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largestBlock);
    if (stateBytes > static_cast<std::size_t>(largestBlock))
        throw InputError("tracer.lbm_directions",
                         "a lattice whose densities of one channel fit one storage block (" +
                             std::to_string(largestBlock) + " bytes, GL_MAX_SHADER_STORAGE_BLOCK_SIZE)",
                         std::to_string(settings.directions) + " links × " + std::to_string(cells) +
                             " cells = " + std::to_string(stateBytes) + " bytes; use 6 links or a coarser grid");
    for (auto& pair : states_)
        for (gl::Buffer& state : pair) {
            state = gl::Buffer(stateBytes, gl::gridResource("the lattice's link densities", r.x, r.y, r.z));
            state.clearToZero();
        }
    fluence_ = gl::Buffer(3 * cells * sizeof(float), gl::gridResource("the multiply scattered fluence", r.x, r.y, r.z));
    fluence_.clearToZero();
    probeValues_ = gl::Buffer(static_cast<std::size_t>(probes_.x) * probes_.y * probes_.z * sizeof(float));

    directed_ = fields.hasAnisotropy();
    if (directed_) {
        birth_ = gl::Buffer(stateBytes, gl::gridResource("the lattice's birth shares", r.x, r.y, r.z));
        const std::vector<float> phase = latticePhaseTable(settings.directions, grid.voxelSize());
        phase_ = gl::Buffer(phase.size() * sizeof(float), phase.data());
    }
    const bool interfaces = !surfaces_.empty();
    if (interfaces)
        interfaces_ = gl::Buffer(cells * sizeof(glm::uvec4), gl::gridResource("the lattice's interface links", r.x, r.y, r.z));
    auto compile = [&](int pass) {
        return gl::compileComputeProgram(
            "lattice_scattering.comp", {{"EIKON_HAS_EXTINCTION", "1"},
                                        {"EIKON_HAS_SCATTERING", "1"},
                                        {"EIKON_HAS_ANISOTROPY", fields.hasAnisotropy() ? "1" : "0"},
                                        {"EIKON_LATTICE_DIRECTIONS", std::to_string(settings.directions)},
                                        {"EIKON_LATTICE_INTERFACES", interfaces ? "1" : "0"},
                                        {"EIKON_LATTICE_DIRECTED", directed_ ? "1" : "0"},
                                        {"EIKON_LATTICE_PASS", std::to_string(pass)}});
    };
    step_ = compile(0);
    probe_ = compile(1);
    result_ = compile(2);
    survey_ = compile(3);
    if (interfaces) interfacePass_ = compile(4);
    if (directed_) {
        birthPass_ = compile(5);
        birthPass_.use();
        const std::vector<float> solidAngles = latticeLinkSolidAngles(settings.directions, grid.voxelSize());
        glUniform1fv(birthPass_.uniform("link_solid_angle"), static_cast<GLsizei>(solidAngles.size()),
                     solidAngles.data());
    }
    const glm::uvec3 ledgerGroups = result_.groupsCovering(static_cast<std::size_t>(r.x), static_cast<std::size_t>(r.y),
                                                                static_cast<std::size_t>(r.z));  // one ledger a group
    tallies_ = gl::Buffer(std::size_t{ledgerGroups.x} * ledgerGroups.y * ledgerGroups.z * kLedgerValues * sizeof(float));
    surveyValues_ = gl::Buffer(sizeof(layout::GpuLatticeSurvey));
    depthLimit_ = latticeDepthLimit(settings.directions, grid.voxelSize());
}

// Which links cross a sharp surface, once a frame (a mesh may move).
void LatticeScattering::findInterfaces() {
    surfaces_.bind();
    interfacePass_.use();
    glUniform1ui(interfacePass_.uniform("sharp_surface_count"), surfaces_.count());
    glUniform3i(interfacePass_.uniform("periodic"), settings_.periodic.x, settings_.periodic.y, settings_.periodic.z);
    interfaces_.bindStorage(layout::kLatticeInterfaces);
    interfacePass_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// Each cell's birth shares, once a frame (the beam may move).
void LatticeScattering::findBirthShares(const LatticeBeam& beam) {
    EIKON_CHECK_MSG(beam.fluence != nullptr && beam.direction != nullptr,
                    "an anisotropic medium's lattice is given the beam its source was scattered out of");
    birthPass_.use();
    beam.fluence->bindStorage(layout::kFluence);
    beam.direction->bindStorage(layout::kFluenceDirection);
    birth_.bindStorage(layout::kLatticeBirth);
    birthPass_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

LatticeScattering::Survey LatticeScattering::survey() {
    surveyValues_.clearToZero();
    surveyValues_.bindStorage(layout::kLatticeSurvey);
    survey_.use();
    glUniform1f(survey_.uniform("min_retention"), static_cast<float>(kMinRetention));
    glUniform1f(survey_.uniform("validated_depth"), static_cast<float>(kValidatedVoxelDepth));
    survey_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    const auto values = surveyValues_.downloadAs<layout::GpuLatticeSurvey>();
    Survey result;
    result.channelsDiffer = values.channelsDiffer != 0;
    result.depth = {depthLimit_, values.thickVoxels, static_cast<double>(std::bit_cast<float>(values.deepestDepth))};
    result.resolution = {kValidatedVoxelDepth, values.coarseVoxels,
                         static_cast<double>(std::bit_cast<float>(values.coarsestDepth))};
    return result;
}

LatticeStats LatticeScattering::run(const FieldTextures& fields, const gl::Buffer& scatteredPower,
                                    const LatticeBeam& beam) {
    LatticeStats stats;
    stats.directions = settings_.directions;
    stats.warmStart = warm_;
    fields.bindForTracing();
    if (!surfaces_.empty()) findInterfaces();
    if (directed_) {
        findBirthShares(beam);
        birth_.bindStorage(layout::kLatticeBirth);
        phase_.bindStorage(layout::kLatticePhase);
    }
    scatteredPower.bindStorage(layout::kRawScattered);
    const Survey surveyed = survey();
    stats.grey = !surveyed.channelsDiffer;
    stats.depth = surveyed.depth;
    stats.resolution = surveyed.resolution;
    if (stats.grey) {
        // The same bits in every channel: solve one, copy its densities, and
        // take the others' fluence and ledger from them.
        stats.channels[0] = runChannel(0, warm_);
        for (int channel = 1; channel < 3; ++channel) {
            for (int half = 0; half < 2; ++half) states_[channel][half].copyFrom(states_[0][half]);
            current_[channel] = current_[0];
            stats.channels[channel] = stats.channels[0];
            const LatticeChannel tally = ledger(channel, states_[channel][current_[channel]]);
            stats.channels[channel].source = tally.source;
            stats.channels[channel].absorbed = tally.absorbed;
            stats.channels[channel].escaped = tally.escaped;
            stats.channels[channel].iterations = 0;
        }
    } else {
        for (int channel = 0; channel < 3; ++channel) stats.channels[channel] = runChannel(channel, warm_);
    }
    warm_ = true;
    gl::checkpoint("lattice scattering");
    return stats;
}

LatticeChannel LatticeScattering::runChannel(int channel, bool warm) {
    std::array<gl::Buffer, 2>& pair = states_[channel];
    int& current = current_[channel];
    if (!warm) {
        pair[0].clearToZero();
        pair[1].clearToZero();
    }
    LatticeChannel result;
    std::vector<float> previous = probeFluence(channel, pair[current]);
    double previousDelta = -1.0, previousDifference = -1.0;
    bool converged = false;
    while (!converged && result.iterations < settings_.maxIterations) {
        const int steps = std::min(settings_.checkInterval, settings_.maxIterations - result.iterations);
        step_.use();
        glUniform1i(step_.uniform("channel"), channel);
        glUniform3i(step_.uniform("periodic"), settings_.periodic.x, settings_.periodic.y, settings_.periodic.z);
        for (int s = 0; s < steps; ++s) {
            pair[current].bindStorage(layout::kLatticeIn);
            pair[1 - current].bindStorage(layout::kLatticeOut);
            step_.dispatchOverCells(grid_.resolution);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            current = 1 - current;
        }
        result.iterations += steps;
        const std::vector<float> probes = probeFluence(channel, pair[current]);
        double brightest = 0.0;
        for (const float value : probes) brightest = std::max(brightest, std::abs(static_cast<double>(value)));
        // The largest relative change among the probes above the floor.
        double delta = 0.0, difference = 0.0;
        for (std::size_t p = 0; p < probes.size(); ++p) {
            const double value = probes[p], change = std::abs(value - previous[p]);
            difference += change;
            if (std::abs(value) >= kFaintProbeFloor * brightest && brightest > 0.0)
                delta = std::max(delta, change / std::abs(value));
        }
        previous = probes;
        if (brightest == 0.0) {
            // No light at any probe yet: light born anywhere reaches one
            // within two probe spacings, unless there is none.
            converged = difference == 0.0 && result.iterations >= 2 * settings_.probeStride;
            result.change = result.remaining = converged ? 0.0 : std::numeric_limits<double>::infinity();
            continue;
        }
        result.change = delta / steps;
        // The rate of convergence: the larger of the largest change's ratio
        // and the summed change's (the largest may move from probe to
        // probe between checks, and its ratio then understate the rate).
        const double ratio = previousDelta > 0.0 && previousDifference > 0.0
                                 ? std::max(delta / previousDelta, difference / previousDifference)
                                 : std::numeric_limits<double>::infinity();
        result.remaining = delta == 0.0 ? 0.0
                           : ratio < 1.0 ? delta * ratio / (1.0 - ratio)
                                         : std::numeric_limits<double>::infinity();
        converged = result.remaining < settings_.tolerance;
        previousDelta = delta;
        previousDifference = difference;
    }
    result.capped = !converged;
    const LatticeChannel tally = ledger(channel, pair[current]);
    result.source = tally.source;
    result.absorbed = tally.absorbed;
    result.escaped = tally.escaped;
    return result;
}

std::vector<float> LatticeScattering::probeFluence(int channel, const gl::Buffer& state) {
    probe_.use();
    glUniform1i(probe_.uniform("channel"), channel);
    glUniform3i(probe_.uniform("periodic"), settings_.periodic.x, settings_.periodic.y, settings_.periodic.z);
    glUniform1i(probe_.uniform("probe_stride"), settings_.probeStride);
    state.bindStorage(layout::kLatticeIn);
    probeValues_.bindStorage(layout::kLatticeProbes);
    probe_.dispatchOverCells(probes_);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    std::vector<float> values(probeValues_.bytes() / sizeof(float));
    probeValues_.download(values.data(), values.size() * sizeof(float));
    return values;
}

LatticeChannel LatticeScattering::ledger(int channel, const gl::Buffer& state) {
    result_.use();
    glUniform1i(result_.uniform("channel"), channel);
    glUniform3i(result_.uniform("periodic"), settings_.periodic.x, settings_.periodic.y, settings_.periodic.z);
    state.bindStorage(layout::kLatticeIn);
    fluence_.bindStorage(layout::kMultipleFluence);
    tallies_.bindStorage(layout::kLatticeTallies);
    result_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    std::vector<float> values(tallies_.bytes() / sizeof(float));
    tallies_.download(values.data(), values.size() * sizeof(float));
    LatticeChannel tally;
    for (std::size_t g = 0; g < values.size(); g += kLedgerValues) {  // a fixed order: the same bits every run
        tally.source += values[g];
        tally.absorbed += values[g + 1];
        for (int face = 0; face < 6; ++face) tally.escaped[face] += values[g + 2 + face];
    }
    return tally;
}

std::vector<float> LatticeScattering::downloadFluence() const {
    std::vector<float> values(fluence_.bytes() / sizeof(float));
    fluence_.download(values.data(), values.size() * sizeof(float));
    return values;
}

}  // namespace eikon::render
