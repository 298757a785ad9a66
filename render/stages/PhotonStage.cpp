#include "render/stages/PhotonStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/GlContext.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/PhotonEmission.h"
#include "render/stages/StageDevice.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace eikon::render {

namespace {

constexpr std::size_t kBatchPhotons = std::size_t{1} << 20;
// Where photons may be suspended, a batch is no larger than the buffer that
// holds its suspended photons (96 bytes each: 24 MiB), so none is lost.
constexpr std::size_t kResumableBatchPhotons = std::size_t{1} << 18;

// The scene's volume lights it (volume.emission_lights): photons leave its glowing cells.
bool glowLights(const Scene& scene) { return scene.volume && scene.volume->emissionLights; }

Rgb tallyOf(const layout::GpuPhotonStats& gpu, layout::PowerTally tally, const Rgb& unit) {
    Rgb watts;
    for (int c = 0; c < 3; ++c) {
        const std::uint64_t units = (std::uint64_t{gpu.power[tally][c][1]} << 32) | gpu.power[tally][c][0];
        watts[c] = static_cast<double>(units) * unit[c];
    }
    return watts;
}

std::uint64_t wide(std::uint32_t low, std::uint32_t high) { return (std::uint64_t{high} << 32) | low; }

// Visits every counter of a pass that sums over shares, in one fixed order:
// the GPU's 64-bit counters as their two words, its 32-bit ones, and the
// host's (resumed photons, wavefront counts).
template <typename Visit>
void visitSummedCounters(layout::GpuPhotonStats& gpu, PhotonStats& host, Visit&& visit) {
    for (auto& tally : gpu.power)
        for (auto& channel : tally) visit.wide(channel[0], channel[1]);
    for (int i = 0; i < 4; ++i) visit.narrow(gpu.photons[i]);
    visit.wide(gpu.steps.x, gpu.steps.y);
    visit.wide(gpu.deposits.x, gpu.deposits.y);
    visit.wide(gpu.invariant.x, gpu.invariant.y);
    visit.narrow(gpu.surfaces.x);
    visit.narrow(gpu.surfaces.y);
    visit.host(host.photonsResumed);
    visit.host(host.resumeDispatches);
    visit.host(host.wavefront.patches);
    visit.host(host.wavefront.splits);
    visit.host(host.wavefront.atLimit);
    visit.host(host.wavefront.rays);
    visit.host(host.wavefront.tubes);
}

struct PackCounters {
    std::vector<std::uint64_t>& sums;
    void wide(std::uint32_t low, std::uint32_t high) { sums.push_back((std::uint64_t{high} << 32) | low); }
    void narrow(std::uint32_t value) { sums.push_back(value); }
    template <typename T> void host(T value) { sums.push_back(static_cast<std::uint64_t>(value)); }
};

struct UnpackCounters {
    const std::vector<std::uint64_t>& sums;
    std::size_t next = 0;
    void wide(std::uint32_t& low, std::uint32_t& high) {
        low = static_cast<std::uint32_t>(sums[next]);
        high = static_cast<std::uint32_t>(sums[next++] >> 32);
    }
    void narrow(std::uint32_t& value) { value = static_cast<std::uint32_t>(sums[next++]); }  // wraps as the GPU's word
    template <typename T> void host(T& value) { value = static_cast<T>(sums[next++]); }
};

// A buffer of (low, high) 32-bit word pairs as 64-bit values, and back.
std::vector<std::uint64_t> downloadWide(const gl::Buffer& buffer) {
    std::vector<std::uint32_t> words(buffer.bytes() / sizeof(std::uint32_t));
    if (!words.empty()) buffer.download(words.data(), words.size() * sizeof(std::uint32_t));
    std::vector<std::uint64_t> values(words.size() / 2);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = (std::uint64_t{words[2 * i + 1]} << 32) | words[2 * i];
    return values;
}

void uploadWide(gl::Buffer& buffer, const std::vector<std::uint64_t>& values) {
    std::vector<std::uint32_t> words(2 * values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        words[2 * i] = static_cast<std::uint32_t>(values[i]);
        words[2 * i + 1] = static_cast<std::uint32_t>(values[i] >> 32);
    }
    if (!words.empty()) buffer.upload(words.data(), words.size() * sizeof(std::uint32_t));
}

std::vector<float> downloadFloats(const gl::Buffer& buffer) {
    std::vector<float> values(buffer.bytes() / sizeof(float));
    if (!values.empty()) buffer.download(values.data(), values.size() * sizeof(float));
    return values;
}

int integratorNumber(TracerDesc::Integrator integrator) {
    switch (integrator) {
        case TracerDesc::Integrator::Euler: return 0;
        case TracerDesc::Integrator::Leapfrog: return 1;
        case TracerDesc::Integrator::Rk4: return 2;
    }
    return 1;
}

}  // namespace

