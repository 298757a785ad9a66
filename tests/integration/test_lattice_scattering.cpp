// The multiple-scattering lattice (render/stages/LatticeScattering) against
// closed forms and an independent Monte Carlo reference, fed a source it is
// handed directly (no photons, so no photon noise):
// - an isotropic point source in an infinite medium against diffusion
//   theory, φ(r) = P·exp(−μ_eff·r)/(4π·D·r);
// - homogeneous slabs lit at normal incidence against the analog path
//   tracing of verify/reference/SlabTransport: diffuse reflectance and
//   transmittance from the power the lattice lets out of each face, and as
//   the view pass renders them from its fluence;
// - its ledger: source = absorbed + escaped at convergence; albedo 1 (no
//   blow-up), warm starts, the same bits every run;
// - its depth limit: voxels too thick for its float arithmetic are found,
//   and a lattice that holds them is never converged.
#include "bridge/grid/FieldSet.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/LatticeScattering.h"
#include "sim/field/GridField.h"
#include "tests/integration/GlTestContext.h"
#include "verify/reference/SlabTransport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace eikon {
namespace {

using render::LatticeScattering;
using render::LatticeSettings;
using render::LatticeStats;

// A homogeneous grey medium on `grid` with the lattice's source: the power
// scattered out of the light pass in each cell.
struct LatticeCase {
    GridSpec grid;
    double extinction = 1.0, scattering = 0.5;  // 1/m
    std::vector<float> sourcePower;             // RGB per cell, W

