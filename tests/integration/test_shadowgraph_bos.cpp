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
#include <cstdint>
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
// (L = 1.7, 16.9 and 169 m): the paraxial error — the ray moves
// ~ε·σ inside the bump, so the thin-lens map is off by a part in ~A — must
// shrink with A to the grid's own error, within 1% of the peak contrast at 1e-4.
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

// An absorbing medium, κ = (0.5, 1, 2) /m over the grid's 1 m depth and no
// bump: every pixel of the screen gets I/I₀ = e^(−κ) per channel (the
// screen then tallies each channel on its own).
TEST(Shadowgraph, AbsorptionDimsEachChannelByItsTransmittance) {
    glContext();
    const Scene scene = bumpScene(16, 16, shadowgraph(1.0));
    FieldSet fields = sampledBump(scene, Bump{0.0});
    const Rgb kappa(0.5, 1.0, 2.0);
    fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
    for (std::size_t c = 0; c < fields.grid.cellCount(); ++c)
        for (int channel = 0; channel < 3; ++channel)
            fields.extinction[3 * c + channel] = static_cast<float>(kappa[channel]);
    ++fields.extinctionVersion;
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const std::vector<float> hdr = renderer.diagnosticStage()->downloadHdr();
    for (std::size_t p = 0; p < 16 * 16; ++p)
        for (int channel = 0; channel < 3; ++channel)
            ASSERT_NEAR(hdr[4 * p + channel], std::exp(-kappa[channel]), 1e-5) << "pixel " << p << ", channel " << channel;
}

// BOS: a pinhole 2 m from the bump's centre (Z_A), the background 2 m
// beyond it (Z_D: 1.5 m behind the grid's far face), a view 0.8 m tall at
// the bump (f_px = 320 on 128 rows).
constexpr double kCameraZ = 2.0, kBackgroundZ = -2.0, kHalfView = 0.2;  // tan(fov / 2)

Scene bosScene(int size, double dotDiameter) {
    DiagnosticDesc bos;
    bos.type = DiagnosticDesc::Type::Bos;
    bos.backgroundDistance = -0.5 - kBackgroundZ;
    bos.dotDiameter = dotDiameter;
    Scene scene = bumpScene(size, size, bos);
    scene.camera.projection = CameraDesc::Projection::Perspective;
    scene.camera.fovDeg = glm::degrees(2.0 * std::atan(kHalfView));
    return scene;
}

// The closed form's displacement at pixel (i, j), px on the image's right and up.
glm::dvec2 bosDisplacement(const Scene& scene, const Bump& bump, int i, int j) {
    const glm::dvec3 camera(0.0, 0.0, kCameraZ);
    const double pixel = 2.0 * kHalfView / scene.render.height;  // at unit distance
    const glm::dvec3 d = glm::normalize(glm::dvec3((i + 0.5 - 0.5 * scene.render.width) * pixel,
                                                   (0.5 * scene.render.height - j - 0.5) * pixel, -1.0));
    const glm::dvec3 closest = camera + glm::dot(bump.centre - camera, d) * d;
    const glm::dvec3 impact = closest - bump.centre;  // square to d
    const double opd = bump.peakOpd() * std::exp(-glm::dot(impact, impact) / (kBumpSigma * kBumpSigma));
    const glm::dvec3 bent = glm::normalize(d - 2.0 / (kBumpSigma * kBumpSigma) * opd * impact);
    const glm::dvec3 landed = closest + (kBackgroundZ - closest.z) / bent.z * bent;
    const glm::dvec3 straight = camera + (kBackgroundZ - camera.z) / d.z * d;
    const double depth = kCameraZ - kBackgroundZ;
    return -glm::dvec2(landed - straight) / (depth * pixel);
}

struct BosFrame {
    std::vector<float> displacement;  // px, 2 per pixel
    std::vector<float> measured;      // I/I₀ with the medium, RGBA
    std::vector<std::uint8_t> reference;
};

BosFrame bosOf(const Scene& scene, const Bump& bump) {
    glContext();
    const FieldSet fields = sampledBump(scene, bump);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const render::DiagnosticStage& stage = *renderer.diagnosticStage();
    return {stage.downloadMeasurements().displacement, stage.downloadHdr(), stage.downloadReference().rgba};
}