double PhotonStats::balanceError() const {
    const Rgb sources = emitted + reflected + rouletteGain;
    const Rgb sinks = absorbed + escaped + received + cutOff + blocked + unfollowed;
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        if (sources[c] > 0.0) worst = std::max(worst, std::abs(sources[c] - sinks[c]) / sources[c]);
    return worst;
}

double PhotonStats::emissionError() const {
    const double statedSum = stated.r + stated.g + stated.b;
    return statedSum > 0.0 ? std::abs(emitted.r + emitted.g + emitted.b - statedSum) / statedSum : 0.0;
}

bool feedsLattice(const Scene& scene, const FieldTextures& fields) {
    return scene.tracer.multipleScattering == TracerDesc::MultipleScattering::Lbm && fields.hasScattering();
}

std::string nativePhotonRefusal(const Scene& scene, const FieldTextures& fields, const PhotonProgramOptions& options) {
    const TracerDesc& tracer = scene.tracer;
    if (tracer.integrator != TracerDesc::Integrator::Leapfrog) return "the native pass integrates by leapfrog only";
    if (tracer.stepPolicy != TracerDesc::StepPolicy::Octree) return "the native pass takes octree steps only";
    if (tracer.renormalize) return "the native pass does not renormalise";
    if (tracer.dispersive()) return "the native pass is not dispersive";
    if (std::any_of(scene.receivers.begin(), scene.receivers.end(), [](const ReceiverDesc& r) { return r.bounce; }))
        return "the native pass has no bouncing receivers";
    if (tracer.storeFluence || fields.hasScattering()) return "the native pass keeps no fluence";
    if (fields.hasExtinction()) return "the native pass has no extinction";
    if (glowLights(scene)) return "the native pass has no glowing volume";
    if (hasTriangleSurfaces(buildSharpSurfaces(scene))) return "the native pass has no mesh or water surfaces";
    if (options.bareMarch || options.recordPathVertices > 0 || options.recordEnds)
        return "the native pass records no paths or ends";
    if (options.loopBudget) return "the native pass has no loop budget";
    return {};
}

unsigned defaultMaxSteps(const GridSpec& grid, double stepLength) {
    const glm::dvec3 extent = grid.extent();
    return static_cast<unsigned>(std::min(4.0 * (extent.x + extent.y + extent.z) / stepLength, 2147483647.0));
}

