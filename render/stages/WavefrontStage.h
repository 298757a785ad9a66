// The wavefront estimator ([Ihrke07] §4.2 and §5.2; shaders/wavefront_trace.comp):
// each light's emission square is cut into grid_cells² cells of two
// triangular patches whose corners are traced rays; level by level, patches
// whose corners disagree or whose footprint is larger than split_texels
// split in four, the rest deposit their power on the receivers by the
// intensity law; where the pass stores fluence, patches also split while
// their tube through the grid is wider than split_voxels, and each finished
// one deposits its power along its tube's axis. Seeds go in chunks small enough that a chunk's levels fit
// the level buffers; a level that would not fit stops splitting (its patches
// are deposited and counted as at the limit). Deterministic: the same scene
// gives the same bits. With dispersion each channel is traced on its own.
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/LightPassShare.h"
#include "render/stages/NativeWavefrontTrace.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace eikon::render {

// What one wavefront pass did.
struct WavefrontCounts {
    std::uint64_t patches = 0;  // finished and deposited
    std::uint64_t splits = 0;
    std::uint64_t atLimit = 0;  // finished though they wanted to split (depth or count limit)
    std::uint64_t rays = 0;     // rays traced (patch corners)
    std::uint64_t tubes = 0;    // tube axes traced: fluence in the grid
    std::uint64_t startPatches = 0;  // seeded at depth 0 (wavefrontStartPatches)
};

// The units of the wavefront's fixed-point fluence tallies
// (common/fluence_deposits.glsl, EIKON_FIXED_FLUENCE).
struct FluenceUnits {
    glm::vec3 fluence{0.0f};    // W·m of track per unit, per channel
    float direction = 0.0f;     // W·m per unit of the direction sums
    glm::vec3 scattered{0.0f};  // W of scattered power per unit, per channel
};

// The uniforms the wavefront shares with the photon pass.
struct WavefrontInputs {
    std::vector<unsigned> emissionFaces;  // per emitter (emissionFaces)
    unsigned sharpSurfaceCount = 0;
    unsigned maxSteps = 0;
    double stepLength = 0.0;  // m
    Rgb dispersion{1.0};
    glm::vec3 powerUnit{0.0f};  // W per fixed-point unit, per channel
    PassShare share{};          // the seed chunks this process traces
    FluenceUnits fluenceUnits{};  // where the pass stores fluence
    bool latticeSource = false;   // it also tallies the power scattered per cell
    // The native pass's (WavefrontStage built with `native`): its inputs,
    // and the tallies it leaves, whose receiver tallies hold every texel.
    const NativePhotonInputs* native = nullptr;
    NativePhotonTallies* nativeTallies = nullptr;
};

// Faces of an emitter's emission domain (shaders/wavefront_trace.comp,
// face_direction): one for a directional light's disk and for a cone at most
// 60° wide, whose gnomonic square stays well shaped; six, the cube about the
// light, for a wider one.
unsigned emissionFaces(const layout::GpuEmitter& emitter);

// The reflected branches a frame traces besides each main wavefront:
// tracer.wavefront.reflections where there are sharp surfaces.
int wavefrontBranches(const TracerDesc::Wavefront& settings, bool sharpSurfaces);

// The patches a frame's wavefronts start with, whatever they refine to: each
// emitter face's grid_cells² cells of two patches, in the main wavefront and
// each branch, per channel where the medium disperses. The first cost of a
// wavefront pass, known before it runs.
std::uint64_t wavefrontStartPatches(const TracerDesc::Wavefront& settings, bool dispersive,
                                    const std::vector<unsigned>& emissionFaces, bool sharpSurfaces);
// The same for a scene, its emitters as the light pass builds them.
std::uint64_t wavefrontStartPatches(const Scene& scene);

class WavefrontStage {
public:
    // defines: the march's program options (common/ray_march.glsl) and the
    // fluence's (common/fluence_deposits.glsl). native: the pass runs the
    // shader's text as C++ (NativeWavefrontTrace.h), the scene needing no
    // option it lacks (nativePhotonRefusal), and compiles no program.
    WavefrontStage(const TracerDesc& tracer, gl::ShaderDefines defines, bool storesFluence, bool native);

    // Traces every emitter's wavefront into the receivers' tallies and the
    // light pass's statistics; every binding of the light pass (fields,
    // emitters, receivers, tallies, statistics, sharp surfaces) in place.
    // Natively, into inputs.nativeTallies instead.
    WavefrontCounts run(const WavefrontInputs& inputs);

private:
    enum Mode : unsigned { kSeed = 0, kTrace = 1, kRefine = 2 };  // shaders/wavefront_trace.comp
    void dispatch(Mode mode, unsigned invocations);
    // Every emitter's wavefronts: per channel where the medium disperses, the
    // main one and each reflected branch.
    void traceWavefronts(const WavefrontInputs& inputs);
    // One wavefront: the emitter's faces in chunks of seeds, each refined
    // level by level until no patch splits.
    void traceWavefront(unsigned emitter, unsigned faces, int channel, int branch, const PassShare& share);
    // One chunk of `seeds` start patches from cell `first`, refined until none splits.
    void traceChunk(unsigned first, unsigned seeds);
    WavefrontCounts runNative(const WavefrontInputs& inputs);

    TracerDesc::Wavefront settings_;
    bool dispersive_ = false;
    bool storesFluence_ = false;
    unsigned capacity_ = 0;  // patches a level buffer holds (a multiple of 4)
    NativeWavefrontTrace* native_ = nullptr;  // the native pass of the run under way, if it runs natively
    bool runsNatively_ = false;
    gl::Program program_;
    gl::Buffer levels_[2];
    gl::Buffer counters_;
    std::size_t chunk_ = 0;  // the pass's seed chunks so far, over all its wavefronts
};

}  // namespace eikon::render
