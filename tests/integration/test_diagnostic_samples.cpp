// Anti-aliased diagnostics (docs/accuracy.md, "Diagnostics"):
// render.samples_per_pixel = k² rays a pixel through the centres of a k × k
// grid over it, each pixel the mean of its rays' picture and measurements —
// a box filter over the pixel, as the camera's image has. Against the
// Gaussian bump (tests/integration/GaussianBump.h):
// - where the interferogram's fringes are finer than a pixel one ray a
//   pixel aliases them; the picture's L1 distance from a 256-ray reference
//   must shrink as the rays grow;
// - the OPD and deflection maps must approach their pixels' means, whose
//   closed forms for the separable Gaussian are products of erf, as k grows;
// - the shadowgraph past its focus (a folded map, a ring caustic), whose
//   beam squares are cut into k × k, must approach its 256-square image.
#include "bridge/grid/FieldSet.h"
#include "render/graph/FrameRenderer.h"
#include "tests/integration/GaussianBump.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace eikon {
namespace {

using namespace test;

struct Diagnosed {
    std::vector<glm::vec4> rays;   // per pixel: (ε right, ε up, OPD, how its rays ended)
    std::vector<float> intensity;  // I/I₀, RGBA
};

Diagnosed diagnose(Scene scene, const Bump& bump, int samples) {
    glContext();
    scene.render.samplesPerPixel = samples;
    const FieldSet fields = sampledBump(scene, bump);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    return {renderer.diagnosticStage()->downloadRays(), renderer.diagnosticStage()->downloadHdr()};
}

// ‖a − b‖₁ / ‖b‖₁ over the red channel of RGBA pixels.
double relativeL1(const std::vector<float>& a, const std::vector<float>& b) {
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < b.size(); i += 4) {
        difference += std::abs(static_cast<double>(a[i]) - b[i]);
        norm += std::abs(static_cast<double>(b[i]));
    }
    return difference / norm;
}

// 64 × 64 pixels, 12.5 mm each; A = 3e-5 puts 15 fringes between the axis
// and the edge, 1.1 a pixel where they are densest (ρ = σ/√2): one ray a
// pixel samples them about once a fringe, the reference 16 times.
TEST(DiagnosticSamples, TheInterferogramsFineFringesConvergeToTheManyRayImage) {
    DiagnosticDesc interferometer;
    const Scene scene = bumpScene(64, 64, interferometer);
    Bump bump;
    bump.amplitude = 3e-5;
    const std::vector<float> reference = diagnose(scene, bump, 256).intensity;
    std::vector<double> errors;
    for (const int samples : {1, 4, 16}) {
        errors.push_back(relativeL1(diagnose(scene, bump, samples).intensity, reference));
        reportFigure(("interferogram_l1_against_256_rays_samples_" + std::to_string(samples)).c_str(), errors.back());
    }
    EXPECT_LT(errors[1], 0.7 * errors[0]);
    EXPECT_LT(errors[2], 0.7 * errors[1]);
}

// The mean over a pixel [x0, x1] × [y0, y1] of OPD = P·exp(−(x² + y²)/σ²)
// and of its gradient ε = ∇OPD: per axis, the mean of exp(−x²/σ²) is
// σ·√π/2·(erf(x1/σ) − erf(x0/σ))/h, of its derivative (e(x1) − e(x0))/h.
struct PixelMeans {
    double opd;
    glm::dvec2 deflection;
};

PixelMeans pixelMeans(const Scene& scene, const Bump& bump, int i, int j) {
    const double h = kBumpViewWidth / scene.render.width, s = kBumpSigma;
    const glm::dvec2 low = pixelPoint(scene, i, j) - 0.5 * h, high = low + h;
    const auto meanOf = [&](double a, double b) { return 0.5 * s * std::sqrt(std::numbers::pi) * (std::erf(b / s) - std::erf(a / s)) / h; };
    const auto meanOfSlope = [&](double a, double b) { return (std::exp(-b * b / (s * s)) - std::exp(-a * a / (s * s))) / h; };
    const glm::dvec2 mean(meanOf(low.x, high.x), meanOf(low.y, high.y));
    const glm::dvec2 slope(meanOfSlope(low.x, high.x), meanOfSlope(low.y, high.y));
    return {bump.peakOpd() * mean.x * mean.y, bump.peakOpd() * glm::dvec2(slope.x * mean.y, mean.x * slope.y)};
}