PhotonStage::PhotonStage(const Scene& scene, const FieldTextures& fields, ReceiverMaps& receivers,
                         PhotonProgramOptions options)
    : receivers_(receivers), surfaces_(scene), dispersion_(scene.tracer.dispersion), options_(options) {
    storeFluence_ = scene.tracer.storeFluence ? 2 : (fields.hasScattering() ? 1 : 0);
    if (options.bareMarch) storeFluence_ = 0;
    const TracerDesc& tracer = scene.tracer;
    const bool byWavefront = tracer.estimator == TracerDesc::Estimator::Wavefront;
    const unsigned driverBudget = gl::currentLoopBudget();
    const unsigned loopBudget = options.loopBudget.value_or(driverBudget);
    EIKON_CHECK_MSG(driverBudget == 0 || (loopBudget > 0 && loopBudget <= driverBudget),
                    "a loop budget within the driver's cap");
    // The march's options, which both estimators share (common/ray_march.glsl).
    gl::ShaderDefines defines{
        {"EIKON_HAS_EXTINCTION", fields.hasExtinction() ? "1" : "0"},
        {"EIKON_HAS_SCATTERING", fields.hasScattering() ? "1" : "0"},
        {"EIKON_INTEGRATOR", std::to_string(integratorNumber(tracer.integrator))},
        {"EIKON_OCTREE_STEPS", tracer.stepPolicy == TracerDesc::StepPolicy::Octree ? "1" : "0"},
        surfaces_.kindsOption(),
        {"EIKON_LOOP_BUDGET", std::to_string(loopBudget)},
        receivers.countOption(),
        {"EIKON_STORE_FLUENCE", std::to_string(storeFluence_)},
        {"EIKON_LATTICE_SOURCE", feedsLattice(scene, fields) ? "1" : "0"}};
    fixedFluence_ = byWavefront && storeFluence_ > 0;
    if (options.device == StageDevice::Cpu) deviceReason_ = nativePhotonRefusal(scene, fields, options);
    native_ = options.device == StageDevice::Cpu && deviceReason_.empty();
    if (byWavefront) {
        defines.insert({"EIKON_FIXED_FLUENCE", fixedFluence_ ? "1" : "0"});
        wavefront_ = std::make_unique<WavefrontStage>(tracer, defines, storeFluence_ > 0, native_);
    } else {
        defines.insert({{"EIKON_RENORMALIZE", tracer.renormalize ? "1" : "0"},
                        {"EIKON_DISPERSION", tracer.dispersive() ? "1" : "0"},
                        {"EIKON_BOUNCE", std::any_of(scene.receivers.begin(), scene.receivers.end(),
                                                     [](const ReceiverDesc& r) { return r.bounce; }) ? "1" : "0"},
                        {"EIKON_BARE_MARCH", options.bareMarch ? "1" : "0"},
                        {"EIKON_RECORD_PATHS", std::to_string(options.recordPathVertices)},
                        {"EIKON_RECORDED_PHOTONS", std::to_string(options.recordedPhotons)},
                        {"EIKON_RECORD_STRIDE", std::to_string(options.recordPathVertices > 0 ? std::max(1, options.recordStride) : 1)},
                        {"EIKON_RECORD_ENDS", options.recordEnds ? "1" : "0"},
                        {"EIKON_VOLUME_GLOW", glowLights(scene) ? "1" : "0"}});
        if (!native_) program_ = gl::compileComputeProgram("photon_trace.comp", defines);
        resumable_ = loopBudget > 0 && !native_;
    }
    if (resumable_) {
        const gl::GpuResource resource{"render.photons", "the photons suspended at the driver's loop cap"};
        for (gl::Buffer& buffer : suspended_)
            buffer = gl::Buffer(kResumableBatchPhotons * sizeof(layout::GpuSuspendedPhoton), resource);
        suspendedCount_ = gl::Buffer(sizeof(layout::GpuSuspendedCount));
    }
    if (glowLights(scene)) glow_ = std::make_unique<VolumeGlow>();
    setEmitters(scene);
    if (storeFluence_ > 0) {
        const std::size_t bytes = 3 * fields.grid().cellCount() * sizeof(float);
        const std::size_t rawBytes = fixedFluence_ ? 2 * bytes : bytes;  // two 32-bit words a value when fixed
        const glm::ivec3 r = fields.grid().resolution;
        rawFluence_ = gl::Buffer(rawBytes, gl::gridResource("the light pass's raw fluence", r.x, r.y, r.z));
        rawDirection_ = gl::Buffer(rawBytes, gl::gridResource("the light pass's raw fluence direction", r.x, r.y, r.z));
        fluence_ = gl::Buffer(bytes, gl::gridResource("the fluence", r.x, r.y, r.z));
        direction_ = gl::Buffer(bytes, gl::gridResource("the fluence direction", r.x, r.y, r.z));
        fluenceSmoothProgram_ = gl::compileComputeProgram(
            "fluence_smooth.comp", {{"EIKON_FIXED_FLUENCE", fixedFluence_ ? "1" : "0"},
                                    {"EIKON_LATTICE_SOURCE", fixedFluence_ && feedsLattice(scene, fields) ? "1" : "0"}});
        if (feedsLattice(scene, fields)) {
            rawScattered_ = gl::Buffer(rawBytes, gl::gridResource("the light pass's scattered power", r.x, r.y, r.z));
            if (fixedFluence_) scattered_ = gl::Buffer(bytes, gl::gridResource("the scattered power", r.x, r.y, r.z));
        }
    }
    stats_ = gl::Buffer(sizeof(layout::GpuPhotonStats));
    const std::size_t recordedVertices =
        static_cast<std::size_t>(options.recordPathVertices) * static_cast<std::size_t>(options.recordedPhotons);
    paths_ = gl::Buffer(recordedVertices * sizeof(glm::vec4));
    pathPower_ = gl::Buffer(recordedVertices * sizeof(glm::vec4));
    if (options.recordEnds) ends_ = gl::Buffer(2 * static_cast<std::size_t>(options.recordedPhotons) * sizeof(glm::vec4));
}

