// Placing an imported volume: `offset`, `up_axis` and `transform` (Blender's
// translate · rotate XYZ · scale, or a matrix) map the file's world into the
// scene's. A density linear in the file's coordinates, sampled at every
// render cell, must read what the placement computed here by hand gives —
// to 1e-6 m of position — and a velocity turns and scales with it.
#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <filesystem>
#include <numbers>

namespace eikon::sim {
namespace {

namespace fs = std::filesystem;

// The density of the file at its own world point p, and its gradient's length.
double density(const glm::dvec3& p) { return 2.0 + 1.5 * p.x + 2.5 * p.y - 3.0 * p.z; }
const double kGradient = std::sqrt(1.5 * 1.5 + 2.5 * 2.5 + 3.0 * 3.0);

// Row-major 3×3 products, written out rather than taken from GLM.
using Mat3 = std::array<std::array<double, 3>, 3>;
Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
}
Mat3 turn(int axis, double degrees) {
    const double c = std::cos(degrees * std::numbers::pi / 180.0), s = std::sin(degrees * std::numbers::pi / 180.0);
    if (axis == 0) return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
    if (axis == 1) return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
    return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}
glm::dvec3 transformed(const Mat3& m, const glm::dvec3& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

TEST(VolumePlacement, ATurnedScaledZUpVolumeLandsWhereItsPlacementSays) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_volume_placement";
    fs::remove_all(folder);
    fs::create_directories(folder);
    test::writeVdbFile(folder / "cache.vdb",
                       {{"density", 1, [](double x, double y, double z, int) { return float(density({x, y, z})); }},
                        {"velocity", 3, [](double, double, double, int c) { return float(c + 1); }}},
                       0.02, -1.0, 1.0);
    const glm::dvec3 offset(0.05, -0.1, 0.02), translate(0.1, -0.05, 0.3), turns(30.0, -20.0, 45.0), scale(0.5, 0.7, 0.6);
    nlohmann::json root = nlohmann::json::parse(R"({
      "grid": {"resolution": [10, 8, 6], "bounds": {"min": [-0.25, -0.2, -0.15], "max": [0.25, 0.2, 0.15]}},
      "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}],
      "volume": {"path": "cache.vdb", "grids": {"temperature": "", "velocity": "velocity"}, "up_axis": "z",
                 "offset": [0.05, -0.1, 0.02],
                 "transform": {"translate": [0.1, -0.05, 0.3], "rotate_deg": [30, -20, 45], "scale": [0.5, 0.7, 0.6]}}})");
    const SceneFields fields(parseScene(root, (folder / "scene.json").string()));
    const auto arrays = fields.exportArrays();
    ASSERT_EQ(arrays[0].name, "density");
    ASSERT_EQ(arrays[1].name, "velocity");

    // scene = offset + U · (translate + R · S · file), R = Rz · Ry · Rx, U: (x, y, z) → (x, z, −y).
    const Mat3 rotation = multiply(turn(2, turns.z), multiply(turn(1, turns.y), turn(0, turns.x)));
    const Mat3 up{{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};
    const Mat3 linear = multiply(up, multiply(rotation, Mat3{{{scale.x, 0, 0}, {0, scale.y, 0}, {0, 0, scale.z}}}));
    // Inverse of the linear part: S⁻¹ · Rᵀ · Uᵀ.
    const Mat3 inverse = multiply(Mat3{{{1 / scale.x, 0, 0}, {0, 1 / scale.y, 0}, {0, 0, 1 / scale.z}}},
                               multiply(Mat3{{{rotation[0][0], rotation[1][0], rotation[2][0]},
                                              {rotation[0][1], rotation[1][1], rotation[2][1]},
                                              {rotation[0][2], rotation[1][2], rotation[2][2]}}},
                                        Mat3{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}}));
    const GridSpec& grid = fields.fields().grid;
    double worstMetres = 0.0;
    for (int k = 0; k < grid.resolution.z; ++k)
        for (int j = 0; j < grid.resolution.y; ++j)
            for (int i = 0; i < grid.resolution.x; ++i) {
                const glm::dvec3 x = grid.cellCentre(i, j, k);
                const glm::dvec3 p = transformed(inverse, x - offset - transformed(up, translate));
                const std::size_t c = grid.linearIndex(i, j, k);
                worstMetres = std::max(worstMetres, std::abs(arrays[0].values[c] - density(p)) / kGradient);
                const glm::dvec3 v = transformed(linear, {1.0, 2.0, 3.0});
                for (int a = 0; a < 3; ++a) EXPECT_NEAR(arrays[1].values[3 * c + static_cast<std::size_t>(a)], v[a], 1e-6);
            }
    EXPECT_LT(worstMetres, 1e-6) << "position error of the placement";
    fs::remove_all(folder);
}