    FieldSet fields() const {
        FieldSet set;
        set.grid = grid;
        const std::size_t cells = grid.cellCount();
        set.deltaIndex.assign(cells, 0.0f);
        set.extinction.assign(3 * cells, static_cast<float>(extinction));
        set.scattering.assign(3 * cells, static_cast<float>(scattering));
        return set;
    }
};

struct LatticeRun {
    LatticeStats stats;
    std::vector<float> fluence;  // φ_ms, RGB per cell
};

LatticeRun runLattice(const FieldSet& set, const std::vector<float>& sourcePower, const LatticeSettings& settings,
                      std::vector<layout::GpuSharpSurface> surfaces = {}) {
    test::glContext();
    render::FieldTextures textures;
    textures.upload(render::hostUpload(set));
    const gl::Buffer source(sourcePower.size() * sizeof(float), sourcePower.data());
    LatticeScattering stage(set.grid, textures, settings, std::move(surfaces));
    LatticeRun run;
    run.stats = stage.run(textures, source);
    run.fluence = stage.downloadFluence();
    return run;
}

LatticeRun runLattice(const LatticeCase& lattice, const LatticeSettings& settings) {
    return runLattice(lattice.fields(), lattice.sourcePower, settings);
}

// ---- Diffusion theory ------------------------------------------------------

// μa = 1 /m, μs = 30 /m (μs′/μa = 30), isotropic scattering, so the
// transport mean free path is ℓ* = 1/(μa + μs) = 1/31 m. Diffusion theory
// is the exact transport solution's limit: at μs′/μa = 10 its decay
// constant μ_eff·ℓ* = 0.522 is 4% above transport's (0.502, the root of
// a·artanh(ν)/ν = 1), 17% in fluence at 8 ℓ*; at 30, 0.311 against 0.307,
// 3.6% at 8 ℓ*. Voxels of ℓ*/2 (optical depth 0.5 each) on a periodic box
// of 51 cells ≈ 25 ℓ*: at r = 8 ℓ* the nearest image source adds
// r/(L − r)·e^{−μ_eff(L − 2r)} ≈ 3%. The point source is the centre
// cell. The lattice's fluence is read as the view pass reads it,
// trilinearly between cell centres, and averaged over a sphere of radius r
// (4 000 Fibonacci points): that is φ(r) of the closed form
// P·e^{−μ_eff r}/(4π D r), D = 1/(3(μa + μs′)), μ_eff = √(μa/D), within
// 10% for r from 2 to 8 ℓ* (every quarter ℓ*); measured worst 3.9% on 6
// links, 5.1% on 14, 4.3% on 18. The lattice's own
// diffusion constant differs from D by about (τ/2)·coth(τ/2) − 1 ≈ 2% at a
// voxel depth τ = 0.5, so the closed form keeps the medium's D.
// The cells themselves, binned into one-voxel shells, show the lattice's
// ray effect: light still streaming along the links from the source, and
// so only on the cells those links pass through. 6 and 18 links: worst
// shell 7.4% and 9.2%; 14 links 7.9% from 2.5 ℓ* out but 12.2% low at
// 2 ℓ*, a shell 4 voxels out that holds no cell on a body diagonal (they lie
// 3.5 and 5.2 voxels out) and so misses the light on the 8 diagonals there.
// The shells are bounded at 10%, and at 13% for that one shell of 14 links.
void expectDiffusionProfile(int directions) {
    const double mua = 1.0, mus = 30.0;
    const double transport = 1.0 / (mua + mus);
    const double h = transport / 2.0;
    const int n = 51;
    LatticeCase lattice;
    lattice.grid = {glm::ivec3(n), glm::dvec3(-0.5 * n * h), glm::dvec3(0.5 * n * h)};
    lattice.extinction = mua + mus;
    lattice.scattering = mus;
    const std::size_t cells = lattice.grid.cellCount();
    lattice.sourcePower.assign(3 * cells, 0.0f);
    const double power = 1.0;  // W, red channel only: the others hold no light
    const std::size_t centre = lattice.grid.linearIndex(n / 2, n / 2, n / 2);
    lattice.sourcePower[3 * centre] = static_cast<float>(power);

    LatticeSettings settings;
    settings.directions = directions;
    settings.tolerance = 1e-4;
    settings.periodic = glm::ivec3(1);
    const LatticeRun run = runLattice(lattice, settings);
    EXPECT_FALSE(run.stats.capped());
    EXPECT_NEAR(run.stats.channels[0].source, power, 1e-5 * power);
    EXPECT_LT(run.stats.balanceError(), 1e-4);

    const double D = 1.0 / (3.0 * (mua + mus));
    const double muEff = std::sqrt(mua / D);
    const auto diffusion = [&](double r) { return power * std::exp(-muEff * r) / (4.0 * std::numbers::pi * D * r); };
    const std::string links = std::to_string(directions) + " links";

    // The lattice's red channel and the closed form, both at cell centres
    // (lattice coordinate 0..n−1) and both read trilinearly, so that
    // interpolation bends neither: the source cell, where the closed form
    // is infinite, lies more than a voxel inside every sphere sampled.
    sim::GridField latticeFluence, closedForm;
    for (sim::GridField* field : {&latticeFluence, &closedForm}) {
        field->size = glm::ivec3(n);
        field->values.assign(cells, 0.0);
    }
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t cell = lattice.grid.linearIndex(i, j, k);
                latticeFluence.values[cell] = run.fluence[3 * cell];
                const double r = h * glm::length(glm::dvec3(i - n / 2, j - n / 2, k - n / 2));
                if (r > 0.0) closedForm.values[cell] = diffusion(r);
            }
    double worstSphere = 0.0;
    const int points = 4000;
    for (double r = 2.0 * transport; r <= 8.0 * transport + 1e-12; r += 0.25 * transport) {
        double measured = 0.0, expected = 0.0;
        for (int p = 0; p < points; ++p) {
            const double z = 1.0 - (2.0 * p + 1.0) / points;
            const double phi = p * std::numbers::pi * (3.0 - std::sqrt(5.0));  // golden angle
            const double s = std::sqrt(1.0 - z * z);
            // The source cell's centre is the origin.
            const glm::dvec3 at = r / h * glm::dvec3(s * std::cos(phi), s * std::sin(phi), z) + glm::dvec3(n / 2);
            measured += sim::sampleTrilinear(latticeFluence, at);
            expected += sim::sampleTrilinear(closedForm, at);
        }
        const double error = measured / expected - 1.0;
        worstSphere = std::max(worstSphere, std::abs(error));
        EXPECT_LT(std::abs(error), 0.10) << links << ", sphere r = " << r / transport << " ℓ*";
    }
    test::reportFigure(("worst_diffusion_error_sphere_d3q" + std::to_string(directions)).c_str(), worstSphere);