// A = 1e-3: 0.24 px at the peak. The paraxial error is a part in ~A (0.1%),
// the grid's own error in the deflection 0.2% RMS of its peak.
TEST(BackgroundOrientedSchlieren, TheDisplacementIsTheSetupsClosedForm) {
    const int size = 128;
    const Scene scene = bosScene(size, 0.02);
    Bump bump;
    bump.amplitude = 1e-3;
    const BosFrame frame = bosOf(scene, bump);
    ASSERT_EQ(frame.displacement.size(), 2u * size * size);
    double peak = 0.0;
    std::vector<glm::dvec2> expected;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            expected.push_back(bosDisplacement(scene, bump, i, j));
            peak = std::max(peak, glm::length(expected.back()));
        }
    double squares = 0.0, worst = 0.0;
    for (std::size_t p = 0; p < expected.size(); ++p) {
        const glm::dvec2 found(frame.displacement[2 * p], frame.displacement[2 * p + 1]);
        const double error = glm::length(found - expected[p]);
        squares += error * error;
        worst = std::max(worst, error);
    }
    // Near the axis: f_px·Z_D·ε/(Z_A + Z_D), ε the parallel light's peak deflection.
    const double focalPixels = size / (2.0 * kHalfView), za = kCameraZ, zd = -kBackgroundZ;
    reportFigure("bos_peak_displacement_px", peak);
    reportFigure("bos_small_angle_peak_displacement_px", focalPixels * zd * bump.peakDeflection() / (za + zd));
    reportFigure("bos_displacement_rms_error_of_peak", std::sqrt(squares / static_cast<double>(expected.size())) / peak);
    reportFigure("bos_displacement_worst_error_of_peak", worst / peak);
    EXPECT_LE(worst, 0.01 * peak);
}

double srgbDecode(std::uint8_t value) {
    const double v = value / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// The pictures carry the displacement: the background with the medium at
// pixel p is the reference picture at p − Δ(p) (bilinear between its pixel
// centres; Δ's up is the rows' −), far closer than at p itself wherever the
// pattern moves half a pixel or more (A = 1e-2: 2.4 px at the peak; dots
// six pixels across). Away from the bump the two pictures are the same,
// and the pattern is dots on white, neither blank nor black.
TEST(BackgroundOrientedSchlieren, ThePicturesAreTheBackgroundMovedByTheDisplacement) {
    const int size = 128;
    const Scene scene = bosScene(size, 6.0 * (kCameraZ - kBackgroundZ) * 2.0 * kHalfView / size);
    Bump bump;
    bump.amplitude = 1e-2;
    const BosFrame frame = bosOf(scene, bump);
    const auto reference = [&](double x, double y) {  // pixel coordinates of centres, bilinear
        const int i = std::clamp(static_cast<int>(std::floor(x)), 0, size - 2);
        const int j = std::clamp(static_cast<int>(std::floor(y)), 0, size - 2);
        const double fx = x - i, fy = y - j;
        const auto at = [&](int a, int b) { return srgbDecode(frame.reference[4 * static_cast<std::size_t>(b * size + a)]); };
        return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) + fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
    };
    double moved = 0.0, unmoved = 0.0, far = 0.0, mean = 0.0;
    int pixels = 0, farPixels = 0;
    for (int j = 2; j < size - 2; ++j)
        for (int i = 2; i < size - 2; ++i) {
            const std::size_t p = static_cast<std::size_t>(j * size + i);
            const glm::dvec2 delta(frame.displacement[2 * p], frame.displacement[2 * p + 1]);
            const double seen = frame.measured[4 * p];
            mean += srgbDecode(frame.reference[4 * p]);
            if (glm::length(delta) < 1e-2) {
                far += std::abs(seen - srgbDecode(frame.reference[4 * p]));
                ++farPixels;
            }
            if (glm::length(delta) < 0.5) continue;
            moved += std::abs(seen - reference(i - delta.x, j + delta.y));
            unmoved += std::abs(seen - srgbDecode(frame.reference[4 * p]));
            ++pixels;
        }
    mean /= (size - 4) * (size - 4);
    reportFigure("bos_picture_moved_over_unmoved_difference", moved / unmoved);
    EXPECT_GT(pixels, 500);
    EXPECT_LT(moved, 0.2 * unmoved);
    EXPECT_GT(farPixels, 400);
    EXPECT_LT(far / farPixels, 0.01) << "8-bit sRGB against the linear picture";
    EXPECT_GT(mean, 0.3);
    EXPECT_LT(mean, 0.95);
}

}  // namespace
}  // namespace eikon
