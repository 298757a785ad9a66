// A lens designed in another tool: the index grid of a Luneburg lens
// n = √(2 − (r/R)²), written with OpenVDB's own API, imported through
// `volume.grids.index`. It must give the field the accuracy suite's
// Luneburg case samples from the closed form on the same grid, and focus a
// parallel beam at the far pole (0, 0, R) as well as that case does.
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"
#include "tests/unit/VdbTestFiles.h"
#include "verify/accuracy/AccuracyCase.h"
#include "verify/accuracy/AccuracyRun.h"
#include "verify/reference/AnalyticFields.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>

namespace eikon {
namespace {

namespace fs = std::filesystem;
constexpr double kRadius = 0.4;

// RMS over rays with impact parameter < 0.9 R of where the exit ray crosses
// the plane z = R, from the focus, over R (the Luneburg case's measure).
double focusMiss(const accuracy::GpuTrace& trace) {
    const glm::dvec3 focus(0.0, 0.0, kRadius);
    std::vector<double> misses;
    for (const accuracy::PhotonPath& path : trace.paths) {
        if (path.size() < 3 || std::hypot(path[0].x, path[0].y) > 0.9 * kRadius) continue;
        const glm::dvec3 a = path[path.size() - 2], direction = glm::normalize(path.back() - a);
        if (direction.z <= 0.0) continue;
        misses.push_back(glm::length(accuracy::linePlaneIntersection(a, direction, focus, {0, 0, 1}) - focus) / kRadius);
    }
    EXPECT_GT(misses.size(), 100u);
    return accuracy::rms(misses);
}

TEST(ImportedLens, ALuneburgIndexGridFocusesAtTheFarPole) {
    test::glContext();
    Scene scene;
    scene.grid.boundsMin = glm::dvec3(-0.5);
    scene.grid.boundsMax = glm::dvec3(0.5);
    scene.render.width = scene.render.height = 8;
    scene.render.photons = accuracy::pathCasePhotons(false);
    LightDesc beam;
    beam.kind = LightDesc::Kind::Directional;
    beam.direction = glm::dvec3(0.0, 0.0, 1.0);
    beam.irradiance = Rgb(1.0);
    scene.lights.push_back(beam);
    accuracy::applySettings(scene, accuracy::RunSettings{}, glm::ivec3(64));
    const GridSpec grid = scene.grid.spec();
    const double h = grid.voxelSize().x;

    // The designer's file: voxel (i, j, k) at (i, j, k)·h; placed half a
    // voxel on (volume.offset, here the placement) its voxels sit on the
    // render cells' centres.
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_imported_lens";
    fs::create_directories(folder);
    const glm::dvec3 offset(0.5 * h);
    test::writeVdbFile(folder / "luneburg.vdb",
                       {{"n", 1,
                         [&](double x, double y, double z, int) {
                             const double r = glm::length(glm::dvec3(x, y, z) + offset) / kRadius;
                             return float(r < 1.0 ? std::sqrt(2.0 - r * r) : 1.0);
                         }}},
                       h, -0.55, 0.55);
    Scene imported = scene;
    VolumeDesc volume;
    volume.path = (folder / "luneburg.vdb").string();
    volume.densityGrid = volume.temperatureGrid = "";
    volume.indexGrid = "n";
    volume.placement = glm::translate(glm::dmat4(1.0), offset);
    imported.volume = volume;
    imported.sourcePath = (folder / "lens.json").string();
    const sim::SceneFields importedFields(imported);

    const reference::LuneburgField closedForm(glm::dvec3(0.0), kRadius);
    const FieldSet sampled = accuracy::sampleIndexField(closedForm, grid, 1.0);
    const FieldSet& fromFile = importedFields.fields();
    ASSERT_EQ(fromFile.deltaIndex.size(), sampled.deltaIndex.size());
    double worst = 0.0;
    for (std::size_t c = 0; c < sampled.deltaIndex.size(); ++c)
        worst = std::max(worst, std::abs(double(fromFile.deltaIndex[c]) - double(sampled.deltaIndex[c])));
    EXPECT_LT(worst, 1e-6) << "float32 n against the closed form at the cell centres";

    const accuracy::TraceRequest request = accuracy::pathRequest(scene, 2.0 / h, 0.5);
    const double fileMiss = focusMiss(accuracy::traceOnGpu(scene, fromFile, request));
    const double sampledMiss = focusMiss(accuracy::traceOnGpu(scene, sampled, request));
    test::reportFigure("imported_luneburg_focus_rms_over_R", fileMiss);
    test::reportFigure("sampled_luneburg_focus_rms_over_R", sampledMiss);
    EXPECT_LT(fileMiss, 0.005) << "docs/accuracy.md: 0.2% of R at these settings";
    EXPECT_NEAR(fileMiss, sampledMiss, 0.05 * sampledMiss);
    fs::remove_all(folder);
}

}  // namespace
}  // namespace eikon