    std::vector<double> measured(n, 0.0), expected(n, 0.0);  // one-voxel shells
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double r = h * glm::length(glm::dvec3(i - n / 2, j - n / 2, k - n / 2));
                const int bin = static_cast<int>(std::lround(r / h));
                if (bin == 0 || bin >= n) continue;
                measured[bin] += run.fluence[3 * lattice.grid.linearIndex(i, j, k)];
                expected[bin] += diffusion(r);
            }
    double worstShell = 0.0;
    for (int bin = static_cast<int>(std::ceil(2.0 * transport / h)); bin <= static_cast<int>(8.0 * transport / h); ++bin) {
        const double error = measured[bin] / expected[bin] - 1.0;
        worstShell = std::max(worstShell, std::abs(error));
        const bool rayEffect = directions == 14 && bin * h < 2.5 * transport;
        EXPECT_LT(std::abs(error), rayEffect ? 0.13 : 0.10) << links << ", shell r = " << bin * h / transport << " ℓ*";
    }
    test::reportFigure(("worst_diffusion_error_shell_d3q" + std::to_string(directions)).c_str(), worstShell);
}

TEST(LatticeScattering, PointSourceMatchesDiffusionTheorySixLinks) { expectDiffusionProfile(6); }
TEST(LatticeScattering, PointSourceMatchesDiffusionTheoryFourteenLinks) { expectDiffusionProfile(14); }
TEST(LatticeScattering, PointSourceMatchesDiffusionTheoryEighteenLinks) { expectDiffusionProfile(18); }

// ---- Slabs against Monte Carlo ---------------------------------------------

struct SlabResult {
    // Diffuse, fractions of the incident power: what the lattice lets out
    // of each face, and what the view pass shows (slabExitance).
    double reflected, transmitted;
    double renderedReflected, renderedTransmitted;
    LatticeStats stats;
};

// E2(x) = ∫₀¹ e^{−x/μ} dμ = e^{−x} + x·Ei(−x), the slab's escape kernel.
double exponentialIntegral2(double x) { return x > 0.0 ? std::exp(-x) + x * std::expint(-x) : 1.0; }

// The exitance of a slab's face as the view pass renders it: radiance
// along each outgoing ray is the in-scattering σs(φ_c + φ_ms)/(4π) of
// shaders/view_rays.comp (φ_c = E0·e^{−μt z} the collimated beam's
// fluence, φ_ms the lattice's, linear between cell centres and held at the
// end cells), attenuated exactly to the face. Integrated over the
// hemisphere, M = (μs/2)∫ φ(z) E2(μt·d(z)) dz with d the distance to the
// face; quadrature by 64 midpoints per cell.
double slabExitance(const std::vector<float>& fluence, int cells, double tau, double albedo, bool farFace) {
    const double h = 1.0 / cells, mut = tau, mus = albedo * tau;
    const int points = 64;
    double sum = 0.0;
    for (int p = 0; p < cells * points; ++p) {
        const double z = (p + 0.5) * h / points;
        const double u = std::clamp(z / h - 0.5, 0.0, cells - 1.0);
        const int low = std::min(static_cast<int>(u), cells - 1), high = std::min(low + 1, cells - 1);
        const double t = u - low;
        const double multiple = (1.0 - t) * fluence[3 * low] + t * fluence[3 * high];
        sum += (std::exp(-mut * z) + multiple) * exponentialIntegral2(mut * (farFace ? 1.0 - z : z));
    }
    return 0.5 * mus * sum * h / points;
}