void PhotonStage::setEmitters(const Scene& scene) {
    photons_ = scene.render.photons;
    const Box region = emissionRegion(scene);
    const Rgb glowPower = glow_ ? glow_->power() : Rgb(0.0);
    const auto emitters = buildEmitters(scene.lights, region, photons_, glowPower);
    stated_ = statedEmission(scene.lights, region, wavefront_ != nullptr, glowPower);
    powerUnit_ = glm::vec3(0.0f);
    if (wavefront_) {
        // Units of the brightest light's power over 2^50: a deposit of any
        // patch fits 64 bits, and a sliver of one still counts many units.
        for (const auto& emitter : emitters)
            for (int c = 0; c < 3; ++c)
                powerUnit_[c] = std::max(powerUnit_[c], emitter.photonPower[c] * static_cast<float>(emitter.photons.y));
        for (int c = 0; c < 3; ++c)
            powerUnit_[c] = std::max(powerUnit_[c] / static_cast<float>(layout::kPowerUnitsPerWavefront), 1e-38f);
    } else {
        for (const auto& emitter : emitters)
            for (int c = 0; c < 3; ++c) powerUnit_[c] = std::max(powerUnit_[c], emitter.photonPower[c]);
        // Dispersion gives each photon three times one channel's power.
        const float headroom = scene.tracer.dispersive() ? 3.0f : 1.0f;
        for (int c = 0; c < 3; ++c)
            powerUnit_[c] =
                std::max(headroom * powerUnit_[c] / static_cast<float>(layout::kPowerUnitsPerPhoton), 1e-38f);
    }
    emitterCount_ = static_cast<unsigned>(emitters.size());
    emissionFaces_.clear();
    for (const auto& emitter : emitters) emissionFaces_.push_back(emissionFaces(emitter));
    emitterData_ = emitters;
    emitters_ = emitters.empty() ? gl::Buffer()
                                 : gl::Buffer(emitters.size() * sizeof(layout::GpuEmitter), emitters.data());
}

void PhotonStage::setVolumeGlow(const Scene& scene, const float* emission, const GridSpec& grid) {
    if (!glow_) return;
    glow_->update(emission, grid);
    setEmitters(scene);
}