// A cache as Blender 3.4's Mantaflow writes one (checked against a real
// bake: grids named density, flame, temperature, velocity; fog-volume
// class; half float; a uniform linear transform of voxel dx = the longest
// dimension / the resolution, index (0,0,0) at the origin; Mantaflow's
// file_base_resolution metadata; Z-up, in the domain object's frame).
// Cell (i,j,k) covers [i, i+1]·D/res from the domain's corner (Blender's
// fluid.c), so its centre in Blender's world is
//   location + R · (−D/2 + (i + ½, j + ½, k + ½) · D/res).
// The density is i + 2j + 4k, exact in half float, and linear, so trilinear
// sampling reads the cell coordinate of any point back exactly.
TEST(VolumePlacement, ABlenderCacheLandsWhereItsDomainWas) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_blender_cache";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const glm::dvec3 location(1.0, 2.0, 3.0), turns(10.0, -15.0, 30.0), dimensions(1.6, 1.2, 2.0);
    const glm::ivec3 resolution(13, 10, 16);  // Blender's for these dimensions at resolution_max 16
    const double dx = 2.0 / 16;
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setGridClass(openvdb::GRID_FOG_VOLUME);
    density->setSaveFloatAsHalf(true);
    density->setTransform(openvdb::math::Transform::createLinearTransform(dx));
    density->insertMeta("file_base_resolution",
                        openvdb::Vec3IMetadata(openvdb::Vec3i(resolution.x, resolution.y, resolution.z)));
    auto accessor = density->getAccessor();
    for (int k = 0; k < resolution.z; ++k)
        for (int j = 0; j < resolution.y; ++j)
            for (int i = 0; i < resolution.x; ++i) accessor.setValue(openvdb::Coord(i, j, k), float(i + 2 * j + 4 * k));
    openvdb::io::File((folder / "fluid_data_0001.vdb").string()).write({density});

    // A render grid well inside the domain, in eikon's Y-up world: Blender's
    // (x, y, z) is eikon's (x, z, −y).
    nlohmann::json root = nlohmann::json::parse(R"({
      "grid": {"resolution": [9, 8, 7], "bounds": {"min": [0.75, 2.75, -2.25], "max": [1.25, 3.25, -1.75]}},
      "lights": [{"type": "point", "position": [0, 5, 0], "power": 1}],
      "volume": {"path": "fluid_data_####.vdb", "preset": "blender", "grids": {"temperature": "", "flame": "",
                 "velocity": ""}, "blender_domain": {"location": [1, 2, 3], "rotation_deg": [10, -15, 30],
                 "dimensions": [1.6, 1.2, 2.0]}}})");
    const SceneFields fields(parseScene(root, (folder / "scene.json").string()));
    const auto arrays = fields.exportArrays();
    ASSERT_EQ(arrays[0].name, "density");
    const Mat3 rotation = multiply(turn(2, turns.z), multiply(turn(1, turns.y), turn(0, turns.x)));
    const Mat3 unturn{{{rotation[0][0], rotation[1][0], rotation[2][0]},
                       {rotation[0][1], rotation[1][1], rotation[2][1]},
                       {rotation[0][2], rotation[1][2], rotation[2][2]}}};
    const GridSpec& grid = fields.fields().grid;
    const glm::dvec3 cell = dimensions / glm::dvec3(resolution);
    double worstMetres = 0.0;
    for (int k = 0; k < grid.resolution.z; ++k)
        for (int j = 0; j < grid.resolution.y; ++j)
            for (int i = 0; i < grid.resolution.x; ++i) {
                const glm::dvec3 x = grid.cellCentre(i, j, k);
                const glm::dvec3 blender(x.x, -x.z, x.y);
                const glm::dvec3 u = (transformed(unturn, blender - location) + 0.5 * dimensions) / cell - 0.5;
                const double expected = u.x + 2.0 * u.y + 4.0 * u.z;
                // The density's gradient in metres: (1/cx, 2/cy, 4/cz) in the domain's axes.
                const double gradient = glm::length(glm::dvec3(1.0, 2.0, 4.0) / cell);
                worstMetres = std::max(worstMetres,
                                       std::abs(arrays[0].values[grid.linearIndex(i, j, k)] - expected) / gradient);
            }
    EXPECT_LT(worstMetres, 1e-6) << "position error of the Blender preset";

    // Without Mantaflow's metadata the preset cannot place the cache.
    density->removeMeta("file_base_resolution");
    openvdb::io::File((folder / "fluid_data_0001.vdb").string()).write({density});
    try {
        SceneFields refused(parseScene(root, (folder / "scene.json").string()));
        FAIL() << "a cache without file_base_resolution was placed";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("expected Mantaflow's file_base_resolution metadata"), std::string::npos)
            << error.what();
    }
    fs::remove_all(folder);
}

}  // namespace
}  // namespace eikon::sim