// A slab of optical thickness τ and albedo a filling a one-cell column
// (periodic in x and y: a laterally infinite slab) of cubic voxels, lit at
// normal incidence from z = 0 with E0 = 1 W/m². The source is exact: what
// the collimated beam scatters in each cell, a·E0·h²·(e^{−τ_k} − e^{−τ_{k+1}}).
// Cells: 40, or 4 per unit of τ where that is more (`cells` overrides).
SlabResult latticeSlab(double tau, double albedo, int directions, double tolerance = 1e-6, int cells = 0) {
    const int n = cells > 0 ? cells : std::max(40, static_cast<int>(4 * tau));
    const double thickness = 1.0, h = thickness / n;
    LatticeCase slab;
    slab.grid = {glm::ivec3(1, 1, n), glm::dvec3(0.0), glm::dvec3(h, h, thickness)};
    slab.extinction = tau / thickness;
    slab.scattering = albedo * slab.extinction;
    slab.sourcePower.assign(3 * static_cast<std::size_t>(n), 0.0f);
    const double dtau = slab.extinction * h;
    for (int k = 0; k < n; ++k) {
        const double scattered = albedo * h * h * (std::exp(-k * dtau) - std::exp(-(k + 1) * dtau));
        for (int c = 0; c < 3; ++c) slab.sourcePower[3 * k + c] = static_cast<float>(scattered);
    }
    LatticeSettings settings;
    settings.directions = directions;
    settings.tolerance = tolerance;
    settings.maxIterations = 200000;
    settings.periodic = glm::ivec3(1, 1, 0);
    const LatticeRun run = runLattice(slab, settings);
    const double incident = h * h;  // W
    return {run.stats.channels[0].escaped[4] / incident, run.stats.channels[0].escaped[5] / incident,
            slabExitance(run.fluence, n, tau, albedo, false), slabExitance(run.fluence, n, tau, albedo, true), run.stats};
}

constexpr long long kSlabPhotons = 400000;

reference::SlabFractions monteCarloSlab(double tau, double albedo) {
    reference::SlabSetup setup;
    setup.opticalThickness = tau;
    setup.albedo = albedo;
    setup.photons = kSlabPhotons;
    return reference::traceSlab(setup);
}

// Every slab's ledger closes at convergence: what was born is absorbed or
// leaves through a face, to 1e-4.
TEST(LatticeScattering, SlabLedgerCloses) {
    for (double albedo : {0.5, 0.99}) {
        const SlabResult slab = latticeSlab(5.0, albedo, 14);
        EXPECT_FALSE(slab.stats.capped());
        EXPECT_LT(slab.stats.balanceError(), 1e-4) << "albedo " << albedo;
        EXPECT_GT(slab.stats.iterations(), 0);
    }
}

