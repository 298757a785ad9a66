// The light pass: by photons (shaders/photon_trace.comp: emission, adaptive
// or uniform marching with the chosen integrator, Beer–Lambert attenuation,
// fluence and receiver deposits) or, with tracer.estimator "wavefront", by
// adaptive wavefront tracing (WavefrontStage: receivers only); then the
// receiver filter and the fluence smoothing; and the frame's energy balance
// and error figures.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/LightPassShare.h"
#include "render/stages/NativePhotonTrace.h"
#include "render/stages/ReceiverMaps.h"
#include "render/stages/SharpSurfaceBuffer.h"
#include "render/stages/StageDevice.h"
#include "render/stages/VolumeGlow.h"
#include "render/stages/WavefrontStage.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon::render {

// How a pass traces; the photon count is the scene's (setEmitters).
struct PhotonSettings {
    unsigned seed = 1;
    double stepLength = 0.0;      // uniform Δs, or the octree's Δs_min, in metres
    unsigned maxSteps = 0;        // trapped-ray cap
    double powerCutoff = 1e-4;    // relative to a photon's emitted power
    PassShare share{};            // this process's share of the pass (LightPassShare.h)
    LightPassExchange* exchange = nullptr;  // combines the shares' tallies; null for a whole pass
    // Only the recorded photons (0, k, 2k, …: PhotonProgramOptions), not the
    // whole pass: the probe of the discretisation estimate.
    bool recordedOnly = false;
    // Where set, the even photons are traced first, then the odd ones (each
    // half a checkerboard of every emitter's strata), and this gets the
    // tallies of the even half, filtered as for twice its
    // photons (and the stage keeps that half's fluence, halfFluence): two
    // independent batches for the noise estimate (ErrorEstimateStage). The
    // whole pass's tallies are the same bits either way. A whole pass only.
    ReceiverMaps* evenHalf = nullptr;
};

// Where a recorded photon ended (PhotonProgramOptions::recordEnds).
struct PhotonEnd {
    glm::vec3 position{0.0f};  // on the receiver, where it left the grid, or where it stopped
    int fate = 0;              // layout::PowerTally: kEscaped, kReceived, kCutOff, kBlocked; 0 not traced
    glm::vec3 power{0.0f};     // RGB, W, at the end
    int receiver = -1;         // the receiver it ended on (kReceived)
};

// Options that change the photon program itself (compile-time #defines).
struct PhotonProgramOptions {
    int recordPathVertices = 0;  // per recorded photon; 0 records nothing (compiled out)
    int recordedPhotons = 64;
    int recordStride = 1;        // record photons 0, k, 2k, … (a sample spread over all emitters and strata)
    bool recordEnds = false;     // keep where each of the recordedPhotons, every recordStride-th, ended (downloadEnds)
    bool bareMarch = false;      // benchmark limit: no attenuation, deposits or receivers
    // The loop budget a photon may spend in one dispatch; unset: the
    // driver's (gl::currentLoopBudget). Tests shrink it to suspend photons
    // often; it may not exceed the driver's where the driver has one.
    std::optional<unsigned> loopBudget{};
    // Where the light pass runs (render.device, resolved): Cpu runs the
    // shader's photon tracer or wavefront natively (NativePhotonTrace.h,
    // NativeWavefrontTrace.h) where the scene needs no option it lacks
    // (nativePhotonRefusal), else the compute shader.
    StageDevice device = StageDevice::Gpu;
};

// Where the emitted power went, in W per channel, and the step figures.
struct PhotonStats {
    long long photons = 0;
    Rgb emitted{0.0}, absorbed{0.0}, escaped{0.0}, received{0.0}, cutOff{0.0}, blocked{0.0};
    Rgb reflected{0.0};  // sent back out by bouncing receivers (a source, like emitted)
    // Added by Russian roulette to the dim photons it lets go on, a source
    // too; on average it equals what it cut off (part of cutOff).
    Rgb rouletteGain{0.0};
    // Fresnel reflections at sharp surfaces the wavefront does not follow (a sink).
    Rgb unfollowed{0.0};
    std::uint64_t photonsEscaped = 0, photonsReceived = 0, photonsCutOff = 0, photonsBlocked = 0;
    std::uint64_t steps = 0;
    std::uint64_t voxelDeposits = 0;
    // Events at sharp surfaces: Fresnel reflections (and total internal
    // reflections) and transmissions; photons keep their power at each.
    std::uint64_t surfaceReflections = 0, surfaceTransmissions = 0;
    double maxInvariantError = 0.0;   // max over photons and steps of | |v| − n | / n
    double meanInvariantError = 0.0;  // mean over steps
    // Where the driver caps loops (llvmpipe): photons suspended at the cap
    // and resumed by a later dispatch (each suspension counted), and those
    // dispatches (common/suspended_photons.glsl).
    std::uint64_t photonsResumed = 0;
    int resumeDispatches = 0;
    bool byWavefront = false;         // the wavefront estimator (photons is then 0)
    WavefrontCounts wavefront;