PhotonStats PhotonStage::run(const FieldTextures& fields, const gl::Texture3D* stepTexture,
                             const PhotonSettings& settings) {
    fields.bindForTracing();
    if (stepTexture) stepTexture->bindSampler(layout::kStepTexture);
    receivers_.bind();
    receivers_.clearTallies();
    emitters_.bindStorage(layout::kEmitters);
    if (glow_) glow_->bind();
    stats_.clearToZero();
    stats_.bindStorage(layout::kPhotonStats);
    paths_.clearToZero();
    paths_.bindStorage(layout::kPhotonPaths);
    pathPower_.clearToZero();
    pathPower_.bindStorage(layout::kPhotonPathPower);
    if (ends_.id()) {
        ends_.clearToZero();
        ends_.bindStorage(layout::kPhotonEnds);
    }
    if (storeFluence_ > 0) {
        rawFluence_.clearToZero();
        rawDirection_.clearToZero();
        rawFluence_.bindStorage(layout::kRawFluence);
        rawDirection_.bindStorage(layout::kRawFluenceDirection);
    }
    if (rawScattered_.id()) {
        rawScattered_.clearToZero();
        rawScattered_.bindStorage(layout::kRawScattered);
    }
    if (!surfaces_.empty()) surfaces_.bind();
    PhotonStats stats;
    if (native_) gatherNativeInputs(fields, stepTexture, settings);
    resumed_ = 0;
    resumeDispatches_ = 0;
    if (wavefront_) {
        stats.byWavefront = true;
        stats.wavefront = wavefront_->run({emissionFaces_, surfaces_.empty() ? 0u : surfaces_.count(),
                                           settings.maxSteps, settings.stepLength, dispersion_, powerUnit_,
                                           settings.share, fixedFluence_ ? fluenceUnits(fields) : FluenceUnits{},
                                           rawScattered_.id() != 0, native_ ? &nativeInputs_ : nullptr,
                                           native_ ? &nativeTallies_ : nullptr});
        if (native_) uploadNativeTallies();
    } else if (settings.recordedOnly) {
        const std::size_t stride = static_cast<std::size_t>(std::max(1, options_.recordStride));
        const std::size_t count = std::min(static_cast<std::size_t>(options_.recordedPhotons),
                                           (static_cast<std::size_t>(photons_) + stride - 1) / stride);
        tracePhotons(settings, 0, stride, count);
        stats.photons = static_cast<long long>(count);
        stats.photonsResumed = resumed_;
        stats.resumeDispatches = resumeDispatches_;
    } else {
        const PhotonRange range = shareRange(static_cast<std::size_t>(photons_), settings.share);
        if (settings.evenHalf) {
            EIKON_CHECK_MSG(settings.share.whole() && !settings.exchange, "halves of a whole pass");
            tracePhotons(settings, range.first, 2, (range.count + 1) / 2, true);
            settings.evenHalf->copyTalliesFrom(receivers_);
            if (storeFluence_ > 0) {
                if (!halfFluence_.id()) {
                    const gl::GpuResource resource{"render.error_estimate", "the fluence of half the photons"};
                    for (gl::Buffer* buffer : {&halfRawFluence_, &halfRawDirection_, &halfFluence_, &halfDirection_})
                        *buffer = gl::Buffer(rawFluence_.bytes(), resource);
                }
                halfRawFluence_.copyFrom(rawFluence_);
                halfRawDirection_.copyFrom(rawDirection_);
            }
            tracePhotons(settings, range.first + 1, 2, range.count / 2, true);
        } else {
            tracePhotons(settings, range.first, 1, range.count);
        }
        stats.photons = photons_;
        stats.photonsResumed = resumed_;
        stats.resumeDispatches = resumeDispatches_;
    }
    if (settings.exchange) combineShares(*settings.exchange, stats);
    receivers_.filter(powerUnit_);
    if (settings.evenHalf) settings.evenHalf->filter(2.0f * powerUnit_);
    if (storeFluence_ > 0) {
        smoothFluence(fields, rawFluence_, rawDirection_, fluence_, direction_, 1.0f);
        if (settings.evenHalf)
            smoothFluence(fields, halfRawFluence_, halfRawDirection_, halfFluence_, halfDirection_, 2.0f);
    }
    gl::checkpoint("photon stage");

    const auto gpu = stats_.downloadAs<layout::GpuPhotonStats>();
    const Rgb unit(powerUnit_);
    stats.emitted = tallyOf(gpu, layout::kEmitted, unit);
    if (!settings.recordedOnly && (settings.share.whole() || settings.exchange)) stats.stated = stated_;
    stats.absorbed = tallyOf(gpu, layout::kAbsorbed, unit);
    stats.escaped = tallyOf(gpu, layout::kEscaped, unit);
    stats.received = tallyOf(gpu, layout::kReceived, unit);
    stats.cutOff = tallyOf(gpu, layout::kCutOff, unit);
    stats.blocked = tallyOf(gpu, layout::kBlocked, unit);
    stats.reflected = tallyOf(gpu, layout::kReflected, unit);
    stats.rouletteGain = tallyOf(gpu, layout::kRouletteGain, unit);
    stats.unfollowed = tallyOf(gpu, layout::kUnfollowed, unit);
    stats.photonsEscaped = gpu.photons.x;
    stats.photonsReceived = gpu.photons.y;
    stats.photonsCutOff = gpu.photons.z;
    stats.photonsBlocked = gpu.photons.w;
    stats.steps = wide(gpu.steps.x, gpu.steps.y);
    stats.voxelDeposits = wide(gpu.deposits.x, gpu.deposits.y);
    stats.surfaceReflections = gpu.surfaces.x;
    stats.surfaceTransmissions = gpu.surfaces.y;
    float maxError = 0.0f;
    std::memcpy(&maxError, &gpu.steps.z, sizeof maxError);
    stats.maxInvariantError = maxError;
    const double invariantSum = static_cast<double>(wide(gpu.invariant.x, gpu.invariant.y)) * 0x1p-32;
    stats.meanInvariantError = stats.steps > 0 ? invariantSum / static_cast<double>(stats.steps) : 0.0;
    return stats;
}