// Nine slabs, τ = 1, 5, 20 and albedo 0.5, 0.9, 0.99, against 400 000
// photons of Monte Carlo each, two ways: the power the lattice lets out of
// each face, and the exitance the view pass renders from its fluence
// (slabExitance). The 14-link lattice, the default: both within 10% in
// every slab (measured: at most 3.3% and 2.8%); its error falls with the
// voxel's optical depth (τ = 20 on 20, 40, 80 cells: reflectance at albedo
// 0.99 rendered 11%, 2.9%, 0.5% high), so what remains is the lattice's
// spatial discretisation. The 18-link lattice stays at its angular error
// however fine the voxels: its links leave a face more slowly than the
// continuum of directions does (common/lattice_directions.glsl) and 40% of
// its weight runs parallel to the face, so at albedo 0.5 it lets out 13–14%
// too little reflectance, and its fluence piles up beneath the face, which
// renders 10–20% too bright at albedo 0.9–0.99. It is bounded here at what
// it measures (15% on the ledger, 21% rendered). The paper's 6 links are
// worse again, two thirds of their weight parallel to the face: reflectance
// 38–40% low at albedo 0.5 on the ledger, up to 85% too bright rendered
// (bounded at 42% and 87%).
// Where the reference saw fewer than 100 transmitted photons (τ = 20 below
// albedo 0.99: T of 1.5e-5 ± 0.6e-5 and none) transmittance is not
// compared; elsewhere three binomial errors are added to the bound.
TEST(LatticeScattering, SlabsAgainstMonteCarlo) {
    for (double tau : {1.0, 5.0, 20.0})
        for (double albedo : {0.5, 0.9, 0.99}) {
            const reference::SlabFractions mc = monteCarloSlab(tau, albedo);
            const std::string label = "tau " + std::to_string(tau) + " albedo " + std::to_string(albedo);
            for (int directions : {14, 18, 6}) {
                const SlabResult slab = latticeSlab(tau, albedo, directions);
                EXPECT_FALSE(slab.stats.capped()) << label;
                const double ledgerBound = directions == 14 ? 0.10 : (directions == 18 ? 0.15 : 0.42);
                const double renderedBound = directions == 14 ? 0.10 : (directions == 18 ? 0.21 : 0.87);
                const std::string name = label + " d3q" + std::to_string(directions);
                const auto expectWithin = [&](const char* what, double value, double reference, double error,
                                              double bound) {
                    const double allowed = bound * reference + 3.0 * error;
                    EXPECT_LT(std::abs(value - reference), allowed) << what << ", " << name;
                    test::reportFigure((std::string(what) + "_error_" + name).c_str(), value / reference - 1.0);
                };
                expectWithin("reflectance", slab.reflected, mc.reflected, mc.reflectedError, ledgerBound);
                expectWithin("rendered_reflectance", slab.renderedReflected, mc.reflected, mc.reflectedError,
                             renderedBound);
                if (mc.diffuselyTransmitted * kSlabPhotons >= 100) {
                    expectWithin("transmittance", slab.transmitted, mc.diffuselyTransmitted,
                                 mc.diffuselyTransmittedError, ledgerBound);
                    expectWithin("rendered_transmittance", slab.renderedTransmitted, mc.diffuselyTransmitted,
                                 mc.diffuselyTransmittedError, renderedBound);
                }
            }
        }
}

// A slab of relative index m (a sharp box, its faces two cells in from the
// grid's, clear cells between) lit as above: the beam that entered bounces
// between the faces (reflectance R0 = ((m − 1)/(m + 1))² at normal
// incidence), so each cell's source sums its forward passes, weight
// 1/(1 − R0²e^{−2τ}), and its backward ones, R0·e^{−τ} times that. R and T
// are fractions of the power that entered.
SlabResult fresnelSlab(double tau, double albedo, double relativeIndex, int directions) {
    const int n = std::max(40, static_cast<int>(4 * tau)), clear = 2, cells = n + 2 * clear;
    const double h = 1.0 / n;
    FieldSet set;
    set.grid = {glm::ivec3(1, 1, cells), glm::dvec3(0.0, 0.0, -clear * h), glm::dvec3(h, h, 1.0 + clear * h)};
    set.deltaIndex.assign(cells, 0.0f);
    set.extinction.assign(3 * cells, 0.0f);
    set.scattering.assign(3 * cells, 0.0f);
    std::vector<float> source(3 * static_cast<std::size_t>(cells), 0.0f);
    const double dtau = tau * h, r0 = std::pow((relativeIndex - 1.0) / (relativeIndex + 1.0), 2);
    const double forward = 1.0 / (1.0 - r0 * r0 * std::exp(-2.0 * tau)), backward = r0 * std::exp(-tau) * forward;
    for (int k = 0; k < n; ++k) {
        const double down = std::exp(-k * dtau) - std::exp(-(k + 1) * dtau);
        const double up = std::exp(-(tau - (k + 1) * dtau)) - std::exp(-(tau - k * dtau));
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = 3 * static_cast<std::size_t>(k + clear) + c;
            set.extinction[at] = static_cast<float>(tau);
            set.scattering[at] = static_cast<float>(albedo * tau);
            source[at] = static_cast<float>(albedo * h * h * (forward * down + backward * up));
        }
    }
    layout::GpuSharpSurface box{};
    box.shapeA = glm::vec4(-1e3f, -1e3f, 0.0f, static_cast<float>(layout::kSharpBox));
    box.shapeB = glm::vec4(1e3f, 1e3f, 1.0f, 0.0f);
    box.optics = glm::vec4(static_cast<float>(relativeIndex - 1.0), 1.0f, 0.0f, 0.0f);
    LatticeSettings settings;
    settings.directions = directions;
    settings.tolerance = 1e-6;
    settings.maxIterations = 400000;
    settings.periodic = glm::ivec3(1, 1, 0);
    const LatticeRun run = runLattice(set, source, settings, {box});
    const double incident = h * h;
    return {run.stats.channels[0].escaped[4] / incident, run.stats.channels[0].escaped[5] / incident, 0.0, 0.0, run.stats};
}

