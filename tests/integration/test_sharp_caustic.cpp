// The showcase against ground truth: the default scene's floor irradiance
// with its sharp glass sphere, traced by the photon pass on the GPU, against
// verify/reference/SphereCaustic — exact ray–sphere intersections, Snell and
// Fresnel in double precision on the CPU, sharing no code with the renderer.
// Twice: with the receiver's default 3×3 binomial filter, against the
// reference through the same filter (the model and the tracer alone); and
// with `filter: "none"` against the unfiltered truth (photon noise
// included). Tolerances, both: the shadow edge within one texel of the
// closed form h·tan(asin(R/d)); relative L1 inside the caustic disk ≤ 10%;
// the peak within 10%.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "sim/deform/MeshShapes.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"
#include "verify/reference/ReceiverFilter.h"
#include "verify/reference/SphereCaustic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace eikon {
namespace {

constexpr int kResolution = 192;

double texelRadius(int i, int j, double size, int n) {
    const double u = ((i + 0.5) / n - 0.5) * size, v = ((j + 0.5) / n - 0.5) * size;
    return std::hypot(u, v);
}

// Mean irradiance in rings one texel wide.
std::vector<double> radialProfile(const std::vector<double>& map, double size, int n) {
    const double texel = size / n;
    std::vector<double> sum(static_cast<std::size_t>(n), 0.0), count(static_cast<std::size_t>(n), 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto ring = static_cast<std::size_t>(texelRadius(i, j, size, n) / texel);
            if (ring >= sum.size()) continue;
            sum[ring] += map[static_cast<std::size_t>(j) * n + i];
            count[ring] += 1.0;
        }
    for (std::size_t r = 0; r < sum.size(); ++r) sum[r] = count[r] > 0.0 ? sum[r] / count[r] : 0.0;
    return sum;
}

// The shadow's edge: beyond the caustic, where the profile first climbs past
// half the light's unobstructed irradiance (linear between ring centres).
double shadowEdge(const std::vector<double>& profile, const reference::SphereCausticSetup& setup) {
    const double texel = setup.size / setup.resolution, h = setup.light.y - setup.receiverCentre.y;
    auto unobstructed = [&](double r) { return setup.power / (4.0 * M_PI) * h / std::pow(h * h + r * r, 1.5); };
    const auto start = static_cast<std::size_t>(0.2 / texel);  // past the caustic's core
    for (std::size_t r = start + 1; r < profile.size(); ++r) {
        const double r0 = (static_cast<double>(r) - 0.5) * texel, r1 = (static_cast<double>(r) + 0.5) * texel;
        const double f0 = profile[r - 1] / unobstructed(r0) - 0.5, f1 = profile[r] / unobstructed(r1) - 0.5;
        if (f0 < 0.0 && f1 >= 0.0) return r0 + (r1 - r0) * (-f0) / (f1 - f0);
    }
    return -1.0;
}

// The floor irradiance (green, W/m²) of `scene` as the photon pass gives it.
std::vector<double> floorIrradianceOf(const Scene& scene, const FieldSet& fields) {
    render::FrameRenderer renderer(scene, fields);
    const render::FrameResult result = renderer.render(fields);
    EXPECT_LE(result.photons.balanceError(), 1e-6);
    const std::vector<float> rgb = renderer.receivers().download(0);
    std::vector<double> green(rgb.size() / 3);
    for (std::size_t t = 0; t < green.size(); ++t) green[t] = rgb[3 * t + 1];
    return green;
}

// The default scene traced by photons (its own estimator is the
// wavefront, checked on its own below), with `overrides` after that.
Scene defaultScene(const std::vector<std::string>& overrides) {
    std::vector<std::string> all = {"tracer.estimator=\"photons\""};
    all.insert(all.end(), overrides.begin(), overrides.end());
    return loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json", all);
}

// The default scene's floor irradiance, with `overrides` applied.
std::vector<double> floorIrradiance(const std::vector<std::string>& overrides) {
    const Scene scene = defaultScene(overrides);
    return floorIrradianceOf(scene, sim::voxelizeScene(scene));
}

// The exact-sphere reference of the default scene: `setup` and its map.
struct Reference {
    reference::SphereCausticSetup setup;
    std::vector<double> unfiltered;
    std::vector<double> filtered;  // through the receiver's 3×3 binomial kernel
    double shadow = 0.0;           // closed-form shadow radius, m
    double texel = 0.0;            // m
};

// The default scene's light, sphere and floor as the references see them.
reference::SphereCausticSetup sphereCausticSetupOf(const Scene& scene) {
    EXPECT_EQ(scene.receivers[0].resolution, kResolution);
    reference::SphereCausticSetup setup;
    setup.light = scene.lights[0].position;
    setup.power = scene.lights[0].power.g;
    setup.centre = scene.objects[0].sphere.center;
    setup.radius = scene.objects[0].sphere.radius;
    setup.sphereIndex = scene.objects[0].material.index;
    setup.receiverCentre = scene.receivers[0].point;
    setup.size = scene.receivers[0].size;
    setup.resolution = kResolution;
    return setup;
}

Reference defaultSceneReference() {
    Reference truth;
    reference::SphereCausticSetup& setup = truth.setup;
    setup = sphereCausticSetupOf(defaultScene({}));
    setup.rays = 8'000'000;
    truth.unfiltered = reference::traceSphereCaustic(setup).irradiance;
    truth.filtered = reference::binomialFilter(truth.unfiltered, kResolution);
    truth.shadow = reference::shadowRadius(setup);
    truth.texel = setup.size / kResolution;
    return truth;
}

struct DiskError {
    double relativeL1 = 0.0;
    double peakRatio = 0.0;
};

// Relative L1 and peak ratio over the texels inside the shadow radius.
DiskError diskError(const std::vector<double>& map, const std::vector<double>& exact, double shadow, double size) {
    double difference = 0.0, total = 0.0, peak = 0.0, peakExact = 0.0;
    for (int j = 0; j < kResolution; ++j)
        for (int i = 0; i < kResolution; ++i) {
            if (texelRadius(i, j, size, kResolution) >= shadow) continue;
            const std::size_t t = static_cast<std::size_t>(j) * kResolution + i;
            difference += std::abs(map[t] - exact[t]);
            total += exact[t];
            peak = std::max(peak, map[t]);
            peakExact = std::max(peakExact, exact[t]);
        }
    return {difference / total, peak / peakExact};
}

TEST(SharpCaustic, DefaultSceneMatchesTheExactSphereReference) {
    test::glContext();
    ASSERT_TRUE(defaultScene({}).objects[0].isSharp()) << "the default scene's glass is sharp";
    const Reference truth = defaultSceneReference();
    const reference::SphereCausticSetup& setup = truth.setup;
    const std::vector<double>& unfiltered = truth.unfiltered;
    const std::vector<double>& exact = truth.filtered;
    const double shadow = truth.shadow;
    const double texel = truth.texel;

    const std::vector<double> sharp = floorIrradiance({});
    const double edge = shadowEdge(radialProfile(sharp, setup.size, kResolution), setup);
    test::reportFigure("sharp_caustic_shadow_edge_m", edge);
    test::reportFigure("sharp_caustic_shadow_closed_form_m", shadow);
    EXPECT_NEAR(edge, shadow, texel);
    const DiskError error = diskError(sharp, exact, shadow, setup.size);
    test::reportFigure("sharp_caustic_disk_relative_l1", error.relativeL1);
    test::reportFigure("sharp_caustic_peak_ratio", error.peakRatio);
    EXPECT_LE(error.relativeL1, 0.10);
    EXPECT_NEAR(error.peakRatio, 1.0, 0.10);
    // For the record: the filtered map against the unfiltered truth (what
    // the filter costs), and the paper's smoothed glass.
    const DiskError raw = diskError(sharp, unfiltered, shadow, setup.size);
    test::reportFigure("sharp_caustic_disk_relative_l1_vs_unfiltered_truth", raw.relativeL1);
    test::reportFigure("sharp_caustic_peak_ratio_vs_unfiltered_truth", raw.peakRatio);
    const std::vector<double> unfilteredMap = floorIrradiance({"receivers.0.filter=\"none\""});
    const DiskError direct = diskError(unfilteredMap, unfiltered, shadow, setup.size);
    test::reportFigure("sharp_unfiltered_caustic_disk_relative_l1", direct.relativeL1);
    test::reportFigure("sharp_unfiltered_caustic_peak_ratio", direct.peakRatio);
    // And against the truth itself, with the receiver unfiltered: photon noise
    // of 2²¹ photons included.
    EXPECT_LE(direct.relativeL1, 0.10);
    EXPECT_NEAR(direct.peakRatio, 1.0, 0.10);
    const double unfilteredEdge = shadowEdge(radialProfile(unfilteredMap, setup.size, kResolution), setup);
    test::reportFigure("sharp_unfiltered_shadow_edge_m", unfilteredEdge);
    EXPECT_NEAR(unfilteredEdge, shadow, texel);
    const std::vector<double> smooth = floorIrradiance({"objects.0.surface=\"smooth\""});
    const DiskError smoothError = diskError(smooth, exact, shadow, setup.size);
    test::reportFigure("smooth_caustic_disk_relative_l1", smoothError.relativeL1);
    test::reportFigure("smooth_caustic_shadow_edge_m", shadowEdge(radialProfile(smooth, setup.size, kResolution), setup));
}

// The same glass sphere as a triangle mesh (96 rings, 36 864 triangles),
// whose sharp surface the tracers find as the zero set of its signed
// distance on the scene's grid (h = 1.25 cm): the same tolerances as the
// analytic sphere, through the same filter.
TEST(SharpCaustic, SphereMeshMatchesTheExactSphereReference) {
    test::glContext();
    const Reference truth = defaultSceneReference();
    Scene scene = defaultScene({});
    const SphereShape sphere = scene.objects[0].sphere;
    scene.objects[0] = test::meshObject(sim::sphereMesh(sphere.center, sphere.radius, 96, 192), "default_sphere96.obj",
                                        scene.objects[0].material.index);
    const sim::SceneFields fields(scene);
    const std::vector<double> map = floorIrradianceOf(scene, fields.fields());
    const double edge = shadowEdge(radialProfile(map, truth.setup.size, kResolution), truth.setup);
    test::reportFigure("sharp_mesh_caustic_shadow_edge_m", edge);
    EXPECT_NEAR(edge, truth.shadow, truth.texel);
    const DiskError error = diskError(map, truth.filtered, truth.shadow, truth.setup.size);
    test::reportFigure("sharp_mesh_caustic_disk_relative_l1", error.relativeL1);
    test::reportFigure("sharp_mesh_caustic_peak_ratio", error.peakRatio);
    EXPECT_LE(error.relativeL1, 0.10);
    EXPECT_NEAR(error.peakRatio, 1.0, 0.10);
}


// The camera's view of the same two spheres: camera rays search a mesh once
// per straight stretch (shaders/view_rays.comp), so each pixel's exit
// direction through the 96-ring mesh must match the analytic sphere's but
// for the facets' normal error; a crossing missed or found twice sends a
// ray through the glass unbent or the wrong way, tens of degrees off.
TEST(SharpCaustic, SphereMeshViewMatchesTheAnalyticSpheresView) {
    test::glContext();
    const std::vector<std::string> small = {"render.width=160", "render.height=120", "render.photons=65536",
                                            "grid.resolution=[48,40,48]"};
    const auto exits = [](const Scene& scene, const FieldSet& fields) {
        render::FrameRenderer renderer(scene, fields, {.photons = {}, .recordViewExits = true});
        renderer.render(fields);
        return renderer.viewStage().downloadExits();
    };
    const Scene analytic = defaultScene(small);
    Scene meshed = analytic;
    const SphereShape sphere = meshed.objects[0].sphere;
    meshed.objects[0] = test::meshObject(sim::sphereMesh(sphere.center, sphere.radius, 96, 192),
                                         "default_sphere96.obj", meshed.objects[0].material.index);
    Scene clear = analytic;  // the glass as index 1: every camera ray goes straight
    clear.objects[0].material.index = 1.0;
    const std::vector<glm::vec4> straight = exits(clear, sim::voxelizeScene(clear));
    const std::vector<glm::vec4> exact = exits(analytic, sim::voxelizeScene(analytic));
    const std::vector<glm::vec4> faceted = exits(meshed, sim::SceneFields(meshed).fields());
    ASSERT_EQ(exact.size(), faceted.size());
    ASSERT_EQ(exact.size(), straight.size());
    int bent = 0, apart = 0;  // pixels the sphere turns; of those, exits more than 2° apart
    for (std::size_t p = 0; p < exact.size(); ++p) {
        const glm::dvec3 a(exact[p]), b(faceted[p]), unbent(straight[p]);
        if (glm::dot(glm::normalize(a), glm::normalize(unbent)) > std::cos(0.02)) continue;  // not through the glass
        ++bent;
        apart += glm::dot(glm::normalize(a), glm::normalize(b)) < std::cos(2.0 * std::numbers::pi / 180.0);
    }
    test::reportFigure("sharp_mesh_view_pixels_bent", bent);
    test::reportFigure("sharp_mesh_view_fraction_apart", static_cast<double>(apart) / bent);
    EXPECT_GT(bent, 500);
    EXPECT_LT(static_cast<double>(apart) / bent, 0.05);
}

// Relative L1 of `map` against `exact` over the whole receiver.
double receiverError(const std::vector<double>& map, const std::vector<double>& exact) {
    double difference = 0.0, total = 0.0;
    for (std::size_t t = 0; t < exact.size(); ++t) {
        difference += std::abs(map[t] - exact[t]);
        total += exact[t];
    }
    return difference / total;
}

// The photon path's three receiver filters on the default scene (2²¹
// photons) against the noise-free exact-sphere reference: the binomial
// kernel's bias in the caustic (it flattens the peak) and the unfiltered
// map's noise over the lit floor, against the density-adaptive tent, which
// widens only where photons are sparse. It must beat the binomial kernel in
// the caustic disk and the unfiltered map over the receiver, each by half.
TEST(SharpCaustic, AdaptiveFilterBeatsBinomialInTheCausticAndNoneOnTheFloor) {
    test::glContext();
    const Scene scene = defaultScene({});
    const reference::SphereCausticSetup setup = sphereCausticSetupOf(scene);
    const std::vector<double> exact = reference::integrateSphereCaustic(setup).irradiance;
    const double shadow = reference::shadowRadius(setup);
    const std::vector<double> binomial = floorIrradiance({});
    const std::vector<double> none = floorIrradiance({"receivers.0.filter=\"none\""});
    const std::vector<double> adaptive = floorIrradiance({"receivers.0.filter=\"adaptive\""});
    const char* names[] = {"binomial", "none", "adaptive"};
    const std::vector<double>* maps[] = {&binomial, &none, &adaptive};
    double whole[3], disk[3];
    for (int f = 0; f < 3; ++f) {
        whole[f] = receiverError(*maps[f], exact);
        disk[f] = diskError(*maps[f], exact, shadow, setup.size).relativeL1;
        test::reportFigure((std::string("photon_filter_") + names[f] + "_receiver_relative_l1").c_str(), whole[f]);
        test::reportFigure((std::string("photon_filter_") + names[f] + "_disk_relative_l1").c_str(), disk[f]);
    }
    EXPECT_LT(disk[2], 0.5 * disk[0]);
    EXPECT_LT(whole[2], 0.5 * whole[1]);
}

// The wavefront estimator on the default scene against the noise-free
// exact-sphere reference (integrateSphereCaustic): no filter, no noise, so
// the tolerances are the issue's — relative L1 over the receiver ≤ 1%,
// inside the caustic disk ≤ 6%, the shadow edge within one texel; and the
// same bits twice.
TEST(SharpCaustic, WavefrontMatchesTheNoiseFreeReference) {
    test::glContext();
    const Scene scene = defaultScene({"tracer.estimator=\"wavefront\""});
    const reference::SphereCausticSetup setup = sphereCausticSetupOf(scene);
    const std::vector<double> exact = reference::integrateSphereCaustic(setup).irradiance;
    const double shadow = reference::shadowRadius(setup), texel = setup.size / kResolution;

    const FieldSet fields = sim::voxelizeScene(scene);
    const std::vector<double> map = floorIrradianceOf(scene, fields);
    const double whole = receiverError(map, exact);
    const DiskError disk = diskError(map, exact, shadow, setup.size);
    const double edge = shadowEdge(radialProfile(map, setup.size, kResolution), setup);
    test::reportFigure("wavefront_receiver_relative_l1", whole);
    test::reportFigure("wavefront_caustic_disk_relative_l1", disk.relativeL1);
    test::reportFigure("wavefront_caustic_peak_ratio", disk.peakRatio);
    test::reportFigure("wavefront_shadow_edge_m", edge);
    EXPECT_LE(whole, 0.01);
    EXPECT_LE(disk.relativeL1, 0.06);
    EXPECT_NEAR(edge, shadow, texel);
    EXPECT_EQ(floorIrradianceOf(scene, fields), map) << "the wavefront is deterministic";
}

// Image space (render.method "image_space": light-space caustic maps through
// two rasterized interfaces, render/stages/ImageSpaceCaustics.h) on the
// default scene against the same noise-free reference through the same
// binomial filter: the baseline that says what the approximation costs,
// after one frame and after the four-frame temporal mean. Measured at the
// default 256² photons: 0.3% over the receiver, 1.6–1.7% in the caustic
// disk, the peak 1–2% low, the shadow's edge 2 mm inside the closed form;
// bounded at 1%, 3%, 5% and a texel.
TEST(SharpCaustic, ImageSpaceCausticAgainstTheNoiseFreeReference) {
    test::glContext();
    const Scene scene = defaultScene({"render.method=\"image_space\""});
    const reference::SphereCausticSetup setup = sphereCausticSetupOf(scene);
    const std::vector<double> exact =
        reference::binomialFilter(reference::integrateSphereCaustic(setup).irradiance, kResolution);
    const double shadow = reference::shadowRadius(setup), texel = setup.size / kResolution;
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    const auto floor = [&] {
        const std::vector<float> rgb = renderer.receivers().download(0);
        std::vector<double> green(rgb.size() / 3);
        for (std::size_t t = 0; t < green.size(); ++t) green[t] = rgb[3 * t + 1];
        return green;
    };
    renderer.render(fields);
    const std::vector<double> first = floor();
    for (int frame = 1; frame < render::kTemporalFrames; ++frame) renderer.render(fields);
    const std::vector<double> averaged = floor();
    for (const auto& [name, map] : {std::pair<const char*, const std::vector<double>&>{"one_frame", first},
                                    {"four_frames", averaged}}) {
        const DiskError disk = diskError(map, exact, shadow, setup.size);
        const double edge = shadowEdge(radialProfile(map, setup.size, kResolution), setup);
        test::reportFigure((std::string("image_space_") + name + "_receiver_relative_l1").c_str(),
                           receiverError(map, exact));
        test::reportFigure((std::string("image_space_") + name + "_disk_relative_l1").c_str(), disk.relativeL1);
        test::reportFigure((std::string("image_space_") + name + "_peak_ratio").c_str(), disk.peakRatio);
        test::reportFigure((std::string("image_space_") + name + "_shadow_edge_error_m").c_str(), edge - shadow);
    }
    const DiskError disk = diskError(averaged, exact, shadow, setup.size);
    EXPECT_LE(receiverError(averaged, exact), 0.01);
    EXPECT_LE(disk.relativeL1, 0.03);
    EXPECT_NEAR(disk.peakRatio, 1.0, 0.05);
    EXPECT_NEAR(shadowEdge(radialProfile(averaged, setup.size, kResolution), setup), shadow, texel);
}

}  // namespace
}  // namespace eikon
