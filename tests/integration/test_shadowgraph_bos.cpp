// The shadowgraph and background-oriented schlieren against the Gaussian
// bump's closed forms (tests/integration/GaussianBump.h; docs/accuracy.md,
// "Diagnostics").
//
// Shadowgraph: to first order in A a ray through the bump at ρ leaves it as
// if bent by ε = ∇⊥Φ (Φ = OPD) at the bump's centre plane — the bump is
// symmetric about it — and lands on a screen L beyond that plane at
// R = ρ + L·∇⊥Φ(ρ). With Φ = P·exp(−ρ²/σ²) the map is radial,
// R(ρ) = ρ·(1 − 2κ·e^(−ρ²/σ²)), κ = L·P/σ², and the intensity law gives
// I/I₀ = 1 / |det ∂R/∂ρ| = 1 / |(R/ρ)·(dR/dρ)| summed over the sheets that
// reach a point. Weak (|L·∇²Φ| ≪ 1): ΔI/I₀ = −L·∇²Φ = −L·∫∇²⊥n dz
// ([Settles01] ch. 6). The map folds where dR/dρ = 0 (a ring caustic) once
// 2κ > 1 (its axis focuses first, at 2κ = 1).
//
// BOS: a pinhole camera sees a background plane behind the bump; each ray
// bends by the paraxial ε of its straight line through the bump, at the
// point of its closest approach to the centre (the bump is symmetric about
// it), and lands on the background beside the straight ray's point. The
// background point that pixel sees with the medium is seen without it
// where its own straight ray points: the displacement, in pixels. Near the
// axis it is −f_px·Z_D·ε/(Z_A + Z_D) (f_px the focal length in pixels, Z_A
// the camera's distance from the bump's centre plane, Z_D the background's).
#include "render/graph/FrameRenderer.h"
#include "tests/integration/GaussianBump.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace eikon {
namespace {

using namespace test;

constexpr double kFarFace = 2.5;  // the grid's far face from the bump scene's camera, m

DiagnosticDesc shadowgraph(double screenDistance) {
    DiagnosticDesc diagnostic;
    diagnostic.type = DiagnosticDesc::Type::Shadowgraph;
    diagnostic.screenDistance = screenDistance;
    return diagnostic;
}

// I/I₀ (red) per pixel, row 0 at the top.
std::vector<double> shadowgraphOf(const Scene& scene, const Bump& bump) {
    glContext();
    const FieldSet fields = sampledBump(scene, bump);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const std::vector<float> hdr = renderer.diagnosticStage()->downloadHdr();
    std::vector<double> intensity;
    for (std::size_t i = 0; i < hdr.size(); i += 4) intensity.push_back(hdr[i]);
    return intensity;
}

// The thin lens's map R(ρ) = ρ·(1 − 2κ·e^(−ρ²/σ²)) and the intensity it gives, summed over its sheets.
struct ThinLens {
    double kappa;

    double radial(double rho) const { return rho * (1.0 - 2.0 * kappa * std::exp(-rho * rho / (kBumpSigma * kBumpSigma))); }
    double slope(double rho) const {
        const double u = rho * rho / (kBumpSigma * kBumpSigma);
        return 1.0 - 2.0 * kappa * std::exp(-u) * (1.0 - 2.0 * u);
    }
    // Only where the map does not fold (2κ < 1): one sheet.
    double intensity(double screenRadius) const {
        double low = 0.0, high = screenRadius + 1.0;  // R is increasing: bisect R(ρ) = r
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (low + high);
            (radial(mid) < screenRadius ? low : high) = mid;
        }
        const double rho = 0.5 * (low + high);
        const double ratio = rho > 0.0 ? radial(rho) / rho : 1.0 - 2.0 * kappa;
        return 1.0 / std::abs(ratio * slope(rho));
    }
    // The fold dR/dρ = 0 (2κ > 1): its radius on the screen, |R| there.
    double causticRadius() const {
        double low = 0.0, high = kBumpSigma * std::sqrt(0.5);  // the slope rises through 0 once in u ∈ (0, ½)
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (low + high);
            (slope(mid) < 0.0 ? low : high) = mid;
        }
        return std::abs(radial(0.5 * (low + high)));
    }
};

// κ = L·P/σ², L from the bump's centre plane to the screen.
double kappaOf(const Bump& bump, double screenDistance) {
    return (screenDistance + kFarFace - 2.0) * bump.peakOpd() / (kBumpSigma * kBumpSigma);
}