// Fresnel slabs of water and glass (m = 1.33, 1.5), τ = 1 and 5, albedo
// 0.5, 0.9, 0.99, against the Monte Carlo with the same faces, on the
// default 14 links. Where light scatters many times before it meets a face
// (albedo 0.99) its radiance there is nearly isotropic and the diffuse
// reflectance R_d is the right average: R and T within 2% (bound 3%).
// Where it meets the face after few scatterings its radiance is not
// isotropic, and the lattice's links, each reflected by R_d where the
// continuum reflects the directions inside the escape cone (μ > 0.745 in
// glass) by 4% and traps the rest, let the wrong share out: measured up to
// 13% at albedo 0.9 (bound 15%) and 27% at 0.5 (bound 30%). The 18-link
// lattice errs less at albedo 0.5 (at most 26% and 11% in R) and more at
// 0.99 (3.5%). The ledger closes either way.
TEST(LatticeScattering, FresnelSlabsAgainstMonteCarlo) {
    for (double index : {1.33, 1.5})
        for (double tau : {1.0, 5.0})
            for (double albedo : {0.5, 0.9, 0.99}) {
                reference::SlabSetup setup;
                setup.opticalThickness = tau;
                setup.albedo = albedo;
                setup.relativeIndex = index;
                setup.photons = kSlabPhotons;
                const reference::SlabFractions mc = reference::traceSlab(setup);
                const SlabResult slab = fresnelSlab(tau, albedo, index, 14);
                const std::string label = "index " + std::to_string(index) + " tau " + std::to_string(tau) +
                                          " albedo " + std::to_string(albedo);
                const double bound = albedo > 0.95 ? 0.03 : (albedo > 0.7 ? 0.15 : 0.30);
                EXPECT_FALSE(slab.stats.capped()) << label;
                EXPECT_LT(slab.stats.balanceError(), 1e-4) << label;
                EXPECT_LT(std::abs(slab.reflected - mc.reflected), bound * mc.reflected + 3.0 * mc.reflectedError) << label;
                EXPECT_LT(std::abs(slab.transmitted - mc.diffuselyTransmitted),
                          bound * mc.diffuselyTransmitted + 3.0 * mc.diffuselyTransmittedError)
                    << label;
                test::reportFigure(("fresnel_reflectance_error_" + label).c_str(), slab.reflected / mc.reflected - 1.0);
                test::reportFigure(("fresnel_transmittance_error_" + label).c_str(),
                                   slab.transmitted / mc.diffuselyTransmitted - 1.0);
            }
}

