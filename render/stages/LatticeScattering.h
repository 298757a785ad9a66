// Multiple scattering by lattice-Boltzmann lighting ([Bernabei12] §III-C;
// shaders/lattice_scattering.comp): the power the light pass's photons lose
// to scattering is born on a lattice of 6, 14 or 18 links per voxel, which
// collides and streams it until the flow is steady; the view pass then adds
// σs·φ_ms/(4π), the fluence φ_ms of light scattered at least once scattered
// again (isotropically: the lattice keeps no finer angular detail). In an
// anisotropic medium the source is born in the Henyey–Greenstein
// distribution about the light pass's beam, projected on the links, and
// later scatterings follow HG's remainder once its δ-Eddington forward peak
// is taken out, as a link-to-link phase matrix (render/stages/LatticePhase,
// shaders/common/lattice_phase.glsl).
//
// Channels run one after another (each has its own pair of density buffers,
// so a 128³ grid of 6 links fits one storage block on every driver); where
// the medium and the source are grey (the same in all three channels,
// checked on the GPU each frame) the first is solved and copied. Each
// converges on its own: every `checkInterval` steps the fluence at a sparse
// set of probe cells is read back; with Δ the largest relative change of a
// probe since the last check, among the probes above kFaintProbeFloor of
// the brightest (so the faint regions a picture shows — light transmitted
// through a thick slab — count as much as the bright ones: a relative L1
// change over all probes is the bright region's and understated the
// faint one's remaining change about 25×), and r the ratio of successive
// Δ or of successive summed changes over all probes, whichever is larger
// (the lattice converges geometrically), the remaining change is
// estimated as Δ·r/(1 − r), and the channel stops below the tolerance or at
// the step cap. A frame starts
// from the previous frame's densities (warm start) unless restart() is
// called or nothing was there.
//
// The depth limit. Light born in a voxel leaves it, per generation, in the
// share escape/retention, escape = Σ w_i·exp(−σt·ℓ_i/2) and retention =
// 1 − a(1 − escape) (a the albedo), computed in float: 1 − escape is rounded
// to a multiple of 2⁻²⁴, the spacing of floats just below 1, so retention is
// off by up to 2⁻²⁵ ≈ 3·10⁻⁸ and each generation's transfer by up to
// 2⁻²⁵/retention of itself. A voxel is within the limit while that is at
// most 10⁻⁴ (retention ≥ kMinRetention): at albedo 1 on cubic voxels an
// optical depth across the voxel of 13.96 on 14 links, 16.24 on 6, 13.46 on 18
// (latticeDepthLimit); below albedo 0.9997 every voxel is within it. Beyond
// it each generation gains or loses light by rounding, and light leaving a
// region of such voxels passes through many (a slab 20 voxels thick at
// albedo 1: 0.9% of the light lost at depth 15 per voxel, 4.4% at 20, 67%
// at 30); past about 35 all of it is counted absorbed within a few steps and
// the state stops moving, so its change reads 0. Every frame counts the voxels beyond the limit; a
// lattice that holds any is never reported converged.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/SharpSurfaceBuffer.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace eikon::render {

struct LatticeSettings {
    int directions = 14;       // 6, 14 or 18 (common/lattice_directions.glsl)
    double tolerance = 1e-3;   // on the estimated remaining relative change at the probes
    int maxIterations = 4000;  // per channel
    int checkInterval = 16;    // steps between probe read-backs
    int probeStride = 8;       // a probe every probeStride-th cell on each axis (fewer on small grids)
    // Faces that wrap instead of letting light out, per axis: a laterally
    // periodic slab, or an infinite medium. Scenes use outflow on every face.
    glm::ivec3 periodic{0};

    static LatticeSettings of(const TracerDesc& tracer);
};

// The smallest retention the lattice holds valid: 2⁻²⁵/10⁻⁴.
inline constexpr double kMinRetention = 0x1p-25 / 1e-4;

// The depth limit at albedo 1, as optical depth across the shortest voxel
// edge: where the escape of a voxel of this shape falls to kMinRetention.
double latticeDepthLimit(int directions, const glm::dvec3& voxelSize);

// The light pass's beam, which an anisotropic medium's source is born
// about: smoothed fluence (RGB per cell) and power-weighted direction (xyz
// per cell), PhotonStage::fluence() and fluenceDirection().
struct LatticeBeam {
    const gl::Buffer* fluence = nullptr;
    const gl::Buffer* direction = nullptr;
};

// Probes fainter than this share of the brightest do not enter the
// convergence measure: a thousandth of the brightest is about the faintest
// an image exposed for the bright part shows (8 bits), and the relative
// change of still fainter probes would set the step count alone.
inline constexpr double kFaintProbeFloor = 1e-3;