// A weak lens, L = 1.5 m: |L·∇²Φ| ≤ 0.0071. Where the small-deflection
// limit holds the contrast is −L·∇²Φ with ∇²Φ = 4Φ/σ²·(ρ²/σ² − 1); its own
// error against the exact map is of the order of (L·∇²Φ)², 0.7% of the
// peak here. The pixels hold their mean irradiance; the closed form is
// taken at their centres (their difference, ~(h/σ)²/24, is below 1e-4).
TEST(Shadowgraph, AWeakLensShowsMinusLTimesTheLaplacianOfTheOpticalPath) {
    const double screen = 1.0, lever = screen + kFarFace - 2.0;
    const Scene scene = bumpScene(128, 128, shadowgraph(screen));
    const Bump bump;
    const std::vector<double> intensity = shadowgraphOf(scene, bump);
    const double peak = lever * 4.0 * bump.peakOpd() / (kBumpSigma * kBumpSigma);
    double squares = 0.0, worst = 0.0, total = 0.0;
    for (int j = 0; j < 128; ++j)
        for (int i = 0; i < 128; ++i) {
            const glm::dvec2 p = pixelPoint(scene, i, j);
            const double u = glm::dot(p, p) / (kBumpSigma * kBumpSigma);
            const double expected = -lever * 4.0 * bump.opd(p) / (kBumpSigma * kBumpSigma) * (u - 1.0);
            const double contrast = intensity[static_cast<std::size_t>(j * 128 + i)] - 1.0;
            squares += (contrast - expected) * (contrast - expected);
            worst = std::max(worst, std::abs(contrast - expected));
            total += intensity[static_cast<std::size_t>(j * 128 + i)];
        }
    reportFigure("shadowgraph_weak_peak_contrast", peak);
    reportFigure("shadowgraph_weak_contrast_rms_error_of_peak", std::sqrt(squares / (128 * 128)) / peak);
    reportFigure("shadowgraph_weak_contrast_worst_error_of_peak", worst / peak);
    EXPECT_LE(worst, 0.02 * peak);
    // The light is moved, not made or lost: the bump bends less than a
    // micrometre of it past the image's edge.
    EXPECT_NEAR(total / (128 * 128), 1.0, 1e-5);
}

// A strong lens, 2κ = 0.4 (I/I₀ = 2.8 on the axis), against the thin lens's
// exact intensity law, at the same κ from bumps of A = 1e-2, 1e-3, 1e-4
// (the screen 1.7, 16.9 and 169 m on): the paraxial error — the ray moves
// ~ε·σ inside the bump, so the thin-lens map is off by a part in ~A — must
// shrink with A to the grid's own error, 2% of the peak contrast at 1e-4.
TEST(Shadowgraph, AStrongLensFollowsTheExactIntensityLawAsTheParaxialErrorShrinks) {
    const double amplitudes[] = {1e-2, 1e-3, 1e-4};
    const char* const names[] = {"1e-2", "1e-3", "1e-4"};
    std::vector<double> errors;
    for (std::size_t a = 0; a < 3; ++a) {
        Bump bump;
        bump.amplitude = amplitudes[a];
        const ThinLens lens{0.2};
        const double screen = lens.kappa * kBumpSigma * kBumpSigma / bump.peakOpd() - (kFarFace - 2.0);
        const Scene scene = bumpScene(128, 128, shadowgraph(screen));
        EXPECT_NEAR(kappaOf(bump, screen), lens.kappa, 1e-12);
        const std::vector<double> intensity = shadowgraphOf(scene, bump);
        const double peak = lens.intensity(0.0) - 1.0;
        double squares = 0.0;
        for (int j = 0; j < 128; ++j)
            for (int i = 0; i < 128; ++i) {
                const double expected = lens.intensity(glm::length(pixelPoint(scene, i, j)));
                const double found = intensity[static_cast<std::size_t>(j * 128 + i)];
                squares += (found - expected) * (found - expected);
            }
        errors.push_back(std::sqrt(squares / (128 * 128)) / peak);
        reportFigure(("shadowgraph_strong_rms_error_of_peak_amplitude_" + std::string(names[a])).c_str(),
                     errors.back());
    }
    EXPECT_GT(errors[0], errors[2]);
    EXPECT_LE(errors[2], 0.01);
}

// Past the focus, 2κ = 4: the map folds, and where the row through the
// axis leaves the ring caustic — at |R| where dR/dρ = 0, 0.1617 m, 26.06
// pixels from the axis — its light falls steeply: the pixel that holds the
// fold is the last bright one, and the steepest fall of the row (beyond 5
// pixels from the axis, which is a caustic too: the circle where R = 0
// focuses on it) is from it to the next, on either side.
TEST(Shadowgraph, AStrongLensCastsItsCausticWhereTheMapFolds) {
    const int size = 129;  // the middle pixel's centre on the axis
    Bump bump;
    const ThinLens lens{2.0};
    const double screen = lens.kappa * kBumpSigma * kBumpSigma / bump.peakOpd() - (kFarFace - 2.0);
    const Scene scene = bumpScene(size, size, shadowgraph(screen));
    const std::vector<double> intensity = shadowgraphOf(scene, bump);
    const double pixel = kBumpViewWidth / size, expected = lens.causticRadius() / pixel;
    reportFigure("shadowgraph_caustic_radius_pixels", expected);
    const int row = size / 2;
    const auto at = [&](int offset) { return intensity[static_cast<std::size_t>(row * size + row + offset)]; };
    for (const int side : {-1, 1}) {
        int fold = 5;
        for (int k = 5; k < row; ++k)
            if (at(side * k) - at(side * (k + 1)) > at(side * fold) - at(side * (fold + 1))) fold = k;
        reportFigure(side < 0 ? "shadowgraph_caustic_left_pixels_off" : "shadowgraph_caustic_right_pixels_off",
                     fold - expected);
        EXPECT_LE(std::abs(fold - expected), 0.5) << "side " << side;
        EXPECT_GT(at(side * fold), 2.0 * at(side * (fold + 1))) << "side " << side;
        EXPECT_GT(std::max(at(side * fold), at(side * (fold - 1))), 2.0) << "the ring is bright, side " << side;
    }
}

}  // namespace
}  // namespace eikon
