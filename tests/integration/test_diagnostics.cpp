// The diagnostics against closed forms (docs/accuracy.md, "Diagnostics"): a
// 3D Gaussian index bump (tests/integration/GaussianBump.h) seen by
// parallel light along −z, OPD and ε in the paraxial limit. The
// interferogram, cos²(π·OPD/λ), then has a dark fringe wherever OPD/λ is
// k + ½, and a knife edge shows I/I₀ = clamp(0.5 + f·ε⊥/a, 0, 1). The
// bump is sampled at the render cells' centres, or imported as a
// delta_index grid written with OpenVDB's own API; no smoothing.
#include "bridge/grid/FieldSet.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "tests/integration/GaussianBump.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"
#include "tests/unit/VdbTestFiles.h"
#include "verify/reference/ReferenceTracer.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace eikon {
namespace {

using namespace test;

constexpr int kCells = kBumpCells;
constexpr double kSigma = kBumpSigma;

struct Diagnosed {
    std::vector<glm::vec4> rays;  // (ε right, ε up, OPD, how it ended)
    std::vector<float> intensity;  // I/I₀, RGBA
};

Diagnosed diagnose(const Scene& scene, const FieldSet& fields) {
    glContext();
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    EXPECT_NE(renderer.diagnosticStage(), nullptr);
    return {renderer.diagnosticStage()->downloadRays(), renderer.diagnosticStage()->downloadHdr()};
}

struct MapErrors {
    double opdRms = 0.0, opdWorst = 0.0;                // of the peak OPD
    double deflectionRms = 0.0, deflectionWorst = 0.0;  // of the peak deflection
};

MapErrors mapErrors(const Scene& scene, const Bump& bump, const Diagnosed& diagnosed) {
    MapErrors errors;
    const int width = scene.render.width, height = scene.render.height;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::vec4 ray = diagnosed.rays[static_cast<std::size_t>(j * width + i)];
            EXPECT_EQ(ray.w, 1.0f) << "every ray crosses the grid";
            const glm::dvec2 p = pixelPoint(scene, i, j);
            const double opd = std::abs(ray.z - bump.opd(p)) / bump.peakOpd();
            const double deflection = glm::length(glm::dvec2(ray.x, ray.y) - bump.deflection(p)) / bump.peakDeflection();
            errors.opdRms += opd * opd;
            errors.deflectionRms += deflection * deflection;
            errors.opdWorst = std::max(errors.opdWorst, opd);
            errors.deflectionWorst = std::max(errors.deflectionWorst, deflection);
        }
    errors.opdRms = std::sqrt(errors.opdRms / (width * height));
    errors.deflectionRms = std::sqrt(errors.deflectionRms / (width * height));
    return errors;
}

const DiagnosticDesc kInterferometer{};

DiagnosticDesc knifeEdge(double focalLength, double sourceHeight) {
    DiagnosticDesc knife;
    knife.type = DiagnosticDesc::Type::Schlieren;
    knife.focalLength = focalLength;
    knife.sourceHeight = sourceHeight;
    return knife;
}

TEST(Diagnostics, OpticalPathDifferenceAndDeflectionMatchTheBumpsClosedForms) {
    const Scene scene = bumpScene(96, 96, kInterferometer);
    const Bump bump;
    const MapErrors errors = mapErrors(scene, bump, diagnose(scene, sampledBump(scene, bump)));
    reportFigure("bump_opd_rms_error_of_peak", errors.opdRms);
    reportFigure("bump_opd_worst_error_of_peak", errors.opdWorst);
    reportFigure("bump_deflection_rms_error_of_peak", errors.deflectionRms);
    reportFigure("bump_deflection_worst_error_of_peak", errors.deflectionWorst);
    EXPECT_LE(errors.opdRms, 0.005);
    EXPECT_LE(errors.deflectionRms, 0.01);
}

// The same bump off the axis, imported as a delta_index grid: the file's
// voxels, half a voxel on (volume.offset, here the placement), sit on the render cells' centres.
TEST(Diagnostics, AnImportedDeltaIndexGridGivesTheSameMaps) {
    Scene scene = bumpScene(96, 96, kInterferometer);
    Bump bump;
    bump.centre = glm::dvec3(0.06, -0.04, 0.02);
    const double h = 1.0 / kCells;
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / "eikon_diagnostic_bump";
    std::filesystem::create_directories(folder);
    writeVdbFile(folder / "bump.vdb",
                 {{"dn", 1, [&](double x, double y, double z, int) {
                       return static_cast<float>(bump.deltaIndex(glm::dvec3(x, y, z) + 0.5 * h));
                   }}},
                 h, -0.55, 0.55);
    VolumeDesc volume;
    volume.path = (folder / "bump.vdb").string();
    volume.densityGrid = volume.temperatureGrid = "";
    volume.deltaIndexGrid = "dn";
    volume.placement = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5 * h));
    scene.volume = volume;
    scene.sourcePath = (folder / "bump.json").string();
    const sim::SceneFields imported(scene);
    const MapErrors errors = mapErrors(scene, bump, diagnose(scene, imported.fields()));
    reportFigure("imported_bump_opd_rms_error_of_peak", errors.opdRms);
    reportFigure("imported_bump_deflection_rms_error_of_peak", errors.deflectionRms);
    EXPECT_LE(errors.opdRms, 0.005);
    EXPECT_LE(errors.deflectionRms, 0.01);
    std::filesystem::remove_all(folder);
}