// 12 × 12 pixels of 67 mm (a pixel is 0.44σ): a pixel's centre value is
// off its mean by ~(h/σ)²/24·|f″/f|, about 1% of the peak; k² rays take
// that to 1/k² of it, down to the grid's own error (at 96 × 96 pixels OPD
// 0.03%, deflection 0.2% of the peak, RMS).
TEST(DiagnosticSamples, TheMeasuredMapsApproachTheirPixelsMeans) {
    constexpr int kPixels = 12;
    DiagnosticDesc interferometer;
    const Scene scene = bumpScene(kPixels, kPixels, interferometer);
    const Bump bump;
    std::vector<double> opdErrors, deflectionErrors;
    for (const int samples : {1, 4, 16}) {
        const Diagnosed diagnosed = diagnose(scene, bump, samples);
        double opd = 0.0, deflection = 0.0;
        for (int j = 0; j < kPixels; ++j)
            for (int i = 0; i < kPixels; ++i) {
                const glm::vec4 ray = diagnosed.rays[static_cast<std::size_t>(j * kPixels + i)];
                const PixelMeans mean = pixelMeans(scene, bump, i, j);
                opd += std::pow((ray.z - mean.opd) / bump.peakOpd(), 2);
                deflection += std::pow(glm::length(glm::dvec2(ray.x, ray.y) - mean.deflection) / bump.peakDeflection(), 2);
            }
        opdErrors.push_back(std::sqrt(opd / (kPixels * kPixels)));
        deflectionErrors.push_back(std::sqrt(deflection / (kPixels * kPixels)));
        const std::string suffix = "_samples_" + std::to_string(samples);
        reportFigure(("opd_rms_error_of_peak_against_pixel_means" + suffix).c_str(), opdErrors.back());
        reportFigure(("deflection_rms_error_of_peak_against_pixel_means" + suffix).c_str(), deflectionErrors.back());
    }
    for (const std::vector<double>* errors : {&opdErrors, &deflectionErrors}) {
        EXPECT_LT((*errors)[1], 0.5 * (*errors)[0]);
        EXPECT_LT((*errors)[2], 0.5 * (*errors)[0]);
    }
    EXPECT_LE(opdErrors[2], 0.001);
    EXPECT_LE(deflectionErrors[2], 0.005);
}

// Past the focus (2κ = 4, L = 169 m at A = 1e-4): a ring caustic, where the
// piecewise-linear map of one square a pixel is coarse.
TEST(DiagnosticSamples, TheShadowgraphsCausticConvergesToTheManySquareImage) {
    DiagnosticDesc shadowgraph;
    shadowgraph.type = DiagnosticDesc::Type::Shadowgraph;
    const Bump bump;
    const double kappa = 2.0, farHalf = 0.5;  // the grid's far half, behind the bump's centre plane
    shadowgraph.screenDistance = kappa * kBumpSigma * kBumpSigma / bump.peakOpd() - farHalf;
    const Scene scene = bumpScene(64, 64, shadowgraph);
    const std::vector<float> reference = diagnose(scene, bump, 256).intensity;
    std::vector<double> errors;
    for (const int samples : {1, 4, 16}) {
        errors.push_back(relativeL1(diagnose(scene, bump, samples).intensity, reference));
        reportFigure(("shadowgraph_caustic_l1_against_256_squares_samples_" + std::to_string(samples)).c_str(),
                     errors.back());
    }
    EXPECT_LT(errors[1], 0.7 * errors[0]);
    EXPECT_LT(errors[2], 0.7 * errors[1]);
}

// The viewer's preview while the camera moves (FrameRenderer::setPixelStride
// s > 1): one ray per s×s block of pixels, through the middle of the
// block's middle pixel, filling the block — the one-ray picture's pixel
// there, bit for bit (the shadowgraph: one square a pixel, its one-ray
// picture) — and at rest again all k², as before the preview.
TEST(DiagnosticSamples, APreviewDrawsOneRayABlockAndRestDrawsAllOfThem) {
    glContext();
    DiagnosticDesc shadowgraph;
    shadowgraph.type = DiagnosticDesc::Type::Shadowgraph;
    shadowgraph.screenDistance = 20.0;
    DiagnosticDesc bos;
    bos.type = DiagnosticDesc::Type::Bos;
    const int width = 30, height = 22, stride = 4;  // blocks cut short at the right and bottom edges
    for (const DiagnosticDesc& diagnostic : {DiagnosticDesc{}, shadowgraph, bos}) {
        Scene scene = bumpScene(width, height, diagnostic);
        if (diagnostic.type == DiagnosticDesc::Type::Bos) scene.camera.projection = CameraDesc::Projection::Perspective;
        Bump bump;
        bump.amplitude = 3e-5;
        const FieldSet fields = sampledBump(scene, bump);
        const std::vector<float> one = diagnose(scene, bump, 1).intensity;
        scene.render.samplesPerPixel = 16;
        render::FrameRenderer renderer(scene, fields);
        const render::FrameResult full = renderer.render(fields);
        EXPECT_EQ(full.viewSamples, 16);
        EXPECT_EQ(full.pixelStride, 1);
        const std::vector<float> all = renderer.diagnosticStage()->downloadHdr();
        renderer.setPixelStride(stride);
        const render::FrameResult preview = renderer.render(fields);
        EXPECT_EQ(preview.viewSamples, 1);
        const std::vector<float> drawn = renderer.diagnosticStage()->downloadHdr();
        if (diagnostic.type == DiagnosticDesc::Type::Shadowgraph) {
            EXPECT_EQ(preview.pixelStride, 1);
            EXPECT_EQ(drawn, one);
        } else {
            EXPECT_EQ(preview.pixelStride, stride);
            std::size_t mismatched = 0;
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) {
                    const int middleX = std::min(x / stride * stride + stride / 2, width - 1);
                    const int middleY = std::min(y / stride * stride + stride / 2, height - 1);
                    const std::size_t pixel = 4 * (static_cast<std::size_t>(y) * width + x);
                    const std::size_t middle = 4 * (static_cast<std::size_t>(middleY) * width + middleX);
                    for (int c = 0; c < 4; ++c) mismatched += drawn[pixel + c] != one[middle + c] ? 1 : 0;
                }
            EXPECT_EQ(mismatched, 0u) << static_cast<int>(diagnostic.type);
        }
        renderer.setPixelStride(1);
        renderer.render(fields);
        EXPECT_EQ(renderer.diagnosticStage()->downloadHdr(), all);
        EXPECT_NE(all, one) << "the fringes, the screen and the dots differ between 1 and 16 rays";
    }
}

}  // namespace
}  // namespace eikon