FluenceUnits PhotonStage::fluenceUnits(const FieldTextures& fields) const {
    const auto edge = static_cast<float>(fields.grid().smallestVoxelEdge());
    FluenceUnits units;
    units.fluence = powerUnit_ * edge;
    units.direction = std::max({units.fluence.r, units.fluence.g, units.fluence.b});
    units.scattered = powerUnit_;
    return units;
}

void PhotonStage::smoothFluence(const FieldTextures& fields, const gl::Buffer& raw, const gl::Buffer& rawDirection,
                                const gl::Buffer& smoothed, const gl::Buffer& smoothedDirection, float scale) {
    fields.gridBlock().bindUniform(layout::kGridBlock);
    raw.bindStorage(layout::kRawFluence);
    rawDirection.bindStorage(layout::kRawFluenceDirection);
    smoothed.bindStorage(layout::kFluence);
    smoothedDirection.bindStorage(layout::kFluenceDirection);
    fluenceSmoothProgram_.use();
    glUniform1f(fluenceSmoothProgram_.uniform("scale"), scale);
    if (fixedFluence_) {
        // The wavefront's fluence has no noise to smooth (its tubes are
        // narrower than a voxel and already spread by spline weights): its
        // fixed-point tallies are converted as they are.
        const FluenceUnits units = fluenceUnits(fields);
        glUniform3f(fluenceSmoothProgram_.uniform("fluence_unit"), units.fluence.r, units.fluence.g, units.fluence.b);
        glUniform1f(fluenceSmoothProgram_.uniform("direction_unit"), units.direction);
        if (scattered_.id()) {
            glUniform3f(fluenceSmoothProgram_.uniform("scattered_unit"), units.scattered.r, units.scattered.g,
                        units.scattered.b);
            rawScattered_.bindStorage(layout::kRawScattered);
            scattered_.bindStorage(layout::kScatteredPower);
        }
    } else {
        glUniform1i(fluenceSmoothProgram_.uniform("reach"), 1);
    }
    fluenceSmoothProgram_.dispatchOverCells(fields.grid().resolution);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void PhotonStage::gatherNativeInputs(const FieldTextures& fields, const gl::Texture3D* stepTexture,
                                     const PhotonSettings& settings) {
    EIKON_CHECK_MSG(stepTexture, "the native photon pass's step structure");
    const std::size_t cells = fields.grid().cellCount();
    hostGradient_.resize(cells);
    hostSteps_.resize(cells);
    downloadTexels(fields.gradient(), GL_RGBA, hostGradient_.data(), cells * sizeof(glm::vec4));
    downloadTexels(*stepTexture, GL_RGBA, hostSteps_.data(), cells * sizeof(glm::vec4));
    NativePhotonInputs& in = nativeInputs_;
    fields.gridBlock().download(&in.grid, sizeof in.grid);
    in.gradient = hostGradient_.data();
    in.steps = hostSteps_.data();
    in.receivers.clear();
    for (unsigned r = 0; r < receivers_.count(); ++r) in.receivers.push_back(receivers_.receiver(r));
    in.emitters = emitterData_;
    in.surfaces = surfaces_.surfaces();
    in.dispersion = glm::vec3(static_cast<float>(dispersion_.r), static_cast<float>(dispersion_.g),
                              static_cast<float>(dispersion_.b));
    in.stepLength = static_cast<float>(settings.stepLength);
    in.maxSteps = settings.maxSteps;
    in.seed = settings.seed;
    in.powerCutoff = static_cast<float>(settings.powerCutoff);
    in.powerUnit = powerUnit_;
    nativeTallies_ = NativePhotonTallies{};
    nativeTallies_.receiver.assign(3 * static_cast<std::size_t>(receivers_.texelCount()), 0);
}

void PhotonStage::uploadNativeTallies() {
    receivers_.uploadTallies(nativeTallies_.receiver);
    const layout::GpuPhotonStats gpu = nativeTallies_.stats();
    stats_.upload(&gpu, sizeof gpu);
}

void PhotonStage::tracePhotons(const PhotonSettings& settings, std::size_t first, std::size_t stride,
                               std::size_t count, bool checkerboard) {
    if (emitterCount_ == 0) return;  // no light this frame: lights of no power, a volume that does not glow yet
    if (native_) {
        // The tallies so far replace the buffers' (cleared by run): the halves
        // of a halved pass read them between their traces.
        tracePhotonsNative(nativeInputs_, first, stride, count, checkerboard, nativeTallies_);
        uploadNativeTallies();
        return;
    }
    program_.use();
    glUniform1ui(program_.uniform("checkerboard"), checkerboard ? 1u : 0u);
    if (!surfaces_.empty()) glUniform1ui(program_.uniform("sharp_surface_count"), surfaces_.count());
    glUniform1ui(program_.uniform("emitter_count"), emitterCount_);
    glUniform1ui(program_.uniform("seed"), settings.seed);
    glUniform1f(program_.uniform("step_length"), static_cast<float>(settings.stepLength));
    glUniform1ui(program_.uniform("max_steps"), settings.maxSteps);
    glUniform1f(program_.uniform("power_cutoff"), static_cast<float>(settings.powerCutoff));
    glUniform3f(program_.uniform("power_unit"), powerUnit_.r, powerUnit_.g, powerUnit_.b);
    glUniform3f(program_.uniform("dispersion"), static_cast<float>(dispersion_.r), static_cast<float>(dispersion_.g),
                static_cast<float>(dispersion_.b));
    glUniform1ui(program_.uniform("photon_stride"), static_cast<GLuint>(stride));
    if (options_.recordEnds)
        glUniform1ui(program_.uniform("end_stride"), static_cast<GLuint>(std::max(1, options_.recordStride)));
    const std::size_t batchPhotons = resumable_ ? kResumableBatchPhotons : kBatchPhotons;
    for (std::size_t done = 0; done < count; done += batchPhotons) {
        const std::size_t batch = std::min(batchPhotons, count - done);
        glUniform1ui(program_.uniform("photon_offset"), static_cast<GLuint>(first + done * stride));
        glUniform1ui(program_.uniform("batch_size"), static_cast<GLuint>(batch));
        if (resumable_) {
            glUniform1ui(program_.uniform("resuming"), 0u);
            glUniform1ui(program_.uniform("suspended_capacity"), static_cast<GLuint>(kResumableBatchPhotons));
            suspendedCount_.clearToZero();
            suspendedCount_.bindStorage(layout::kSuspendedCount);
            suspended_[1].bindStorage(layout::kSuspendedIn);  // unread when emitting, but bound
            suspended_[0].bindStorage(layout::kSuspendedOut);
        }
        program_.dispatchCovering(batch);
        if (resumable_) resumeSuspended(batch);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void PhotonStage::combineShares(LightPassExchange& exchange, PhotonStats& stats) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    auto gpu = stats_.downloadAs<layout::GpuPhotonStats>();
    LightPassTallies tallies;
    visitSummedCounters(gpu, stats, PackCounters{tallies.sums});
    const std::size_t counters = tallies.sums.size();
    const std::vector<std::uint64_t> receiverTallies = receivers_.downloadTallies();
    tallies.sums.insert(tallies.sums.end(), receiverTallies.begin(), receiverTallies.end());
    // The wavefront's fixed-point fluence sums as integers (modulo 2^64, so
    // the direction's two's complement too), bit for bit; photons' as floats.
    std::vector<gl::Buffer*> wideBuffers, floatBuffers = {&paths_, &pathPower_};
    for (gl::Buffer* buffer : {&rawFluence_, &rawDirection_, &rawScattered_})
        (fixedFluence_ ? wideBuffers : floatBuffers).push_back(buffer);
    for (const gl::Buffer* buffer : wideBuffers) {
        const std::vector<std::uint64_t> values = downloadWide(*buffer);
        tallies.sums.insert(tallies.sums.end(), values.begin(), values.end());
    }
    tallies.maxima = {gpu.steps.z};
    for (const gl::Buffer* buffer : floatBuffers) {
        const std::vector<float> values = downloadFloats(*buffer);
        tallies.floatSums.insert(tallies.floatSums.end(), values.begin(), values.end());
    }

    exchange.combine(tallies);
    if (!exchange.receivesTotals()) return;  // this share's own tallies stay as they are

    visitSummedCounters(gpu, stats, UnpackCounters{tallies.sums});
    gpu.steps.z = tallies.maxima.at(0);
    stats_.upload(&gpu, sizeof gpu);
    const auto receiverEnd = tallies.sums.begin() + static_cast<std::ptrdiff_t>(counters + receiverTallies.size());
    receivers_.uploadTallies({tallies.sums.begin() + static_cast<std::ptrdiff_t>(counters), receiverEnd});
    auto wide = receiverEnd;
    for (gl::Buffer* buffer : wideBuffers) {
        const auto end = wide + static_cast<std::ptrdiff_t>(buffer->bytes() / sizeof(std::uint64_t));
        uploadWide(*buffer, {wide, end});
        wide = end;
    }
    std::size_t offset = 0;
    for (gl::Buffer* buffer : floatBuffers) {
        const std::size_t bytes = buffer->bytes();
        if (bytes > 0) buffer->upload(tallies.floatSums.data() + offset, bytes);
        offset += bytes / sizeof(float);
    }
}

void PhotonStage::resumeSuspended(std::size_t batch) {
    int written = 0;  // the buffer the last dispatch suspended its photons into
    for (;;) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        const std::size_t suspended =
            std::min<std::size_t>(suspendedCount_.downloadAs<layout::GpuSuspendedCount>().count, batch);
        if (suspended == 0) return;
        resumed_ += suspended;
        ++resumeDispatches_;
        suspended_[written].bindStorage(layout::kSuspendedIn);
        suspended_[1 - written].bindStorage(layout::kSuspendedOut);
        suspendedCount_.clearToZero();
        glUniform1ui(program_.uniform("resuming"), 1u);
        glUniform1ui(program_.uniform("batch_size"), static_cast<GLuint>(suspended));
        program_.dispatchCovering(suspended);
        written = 1 - written;
    }
}

std::vector<float> PhotonStage::downloadFluence() const { return downloadFloats(fluence_); }

std::vector<float> PhotonStage::downloadFluenceDirection() const { return downloadFloats(direction_); }

std::vector<float> PhotonStage::downloadHalfFluence() const { return downloadFloats(halfFluence_); }

std::vector<glm::vec4> PhotonStage::downloadPathPower() const {
    std::vector<glm::vec4> power(pathPower_.bytes() / sizeof(glm::vec4));
    if (!power.empty()) pathPower_.download(power.data(), power.size() * sizeof(glm::vec4));
    return power;
}

std::vector<PhotonEnd> PhotonStage::downloadEnds() const {
    std::vector<glm::vec4> raw(ends_.bytes() / sizeof(glm::vec4));
    if (!raw.empty()) ends_.download(raw.data(), raw.size() * sizeof(glm::vec4));
    std::vector<PhotonEnd> ends(raw.size() / 2);
    for (std::size_t i = 0; i < ends.size(); ++i) {
        ends[i].position = glm::vec3(raw[2 * i]);
        ends[i].fate = static_cast<int>(raw[2 * i].w);
        ends[i].power = glm::vec3(raw[2 * i + 1]);
        ends[i].receiver = static_cast<int>(raw[2 * i + 1].w);
    }
    return ends;
}

std::vector<glm::vec4> PhotonStage::downloadPaths() const {
    return paths_.downloadAll<glm::vec4>();
}

}  // namespace eikon::render