// A diagnostic draws the picture in place of view and post: with the
// default octree policy and error estimates asked for, a frame has no step
// structure, view or post (the march takes fixed steps) and the
// diagnostic's own estimate (DiagnosticErrorEstimate), and a camera change
// runs the diagnostic and its estimate alone.
TEST(Diagnostics, TheRendererDrawsTheDiagnosticInPlaceOfViewAndPost) {
    glContext();
    Scene scene = bumpScene(32, 24, kInterferometer);
    ASSERT_EQ(scene.tracer.stepPolicy, TracerDesc::StepPolicy::Octree);
    const FieldSet fields = sampledBump(scene, Bump{});
    render::RendererOptions options;
    options.estimateErrors = true;
    render::FrameRenderer renderer(scene, fields, options);
    const auto ran = [](const render::FrameResult& result) {
        std::vector<std::string> names;
        for (const render::StageReport& stage : result.stages)
            if (stage.ran) names.push_back(stage.name);
        return names;
    };
    const render::FrameResult first = renderer.render(fields);
    EXPECT_EQ(ran(first), (std::vector<std::string>{"upload", "prepare", "diagnostic", "error_estimate"}));
    EXPECT_EQ(first.stages.size(), 4u);
    ASSERT_TRUE(first.errorEstimate);
    EXPECT_TRUE(first.errorEstimate->discretisation.deflection);
    EXPECT_FALSE(first.errorEstimate->noiseEstimated);
    EXPECT_EQ(first.image.width, 32);
    EXPECT_EQ(first.hdr.size(), 4u * 32 * 24);
    scene.camera.position.x = 0.1;
    renderer.setCamera(scene.camera);
    EXPECT_EQ(ran(renderer.render(fields)), (std::vector<std::string>{"diagnostic", "error_estimate"}));
    EXPECT_TRUE(ran(renderer.render(fields)).empty());
}

// Dark fringes along a row: runs of pixels with I/I₀ < 1/4.
int darkFringes(const std::vector<float>& intensity, int width) {
    int runs = 0;
    bool dark = false;
    for (int i = 0; i < width; ++i) {
        const bool now = intensity[4 * static_cast<std::size_t>(i)] < 0.25f;
        runs += now && !dark;
        dark = now;
    }
    return runs;
}

// Along the row through the centre OPD/λ climbs from m_edge to m_peak and
// back: a dark fringe at each k + ½ between them, on either side (4.5
// pixels a fringe where they are densest). A tilted reference beam over an
// empty grid gives its fringes across the width, no more, no less.
TEST(Diagnostics, TheInterferogramHasTheClosedFormNumberOfFringes) {
    const int width = 1025;
    const Scene scene = bumpScene(width, 1, kInterferometer);
    const Bump bump;
    const Diagnosed diagnosed = diagnose(scene, sampledBump(scene, bump));
    const double wavelength = kInterferometer.wavelengthNm * 1e-9;
    const double edge = bump.opd(pixelPoint(scene, 0, 0)) / wavelength, peak = bump.peakOpd() / wavelength;
    const int expected = 2 * static_cast<int>(std::floor(peak - 0.5) - std::floor(edge - 0.5));
    reportFigure("bump_peak_fringe_order", peak);
    EXPECT_EQ(darkFringes(diagnosed.intensity, width), expected) << "peak OPD/λ = " << peak;

    DiagnosticDesc tilted = kInterferometer;
    tilted.fringeTilt = 37.0;
    const Scene empty = bumpScene(width, 1, tilted);
    Bump none;
    none.amplitude = 0.0;
    EXPECT_EQ(darkFringes(diagnose(empty, sampledBump(empty, none)).intensity, width), 37);
}