    // What the lights state they emit into what the pass samples
    // (statedEmission), where the pass is whole; 0: not known.
    Rgb stated{0.0};

    // |emitted + reflected + rouletteGain − (absorbed + escaped + received + cutOff + blocked + unfollowed)|
    // / (emitted + reflected + rouletteGain), worst channel.

    double balanceError() const;
    // |Σ emitted − Σ stated| / Σ stated over the channels (0 where stated is
    // not known): light lost or made at emission, which the balance, summing
    // what the packets carry, cannot see.
    double emissionError() const;
};

class PhotonStage {
public:
    PhotonStage(const Scene& scene, const FieldTextures& fields, ReceiverMaps& receivers,
                PhotonProgramOptions options = {});

    // Rebuilds the emitters from the scene's lights (a light moved) and the
    // glowing volume's power.
    void setEmitters(const Scene& scene);
    // A scene whose volume lights it (volume.emission_lights): the glowing
    // cells of this frame's emission (RGB per cell, host memory), then
    // setEmitters. Ignored without emission lights.
    void setVolumeGlow(const Scene& scene, const float* emission, const GridSpec& grid);

    // stepTexture: the octree step structure, when the scene's tracer uses it.
    PhotonStats run(const FieldTextures& fields, const gl::Texture3D* stepTexture, const PhotonSettings& settings);

    // Where the photons are traced, and, where the CPU was asked for and the
    // compute shader runs, why.
    StageDevice device() const { return native_ ? StageDevice::Cpu : StageDevice::Gpu; }
    const std::string& deviceReason() const { return deviceReason_; }

    bool storesFluence() const { return storeFluence_ > 0; }
    // Smoothed fluence φ (W/m², RGB per cell) and power-weighted mean
    // direction (xyz per cell); empty unless storesFluence().
    const gl::Buffer& fluence() const { return fluence_; }
    const gl::Buffer& fluenceDirection() const { return direction_; }
    // The power (W, RGB per cell) the photons lost to scattering, by the
    // σs/κ their attenuation used: the multiple-scattering lattice's source.
    // Empty unless the scene has a lattice (tracer.multiple_scattering).
    const gl::Buffer& scatteredPower() const { return fixedFluence_ ? scattered_ : rawScattered_; }
    std::vector<float> downloadFluence() const;
    std::vector<float> downloadFluenceDirection() const;
    // Recorded vertices (xyz, w = 1 where written) of the recorded photons,
    // recordPathVertices per photon, and the RGB power (W) at each of them.
    std::vector<glm::vec4> downloadPaths() const;
    std::vector<glm::vec4> downloadPathPower() const;
    std::vector<PhotonEnd> downloadEnds() const;  // recordedPhotons of them, with recordEnds
    // The smoothed fluence and direction of the even half of the last pass
    // traced with PhotonSettings::evenHalf, scaled to the whole pass's power.
    const gl::Buffer& halfFluence() const { return halfFluence_; }
    const gl::Buffer& halfFluenceDirection() const { return halfDirection_; }
    std::vector<float> downloadHalfFluence() const;

private:
    // Traces photons first, first + stride, … (count of them); checkerboard:
    // with stride 2, the halves take checkerboards of strata
    // (checkerboard_photon in shaders/photon_trace.comp).
    void tracePhotons(const PhotonSettings& settings, std::size_t first, std::size_t stride, std::size_t count,
                      bool checkerboard = false);
    // The fluence smoothing of raw into smoothed, times scale.
    // The fixed-point fluence's units: the light pass's power unit times the
    // smallest voxel edge for track (a deposit of any tube fits 64 bits with
    // 2^14 times all the power crossing a voxel to spare), the largest of
    // them for the direction sums, the power unit for scattered power.
    FluenceUnits fluenceUnits(const FieldTextures& fields) const;
    void smoothFluence(const FieldTextures& fields, const gl::Buffer& raw, const gl::Buffer& rawDirection,
                       const gl::Buffer& smoothed, const gl::Buffer& smoothedDirection, float scale);
    // Sums the raw tallies of every share of the pass into this one's
    // (statistics, receivers, fluence, recorded paths), before the filters.
    void combineShares(LightPassExchange& exchange, PhotonStats& stats);
    // Dispatches the photons the last dispatch suspended, and again, until
    // none is suspended; counts them into resumed_.
    void resumeSuspended(std::size_t batch);
    // The native pass's inputs for this run: the field and step textures'
    // texels on the host.
    void gatherNativeInputs(const FieldTextures& fields, const gl::Texture3D* stepTexture, const PhotonSettings& settings);
    // The native pass's tallies so far into the receivers' and statistics' buffers.
    void uploadNativeTallies();