// Albedo 1: nothing is absorbed, so everything born leaves through the two
// faces, R + T = 1 − e^{−τ} (the collimated beam's scattered part), and the
// lattice converges rather than blowing up. And voxels a hundred mean free
// paths thick (τ = 4000 over 40 cells, albedo 0.999): the closed-form
// collision stays finite and the ledger closes.
TEST(LatticeScattering, AlbedoOneAndOpaqueVoxelsStayBounded) {
    const SlabResult lossless = latticeSlab(5.0, 1.0, 14);
    EXPECT_FALSE(lossless.stats.capped());
    EXPECT_NEAR(lossless.reflected + lossless.transmitted, 1.0 - std::exp(-5.0), 1e-4);
    test::reportFigure("albedo_one_iterations", lossless.stats.channels[0].iterations);

    const SlabResult opaque = latticeSlab(4000.0, 0.999, 14, 1e-4, 40);
    EXPECT_TRUE(std::isfinite(opaque.reflected));
    EXPECT_GT(opaque.reflected, 0.0);
    EXPECT_LT(opaque.reflected, 1.0);
    EXPECT_EQ(opaque.transmitted, 0.0);
    EXPECT_LT(opaque.stats.balanceError(), 1e-4);
}

// The depth limit (LatticeScattering.h), on slabs of albedo 1, 20 cubic
// voxels thick. At an optical depth of 40 per voxel the float transfer
// counts nearly all the light as absorbed and the state stops moving: the
// probes see no change and the ledger balances, yet the lattice must not be
// reported converged, and every voxel is counted beyond the limit with its
// depth. At 10 per voxel, within the limit, it converges as before and lets
// out all the light to 1e-3.
TEST(LatticeScattering, VoxelsBeyondTheDepthLimitAreNeverConverged) {
    EXPECT_NEAR(render::latticeDepthLimit(14, glm::dvec3(0.05)), 13.96, 0.01);
    EXPECT_NEAR(render::latticeDepthLimit(6, glm::dvec3(0.05)), 16.24, 0.01);
    EXPECT_NEAR(render::latticeDepthLimit(18, glm::dvec3(0.05)), 13.46, 0.01);
    const int cells = 20;
    const SlabResult thick = latticeSlab(40.0 * cells, 1.0, 14, 1e-3, cells);
    EXPECT_FALSE(thick.stats.capped());  // it stopped: nothing moved
    EXPECT_LT(thick.reflected + thick.transmitted, 0.01);
    EXPECT_FALSE(thick.stats.converged());
    EXPECT_EQ(thick.stats.depth.thickVoxels, static_cast<std::uint64_t>(cells));
    EXPECT_NEAR(thick.stats.depth.deepest, 40.0, 1e-3);
    EXPECT_NEAR(thick.stats.depth.limit, 13.96, 0.01);

    const SlabResult thin = latticeSlab(10.0 * cells, 1.0, 14, 1e-3, cells);
    EXPECT_TRUE(thin.stats.converged());
    EXPECT_EQ(thin.stats.depth.thickVoxels, 0u);
    EXPECT_NEAR(thin.reflected + thin.transmitted, 1.0, 1e-3);
}

// The convergence measure sees faint regions. A slab of τ = 20, albedo
// 0.99 on 80 cells lets out 0.75 of the light back and 0.015 through its
// far face, where the fluence is some hundred times fainter than under the
// lit face. Stopped at the default tolerance 1e-3 from a cold start, its
// transmittance is within 2e-3 of the lattice's own at 1e-7 and the
// reflectance within 1e-3, and the remaining change it reported is within
// a factor 3 of the true one (measured 8.6e-4 after 1392 steps, reported
// 9.1e-4). A relative L1 change over all probes, the bright region's,
// stopped it after 1104 steps 5.0e-3 short, reporting 9.3e-4.
TEST(LatticeScattering, ConvergenceCountsTheFaintRegions) {
    const SlabResult stopped = latticeSlab(20.0, 0.99, 14, 1e-3, 80);
    const SlabResult reference = latticeSlab(20.0, 0.99, 14, 1e-7, 80);
    ASSERT_FALSE(stopped.stats.capped());
    ASSERT_FALSE(reference.stats.capped());
    const double transmittedChange = std::abs(stopped.transmitted / reference.transmitted - 1.0);
    const double reflectedChange = std::abs(stopped.reflected / reference.reflected - 1.0);
    test::reportFigure("faint_transmittance_remaining_change", transmittedChange);
    test::reportFigure("bright_reflectance_remaining_change", reflectedChange);
    test::reportFigure("reported_remaining_change", stopped.stats.channels[0].remaining);
    test::reportFigure("steps_at_tolerance_1e-3", stopped.stats.channels[0].iterations);
    EXPECT_LT(transmittedChange, 2e-3);
    EXPECT_LT(reflectedChange, 1e-3);
    EXPECT_LT(transmittedChange, 3.0 * stopped.stats.channels[0].remaining);
}