// f/a = 5000: the peak contrast f·ε/a is 0.76, so the middle of the image
// is in the linear range and the steepest flanks clip. Where the closed
// form is inside (|f·ε⊥/a| < 0.45), the contrast must match it within 1% of
// its peak (RMS) and the rays' own ε to float precision; past 0.55 the
// picture is black above the bump's centre and white below it: the knife
// (edge horizontal) passes rays bent up, and the bump bends rays toward its
// centre.
TEST(Diagnostics, KnifeEdgeContrastIsFocalLengthTimesDeflectionOverSourceHeight) {
    const double focalLength = 1.0, sourceHeight = 2e-4, sensitivity = focalLength / sourceHeight;
    const Scene scene = bumpScene(96, 96, knifeEdge(focalLength, sourceHeight));
    const Bump bump;
    const Diagnosed diagnosed = diagnose(scene, sampledBump(scene, bump));
    double squares = 0.0, worstOwn = 0.0;
    int linear = 0, clipped = 0;
    for (int j = 0; j < scene.render.height; ++j)
        for (int i = 0; i < scene.render.width; ++i) {
            const std::size_t p = static_cast<std::size_t>(j * scene.render.width + i);
            const double contrast = diagnosed.intensity[4 * p] - 0.5;
            const double expected = sensitivity * bump.deflection(pixelPoint(scene, i, j)).y;
            if (std::abs(expected) < 0.45) {
                squares += (contrast - expected) * (contrast - expected);
                worstOwn = std::max(worstOwn, std::abs(contrast - sensitivity * diagnosed.rays[p].y));
                ++linear;
            } else if (std::abs(expected) > 0.55) {
                EXPECT_EQ(diagnosed.intensity[4 * p], expected > 0.0 ? 1.0f : 0.0f) << "pixel " << i << ", " << j;
                ++clipped;
            }
        }
    const double peakContrast = sensitivity * bump.peakDeflection();
    const double rms = std::sqrt(squares / linear) / peakContrast;
    reportFigure("knife_edge_contrast_rms_error_of_peak", rms);
    EXPECT_GT(linear, 4000);
    EXPECT_GT(clipped, 100);
    EXPECT_LE(rms, 0.01);
    EXPECT_LE(worstOwn, 1e-6);
}

// An absorbing medium (κ per channel, over the grid's 1 m depth) dims each
// ray's light by T = exp(−κ·1 m): the knife edge's undeflected half to
// T/2, the interferometer's bright field (OPD 0) to (1 + √T)²/4. New κ
// alone (the index as it was) draws the picture again.
TEST(Diagnostics, AbsorptionDimsTheLightByItsTransmittance) {
    glContext();
    DiagnosticDesc shadowgraph;
    shadowgraph.type = DiagnosticDesc::Type::Shadowgraph;
    for (const DiagnosticDesc& diagnostic : {knifeEdge(1.0, 1e-3), kInterferometer, shadowgraph}) {
        const Scene scene = bumpScene(16, 16, diagnostic);
        FieldSet fields = sampledBump(scene, Bump{0.0});
        std::unique_ptr<render::FrameRenderer> renderer;
        // Coloured, grey (the shadowgraph's screen then tallies one channel), coloured again.
        for (const Rgb& kappa : {Rgb(0.5, 1.0, 2.0), Rgb(1.5, 1.5, 1.5), Rgb(1.0, 2.0, 4.0)}) {
            fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
            for (std::size_t c = 0; c < fields.grid.cellCount(); ++c)
                for (int channel = 0; channel < 3; ++channel)
                    fields.extinction[3 * c + channel] = static_cast<float>(kappa[channel]);
            ++fields.extinctionVersion;
            if (!renderer) renderer = std::make_unique<render::FrameRenderer>(scene, fields);
            renderer->render(fields);
            const std::vector<float> intensity = renderer->diagnosticStage()->downloadHdr();
            for (int channel = 0; channel < 3; ++channel) {
                const double t = std::exp(-kappa[channel]);
                // The shadowgraph's undisturbed screen: I/I₀ = T.
                const double expected = diagnostic.type == DiagnosticDesc::Type::Schlieren     ? 0.5 * t
                                        : diagnostic.type == DiagnosticDesc::Type::Shadowgraph ? t
                                                                                               : 0.25 * (1.0 + std::sqrt(t)) * (1.0 + std::sqrt(t));
                EXPECT_NEAR(intensity[4 * 136 + channel], expected, 1e-5 * expected)
                    << static_cast<int>(diagnostic.type) << ", κ " << kappa[0] << ", channel " << channel;
            }
        }
    }
}

