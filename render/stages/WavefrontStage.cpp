#include "render/stages/WavefrontStage.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "render/stages/PhotonEmission.h"
#include "render/stages/SharpSurfaceBuffer.h"

#include <algorithm>
#include <string>

namespace eikon::render {

namespace {

// A chunk seeds at most capacity / kChunkHeadroom patches, so that its tree
// may grow that many times over before a level is full.
constexpr unsigned kChunkHeadroom = 1024;

unsigned levelCapacity(long long maxPatches) {
    GLint64 largest = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
    const long long fits = largest / static_cast<long long>(sizeof(layout::GpuWavefrontPatch));
    if (maxPatches > fits)
        throw InputError("tracer.wavefront.max_patches",
                         "at most " + std::to_string(fits) + " (a patch takes " +
                             std::to_string(sizeof(layout::GpuWavefrontPatch)) +
                             " bytes; GL_MAX_SHADER_STORAGE_BLOCK_SIZE is " + std::to_string(largest) + ")",
                         std::to_string(maxPatches));
    return static_cast<unsigned>(maxPatches) / 4u * 4u;
}

}  // namespace

unsigned emissionFaces(const layout::GpuEmitter& emitter) {
    const bool cone = emitter.origin.w == 0.0f;
    return cone && emitter.axis.w > 0.5f ? 6u : 1u;  // wider than 60°
}

int wavefrontBranches(const TracerDesc::Wavefront& settings, bool sharpSurfaces) {
    return sharpSurfaces ? settings.reflections : 0;
}

std::uint64_t wavefrontStartPatches(const TracerDesc::Wavefront& settings, bool dispersive,
                                    const std::vector<unsigned>& emissionFaces, bool sharpSurfaces) {
    const std::uint64_t cells = std::uint64_t(settings.gridCells) * std::uint64_t(settings.gridCells);
    const std::uint64_t wavefronts = (dispersive ? 3 : 1) * std::uint64_t(1 + wavefrontBranches(settings, sharpSurfaces));
    std::uint64_t faces = 0;
    for (const unsigned emitterFaces : emissionFaces) faces += emitterFaces;
    return faces * cells * 2 * wavefronts;
}

std::uint64_t wavefrontStartPatches(const Scene& scene) {
    std::vector<unsigned> faces;
    for (const layout::GpuEmitter& emitter : buildEmitters(scene.lights, emissionRegion(scene), scene.render.photons))
        faces.push_back(emissionFaces(emitter));
    return wavefrontStartPatches(scene.tracer.wavefront, scene.tracer.dispersive(), faces,
                                 !buildSharpSurfaces(scene).empty());
}

WavefrontStage::WavefrontStage(const TracerDesc& tracer, gl::ShaderDefines defines, bool storesFluence, bool native)
    : settings_(tracer.wavefront), dispersive_(tracer.dispersive()), storesFluence_(storesFluence),
      runsNatively_(native) {
    capacity_ = levelCapacity(settings_.maxPatches);
    if (native) return;
    program_ = gl::compileComputeProgram("wavefront_trace.comp", defines);
    for (gl::Buffer& level : levels_)
        level = gl::Buffer(std::size_t{capacity_} * sizeof(layout::GpuWavefrontPatch),
                           {"tracer.wavefront.max_patches", "a level of wavefront patches"});
    counters_ = gl::Buffer(sizeof(layout::GpuWavefrontCounters));
}

void WavefrontStage::dispatch(Mode mode, unsigned invocations) {
    glUniform1ui(program_.uniform("mode"), static_cast<GLuint>(mode));
    glUniform1ui(program_.uniform("patch_count"), invocations);
    program_.dispatchCovering(invocations);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void WavefrontStage::traceWavefront(unsigned emitter, unsigned faces, int channel, int branch,
                                    const PassShare& share) {
    if (native_) {
        native_->setWavefront(emitter, faces, channel, branch);
    } else {
        glUniform1ui(program_.uniform("emission_faces"), faces);
        glUniform1ui(program_.uniform("seed_emitter"), emitter);
        glUniform1i(program_.uniform("channel"), channel);
        glUniform1i(program_.uniform("branch"), branch);
    }
    const auto cellsPerEdge = static_cast<unsigned>(settings_.gridCells);
    const unsigned cells = faces * cellsPerEdge * cellsPerEdge;
    const unsigned chunkCells = std::max(1u, capacity_ / (2u * kChunkHeadroom));
    for (unsigned first = 0; first < cells; first += chunkCells) {
        if (!share.ownsChunk(chunk_++)) continue;
        const unsigned seeds = 2u * std::min(chunkCells, cells - first);
        if (native_) native_->traceChunk(first, seeds);
        else traceChunk(first, seeds);
    }
}

void WavefrontStage::traceChunk(unsigned first, unsigned seeds) {
    levels_[0].bindStorage(layout::kWavefrontChildren);
    glUniform1ui(program_.uniform("first_cell"), first);
    dispatch(kSeed, seeds);
    glUniform1ui(program_.uniform("seeded_jobs"), 1u);
    dispatch(kTrace, 3u * seeds);
    glUniform1ui(program_.uniform("seeded_jobs"), 0u);
    for (unsigned count = seeds, source = 0; count > 0; source = 1 - source) {
        levels_[source].bindStorage(layout::kWavefrontPatches);
        levels_[1 - source].bindStorage(layout::kWavefrontChildren);
        const std::uint32_t none = 0;
        counters_.upload(&none, sizeof none, offsetof(layout::GpuWavefrontCounters, children));
        dispatch(kRefine, count);
        const auto children = counters_.downloadAs<std::uint32_t>(offsetof(layout::GpuWavefrontCounters, children));
        count = std::min(children, capacity_);
        if (count > 0) dispatch(kTrace, count / 4u * 3u);
    }
}

void WavefrontStage::traceWavefronts(const WavefrontInputs& inputs) {
    chunk_ = 0;
    const int channels = dispersive_ ? 3 : 1;
    const int branches = wavefrontBranches(settings_, inputs.sharpSurfaceCount > 0);
    for (unsigned emitter = 0; emitter < inputs.emissionFaces.size(); ++emitter)
        for (int channel = 0; channel < channels; ++channel)
            for (int branch = -1; branch < branches; ++branch)
                traceWavefront(emitter, inputs.emissionFaces[emitter], dispersive_ ? channel : -1, branch, inputs.share);
}

WavefrontCounts WavefrontStage::runNative(const WavefrontInputs& inputs) {
    EIKON_CHECK_MSG(inputs.native && inputs.nativeTallies, "the native wavefront pass's inputs");
    NativeWavefrontSettings settings;
    settings.gridCells = static_cast<unsigned>(settings_.gridCells);
    settings.maxDepth = static_cast<unsigned>(settings_.maxDepth);
    settings.capacity = capacity_;
    settings.splitTexels = static_cast<float>(settings_.splitTexels);
    settings.tearTexels = static_cast<float>(settings_.tearTexels);
    settings.minPower = static_cast<float>(settings_.minPower);
    settings.reflectionSplit = static_cast<float>(settings_.reflectionSplit);
    NativeWavefrontTrace native(*inputs.native, settings, inputs.nativeTallies->receiver.size() / 3);
    native_ = &native;
    traceWavefronts(inputs);
    native_ = nullptr;
    *inputs.nativeTallies = native.tallies();
    const NativeWavefrontCounts counts = native.counts();
    return {counts.finished, counts.splits, counts.atLimit, counts.rays, 0,
            wavefrontStartPatches(settings_, dispersive_, inputs.emissionFaces, inputs.sharpSurfaceCount > 0)};
}

WavefrontCounts WavefrontStage::run(const WavefrontInputs& inputs) {
    if (runsNatively_) return runNative(inputs);
    program_.use();
    counters_.clearToZero();
    counters_.bindStorage(layout::kWavefrontCounters);
    if (inputs.sharpSurfaceCount > 0)
        glUniform1ui(program_.uniform("sharp_surface_count"), inputs.sharpSurfaceCount);
    glUniform1ui(program_.uniform("max_steps"), inputs.maxSteps);
    glUniform1f(program_.uniform("step_length"), static_cast<float>(inputs.stepLength));
    glUniform3f(program_.uniform("dispersion"), static_cast<float>(inputs.dispersion.r),
                static_cast<float>(inputs.dispersion.g), static_cast<float>(inputs.dispersion.b));
    glUniform3f(program_.uniform("power_unit"), inputs.powerUnit.r, inputs.powerUnit.g, inputs.powerUnit.b);
    glUniform1ui(program_.uniform("grid_cells"), static_cast<unsigned>(settings_.gridCells));
    glUniform1ui(program_.uniform("max_depth"), static_cast<unsigned>(settings_.maxDepth));
    glUniform1ui(program_.uniform("capacity"), capacity_);
    glUniform1f(program_.uniform("split_texels"), static_cast<float>(settings_.splitTexels));
    glUniform1f(program_.uniform("tear_texels"), static_cast<float>(settings_.tearTexels));
    glUniform1f(program_.uniform("min_power"), static_cast<float>(settings_.minPower));
    glUniform1f(program_.uniform("reflection_split"), static_cast<float>(settings_.reflectionSplit));
    if (storesFluence_) {
        const FluenceUnits& units = inputs.fluenceUnits;
        glUniform1f(program_.uniform("split_voxels"), static_cast<float>(settings_.splitVoxels));
        glUniform3f(program_.uniform("fluence_unit"), units.fluence.r, units.fluence.g, units.fluence.b);
        glUniform1f(program_.uniform("direction_unit"), units.direction);
        if (inputs.latticeSource)
            glUniform3f(program_.uniform("scattered_unit"), units.scattered.r, units.scattered.g, units.scattered.b);
    }

    traceWavefronts(inputs);
    gl::checkpoint("wavefront stage");
    const auto counters = counters_.downloadAs<layout::GpuWavefrontCounters>();
    return {counters.finished, counters.splits, counters.atLimit, counters.rays, counters.tubes,
            wavefrontStartPatches(settings_, dispersive_, inputs.emissionFaces, inputs.sharpSurfaceCount > 0)};
}

}  // namespace eikon::render