// Voxels coarser than the validated quarter of a reduced mean free path are
// counted: τ = 20 on 40 cells (0.5 each, all 40 coarse), on 100 (0.2: none).
TEST(LatticeScattering, VoxelsCoarserThanTheValidatedResolutionAreCounted) {
    const SlabResult coarse = latticeSlab(20.0, 0.99, 14, 1e-3, 40);
    EXPECT_EQ(coarse.stats.resolution.coarseVoxels, 40u);
    EXPECT_NEAR(coarse.stats.resolution.coarsest, 0.5, 1e-6);
    EXPECT_EQ(coarse.stats.resolution.validated, 0.25);
    const SlabResult fine = latticeSlab(20.0, 0.99, 14, 1e-3, 100);
    EXPECT_EQ(fine.stats.resolution.coarseVoxels, 0u);
    EXPECT_NEAR(fine.stats.resolution.coarsest, 0.2, 1e-6);
}

// A frame starts from the last one's densities: the same source again is
// converged at the first check, a source 10% stronger takes fewer steps
// than from nothing; and two lattices given the same input agree bit for
// bit (fixed-order sums, no atomics).
TEST(LatticeScattering, WarmStartsSaveStepsAndRunsRepeatBitForBit) {
    test::glContext();
    const int n = 24;
    LatticeCase lattice;
    lattice.grid = {glm::ivec3(n), glm::dvec3(-0.12), glm::dvec3(0.12)};
    lattice.extinction = 50.0;
    lattice.scattering = 45.0;
    lattice.sourcePower.assign(3 * lattice.grid.cellCount(), 0.0f);
    for (int k = 8; k < 16; ++k)
        for (int j = 8; j < 16; ++j)
            for (int i = 8; i < 16; ++i)
                for (int c = 0; c < 3; ++c) lattice.sourcePower[3 * lattice.grid.linearIndex(i, j, k) + c] = 1.0f + c;
    const FieldSet set = lattice.fields();
    render::FieldTextures textures;
    textures.upload(render::hostUpload(set));
    gl::Buffer source(lattice.sourcePower.size() * sizeof(float), lattice.sourcePower.data());
    LatticeSettings settings;
    settings.tolerance = 1e-4;
    LatticeScattering stage(set.grid, textures, settings), twin(set.grid, textures, settings);

    const LatticeStats cold = stage.run(textures, source);
    twin.run(textures, source);
    EXPECT_EQ(twin.downloadFluence(), stage.downloadFluence());
    // Converged at the second check of each channel: the first has no ratio to extrapolate by.
    const LatticeStats again = stage.run(textures, source);
    EXPECT_FALSE(cold.warmStart);
    EXPECT_TRUE(again.warmStart);
    EXPECT_EQ(again.iterations(), 3 * 2 * settings.checkInterval);

    std::vector<float> brighter = lattice.sourcePower;
    for (float& value : brighter) value *= 1.1f;
    source.upload(brighter.data(), brighter.size() * sizeof(float));
    const LatticeStats warm = stage.run(textures, source);
    stage.restart();
    const LatticeStats restarted = stage.run(textures, source);
    EXPECT_FALSE(restarted.warmStart);
    EXPECT_LT(warm.iterations(), restarted.iterations());
    test::reportFigure("cold_iterations", restarted.iterations());
    test::reportFigure("warm_iterations", warm.iterations());
}

}  // namespace
}  // namespace eikon