    ReceiverMaps& receivers_;
    SharpSurfaceBuffer surfaces_;
    Rgb dispersion_{1.0};
    int storeFluence_ = 0;  // 0 none, 1 where σs > 0, 2 everywhere
    // The wavefront's fluence tallies are 64-bit fixed point (deterministic),
    // converted to floats by fluence_smooth.comp; photons' are float sums.
    bool fixedFluence_ = false;
    gl::Buffer scattered_;  // the fixed-point scattered power as floats, for the lattice
    gl::Program program_;                        // photons
    std::unique_ptr<WavefrontStage> wavefront_;  // or the wavefront
    gl::Program fluenceSmoothProgram_;
    Rgb stated_{0.0};  // statedEmission of the emitters
    gl::Buffer emitters_;
    unsigned emitterCount_ = 0;
    std::unique_ptr<VolumeGlow> glow_;  // with emission lights
    std::vector<unsigned> emissionFaces_;  // per emitter, for the wavefront
    std::vector<layout::GpuEmitter> emitterData_;  // what emitters_ holds
    long long photons_ = 0;      // the count the emitters were built for
    glm::vec3 powerUnit_{0.0f};  // W per fixed-point tally unit, per channel
    gl::Buffer rawFluence_, rawDirection_, fluence_, direction_;
    gl::Buffer rawScattered_;  // with a lattice
    gl::Buffer halfRawFluence_, halfRawDirection_, halfFluence_, halfDirection_;  // allocated by the first halved pass
    PhotonProgramOptions options_;
    gl::Buffer ends_;
    gl::Buffer stats_;
    gl::Buffer paths_;
    gl::Buffer pathPower_;
    bool resumable_ = false;           // the driver caps loops: photons are suspended and resumed
    gl::Buffer suspended_[2];          // ping-pong: the photons one dispatch suspends, the next resumes
    gl::Buffer suspendedCount_;        // layout::GpuSuspendedCount
    std::uint64_t resumed_ = 0;        // this trace's resumed photons
    int resumeDispatches_ = 0;         // and the dispatches that resumed them
    bool native_ = false;              // the tracer runs natively (NativePhotonTrace.h, NativeWavefrontTrace.h)
    std::string deviceReason_;         // why not, where render.device asked for it
    NativePhotonInputs nativeInputs_;
    std::vector<glm::vec4> hostGradient_, hostSteps_;
    NativePhotonTallies nativeTallies_;  // this run's, so far
};

// Why the native light pass — photons or wavefront — cannot trace `scene`
// with `options` (the program options it is not compiled with); empty where
// it can.
std::string nativePhotonRefusal(const Scene& scene, const FieldTextures& fields, const PhotonProgramOptions& options);

// Whether the scene diffuses what its photons scatter on a lattice
// (tracer.multiple_scattering "lbm" where some voxel scatters): the light
// pass (photons or wavefront) then tallies the power it scatters per cell.
bool feedsLattice(const Scene& scene, const FieldTextures& fields);

// Default trapped-ray cap: four crossings of the grid along all three axes
// at the smallest step.
unsigned defaultMaxSteps(const GridSpec& grid, double stepLength);

}  // namespace eikon::render