// The validated resolution: voxels up to a quarter of the lattice's mean
// free path along their longest edge (σt′·h ≤ 1/4, σt′ = σa + σs(1 − f)
// with f = g² the δ-Eddington forward share, 0 where g ≤ 0), where the slabs
// against Monte Carlo hold within 3.3% (docs/accuracy.md, multiple
// scattering). At half a mean free path the lattice's reflectance is 4.3%
// low at albedo 0.5 and its deep transmission 12.6% low at τ = 20, albedo
// 0.99.
inline constexpr double kValidatedVoxelDepth = 0.25;

// Scattering voxels coarser than the validated resolution this frame.
struct LatticeResolution {
    double validated = kValidatedVoxelDepth;
    std::uint64_t coarseVoxels = 0;  // scattering cells of σt′·h above it
    double coarsest = 0.0;           // the largest σt′·h along a scattering voxel's longest edge
};

// Voxels beyond the depth limit this frame.
struct LatticeDepth {
    double limit = 0.0;            // latticeDepthLimit of the grid
    std::uint64_t thickVoxels = 0; // cells whose retention is below kMinRetention in some channel
    double deepest = 0.0;          // the largest optical depth across the shortest voxel edge among them
};

// Per channel: the lattice's steps this frame, its ledger (W) and how it ended.
struct LatticeChannel {
    int iterations = 0;
    bool capped = false;         // stopped at maxIterations, not converged
    double change = 0.0;         // largest relative change of a probe per step, over the last check
    double remaining = 0.0;      // estimated remaining relative change of that probe (the convergence measure)
    double source = 0.0;         // born from the light pass's scattering
    double absorbed = 0.0;
    std::array<double, 6> escaped{};  // through the grid faces −x, +x, −y, +y, −z, +z
    double escapedTotal() const;
    // source − absorbed − escaped: what the lattice has not yet delivered
    // (the flow is not steady); 0 to rounding at convergence.
    double undelivered() const { return source - absorbed - escapedTotal(); }
};

struct LatticeStats {
    int directions = 0;
    bool warmStart = false;  // began from the previous frame's densities
    bool grey = false;       // one channel solved for all three
    std::array<LatticeChannel, 3> channels;
    LatticeDepth depth;
    LatticeResolution resolution;
    int iterations() const;  // all channels together
    bool capped() const;
    // Every channel met the tolerance and no voxel is beyond the depth limit.
    bool converged() const;
    // |undelivered| / source, worst channel (0 where nothing scatters).
    double balanceError() const;
};

class LatticeScattering {
public:
    // `surfaces`: the scene's sharp surfaces (buildSharpSurfaces), whose
    // interfaces reflect the lattice's light by their diffuse Fresnel
    // reflectance; none: light diffuses through every index change.
    LatticeScattering(const GridSpec& grid, const FieldTextures& fields, const LatticeSettings& settings,
                      std::vector<layout::GpuSharpSurface> surfaces = {});

    // Diffuses the light the light pass scattered: `scatteredPower` holds,
    // RGB per cell in W, what the photons lost to scattering there
    // (PhotonStage::scatteredPower). `beam`: where the medium is anisotropic
    // (FieldTextures::hasAnisotropy), the beam that light was scattered out
    // of; required there, unused elsewhere.
    LatticeStats run(const FieldTextures& fields, const gl::Buffer& scatteredPower, const LatticeBeam& beam = {});
    // The next run starts from no light rather than the last densities.
    void restart() { warm_ = false; }

    // φ_ms, RGB per cell, W/m².
    const gl::Buffer& fluence() const { return fluence_; }
    std::vector<float> downloadFluence() const;

private:
    LatticeChannel runChannel(int channel, bool warm);
    std::vector<float> probeFluence(int channel, const gl::Buffer& state);
    LatticeChannel ledger(int channel, const gl::Buffer& state);

    GridSpec grid_;
    LatticeSettings settings_;
    glm::ivec3 probes_{0};
    double depthLimit_ = 0.0;  // latticeDepthLimit of the grid
    struct Survey {
        bool channelsDiffer = false;
        LatticeDepth depth;
        LatticeResolution resolution;
    };
    Survey survey();
    void findInterfaces();
    void findBirthShares(const LatticeBeam& beam);
    gl::Program step_, probe_, result_, survey_, interfacePass_, birthPass_;
    SharpSurfaceBuffer surfaces_;
    gl::Buffer interfaces_;  // per cell uvec4 (lattice_scattering.comp); empty without sharp surfaces
    bool directed_ = false;  // an anisotropic medium: the source is born in the beam's phase function
    gl::Buffer birth_;       // per link slot and cell, the source's share (lattice_scattering.comp); empty unless directed_
    gl::Buffer phase_;       // the phase matrix of later scatterings over g (LatticePhase); empty unless directed_
    std::array<std::array<gl::Buffer, 2>, 3> states_;  // per channel, ping-pong
    std::array<int, 3> current_{0, 0, 0};              // which of the pair holds the densities
    gl::Buffer probeValues_, tallies_, fluence_, surveyValues_;
    bool warm_ = false;
};

}  // namespace eikon::render
