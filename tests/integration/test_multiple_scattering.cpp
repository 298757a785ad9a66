// Multiple scattering in a rendered scene (tracer.multiple_scattering
// "lbm"): a scattering sphere lit from above, its lattice fed by the
// photons. What the lattice adds vanishes with the albedo (as a², against
// single scattering's a); a medium that does not scatter gets no lattice
// and the same image bit for bit; the lattice's source is the power the
// photons lost to scattering; and the scene key goes through --set.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace eikon {
namespace {

namespace fs = std::filesystem;

// A sphere of radius 0.15 m, κ = 20 /m and σs = albedo·κ (index 1: no
// refraction), in a 32³ grid, lit straight down, seen from the side.
fs::path sphereScene(double albedo) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_multiple_scattering";
    fs::create_directories(folder);
    const fs::path path = folder / ("sphere_" + std::to_string(albedo) + ".json");
    const std::string sigma = std::to_string(20.0 * albedo);
    std::ofstream(path) << R"({
      "grid": {"bounds": {"min": [-0.25, -0.25, -0.25], "max": [0.25, 0.25, 0.25]}, "resolution": [32, 32, 32]},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.15, "index": 1.0,
                   "extinction": [20, 20, 20], "scattering": [)" + sigma + ", " + sigma + ", " + sigma + R"(]}],
      "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
      "camera": {"position": [0, 0, 1.5], "target": [0, 0, 0], "fov_deg": 20},
      "render": {"width": 24, "height": 24, "photons": 65536, "background": [0, 0, 0]},
      "tracer": {"step_policy": "uniform"}
    })";
    return path;
}

struct Rendered {
    std::vector<float> hdr;
    render::PhotonStats photons;
    std::optional<render::LatticeStats> lattice;
    bool hasLattice = false;
};

Rendered renderScene(const fs::path& path, const std::vector<std::string>& overrides) {
    test::glContext();
    const Scene scene = loadSceneFile(path.string(), overrides);
    const sim::SceneFields fields(scene);
    render::FrameRenderer renderer(scene, fields.fields());
    const render::FrameResult frame = renderer.render(fields.fields());
    return {renderer.viewStage().downloadHdr(), frame.photons, frame.lattice, renderer.latticeStage() != nullptr};
}

double sum(const std::vector<float>& hdr) {
    double total = 0.0;
    for (std::size_t p = 0; p < hdr.size(); p += 4) total += hdr[p] + hdr[p + 1] + hdr[p + 2];
    return total;
}

const std::vector<std::string> kLattice = {"tracer.multiple_scattering=\"lbm\""};

// Single scattering grows as a, light scattered twice or more as a² at small
// a: the lattice's share of the image, (lbm − none)/none, falls tenfold from
// a = 0.2 to 0.02 (within 30%: the next orders add a³). It adds light in
// every pixel, never takes any.
TEST(MultipleScattering, WhatTheLatticeAddsVanishesWithTheAlbedo) {
    double share[2];
    int n = 0;
    for (double albedo : {0.2, 0.02}) {
        const Rendered single = renderScene(sphereScene(albedo), {});
        const Rendered multiple = renderScene(sphereScene(albedo), kLattice);
        ASSERT_TRUE(multiple.hasLattice);
        ASSERT_FALSE(single.hasLattice);
        for (std::size_t p = 0; p < single.hdr.size(); ++p) EXPECT_GE(multiple.hdr[p], single.hdr[p]) << p;
        share[n++] = sum(multiple.hdr) / sum(single.hdr) - 1.0;
    }
    test::reportFigure("lattice_share_albedo_0.2", share[0]);
    test::reportFigure("lattice_share_albedo_0.02", share[1]);
    EXPECT_GT(share[0], 0.0);
    EXPECT_NEAR(share[1] / share[0], 0.1, 0.03);
}

// Albedo 0: nothing scatters, so no lattice is made and the image is the
// single-scattering one's bits.
TEST(MultipleScattering, NoScatteringNoLattice) {
    const Rendered single = renderScene(sphereScene(0.0), {});
    const Rendered multiple = renderScene(sphereScene(0.0), kLattice);
    EXPECT_FALSE(multiple.hasLattice);
    EXPECT_FALSE(multiple.lattice.has_value());
    EXPECT_EQ(multiple.hdr, single.hdr);
}

// The lattice's source is what the photons lost to scattering: in a medium
// of one albedo, a times the power they lost to extinction, to float
// rounding (1e-5), so the frame's ledger — the photons' and the lattice's —
// closes; the lattice's own to 1e-4 at a tolerance of 1e-5.
TEST(MultipleScattering, TheLatticeCarriesWhatThePhotonsScattered) {
    const double albedo = 0.9;
    const Rendered frame = renderScene(sphereScene(albedo), {"tracer.multiple_scattering=\"lbm\"",
                                                             "tracer.lbm_tolerance=1e-5"});
    ASSERT_TRUE(frame.lattice.has_value());
    for (int c = 0; c < 3; ++c) {
        const double scattered = albedo * frame.photons.absorbed[c];
        EXPECT_NEAR(frame.lattice->channels[c].source / scattered, 1.0, 1e-5) << c;
    }
    EXPECT_LT(frame.lattice->balanceError(), 1e-4);
    EXPECT_FALSE(frame.lattice->capped());
    EXPECT_EQ(frame.lattice->directions, 14);
    const Rendered coarse = renderScene(sphereScene(albedo), {"tracer.multiple_scattering=\"lbm\"",
                                                              "tracer.lbm_directions=6"});
    EXPECT_EQ(coarse.lattice->directions, 6);
}

}  // namespace
}  // namespace eikon