// The bump in closed form, for the reference tracer.
class BumpField final : public reference::IndexField {
public:
    explicit BumpField(const Bump& bump) : bump_(bump) {}
    double index(const glm::dvec3& x) const override { return 1.0 + bump_.deltaIndex(x); }
    glm::dvec3 gradient(const glm::dvec3& x) const override {
        return -2.0 / (kSigma * kSigma) * (x - bump_.centre) * bump_.deltaIndex(x);
    }

private:
    Bump bump_;
};

// Exact deflections (ε right, ε up) of the scene's rays, bent as the ray
// equation bends them, from the image plane to the grid's far face.
std::vector<glm::dvec2> exactDeflections(const Scene& scene, const Bump& bump) {
    const BumpField field(bump);
    const reference::ReferenceTracer tracer(field);
    std::vector<glm::dvec2> deflections;
    for (int j = 0; j < scene.render.height; ++j)
        for (int i = 0; i < scene.render.width; ++i) {
            const glm::dvec2 p = pixelPoint(scene, i, j);
            const reference::ReferenceResult end = tracer.trace(
                tracer.start({p.x, p.y, 0.5}, {0.0, 0.0, -1.0}), 2.0,
                [](const reference::RayState& state) { return state.x.z + 0.5; });
            EXPECT_TRUE(end.eventHit);
            deflections.push_back(glm::dvec2(glm::normalize(end.state.v)));
        }
    return deflections;
}

// The paraxial error: the closed forms hold for straight rays; a ray bends
// by ε ≈ 1.5·A and so samples the bump ε·σ off its straight line, which
// changes its deflection by a part in ~A. Against the reference tracer's
// exact rays it must shrink in proportion to A. eikon's rays must bend as
// the exact ones do: the part of their deflection that is not linear in A
// (the map at A scaled to 1e-4, less the map at 1e-4: the grid's own error
// is linear in A and cancels) must be the exact rays' to 20%.
TEST(Diagnostics, TheParaxialErrorShrinksWithTheAmplitudeAndTheRaysBendAsTheExactOnes) {
    const Scene scene = bumpScene(64, 64, kInterferometer);
    const double amplitudes[] = {1e-4, 1e-3, 1e-2};
    const char* const names[] = {"1e-4", "1e-3", "1e-2"};
    std::vector<std::vector<glm::dvec2>> traced, exact;
    std::vector<double> paraxial;
    for (std::size_t a = 0; a < 3; ++a) {
        Bump bump;
        bump.amplitude = amplitudes[a];
        const Diagnosed diagnosed = diagnose(scene, sampledBump(scene, bump));
        exact.push_back(exactDeflections(scene, bump));
        traced.emplace_back();
        double paraxialSquares = 0.0, tracedSquares = 0.0;
        for (std::size_t p = 0; p < exact.back().size(); ++p) {
            traced.back().push_back(glm::dvec2(diagnosed.rays[p]));
            const int i = static_cast<int>(p) % scene.render.width, j = static_cast<int>(p) / scene.render.width;
            const glm::dvec2 closedForm = bump.deflection(pixelPoint(scene, i, j));
            paraxialSquares += glm::dot(closedForm - exact.back()[p], closedForm - exact.back()[p]);
            tracedSquares += glm::dot(traced.back()[p] - exact.back()[p], traced.back()[p] - exact.back()[p]);
        }
        const double pixels = static_cast<double>(exact.back().size());
        paraxial.push_back(std::sqrt(paraxialSquares / pixels) / bump.peakDeflection());
        reportFigure(("paraxial_deflection_rms_error_of_peak_amplitude_" + std::string(names[a])).c_str(),
                     paraxial.back());
        reportFigure(("traced_deflection_rms_error_of_peak_against_exact_amplitude_" + std::string(names[a])).c_str(),
                     std::sqrt(tracedSquares / pixels) / bump.peakDeflection());
    }
    EXPECT_GT(paraxial[1], 5.0 * paraxial[0]);
    EXPECT_GT(paraxial[2], 5.0 * paraxial[1]);
    EXPECT_LT(paraxial[2], 20.0 * paraxial[1]);

    double exactSquares = 0.0, differenceSquares = 0.0;
    for (std::size_t p = 0; p < exact[0].size(); ++p) {
        const double scale = amplitudes[0] / amplitudes[2];
        const glm::dvec2 exactBend = exact[2][p] * scale - exact[0][p];
        const glm::dvec2 tracedBend = traced[2][p] * scale - traced[0][p];
        exactSquares += glm::dot(exactBend, exactBend);
        differenceSquares += glm::dot(tracedBend - exactBend, tracedBend - exactBend);
    }
    const double bendError = std::sqrt(differenceSquares / exactSquares);
    reportFigure("nonlinear_deflection_relative_error_amplitude_1e-2", bendError);
    EXPECT_LT(bendError, 0.2);
}

}  // namespace
}  // namespace eikon
