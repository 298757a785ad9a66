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

// An adaptive domain's cache: Blender bakes only the part of the domain that
// holds smoke, a grid of fewer cells per axis at an offset the file does not
// hold (here 8 × 6 × 9 cells of the 1.6 × 1.2 × 2.0 m domain's 13 × 10 × 16),
// which the preset used to stretch over the whole domain, silently. Now the
// file's resolution is checked against the dimensions at the file's voxel
// and the cache is refused, naming both; so are dimensions of another domain.
TEST(VolumePlacement, ACacheThatIsNotItsDomainsWholeGridIsRefused) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_blender_adaptive";
    fs::remove_all(folder);
    fs::create_directories(folder);
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setTransform(openvdb::math::Transform::createLinearTransform(2.0 / 16));
    density->insertMeta("file_base_resolution", openvdb::Vec3IMetadata(openvdb::Vec3i(8, 6, 9)));
    density->tree().setValue(openvdb::Coord(1, 1, 1), 1.0f);
    openvdb::io::File((folder / "fluid_data_0001.vdb").string()).write({density});
    const auto sceneWith = [](const std::string& dimensions) {
        return nlohmann::json::parse(R"({
          "grid": {"resolution": [8, 8, 8], "bounds": {"min": [0.5, 2.5, -2.5], "max": [1.5, 3.5, -1.5]}},
          "lights": [{"type": "point", "position": [0, 5, 0], "power": 1}],
          "volume": {"path": "fluid_data_####.vdb", "preset": "blender", "grids": {"temperature": "", "flame": "",
                     "velocity": ""}, "blender_domain": {"location": [1, 2, 3], "dimensions": )" +
                                     dimensions + "}}}");
    };
    try {
        SceneFields refused(parseScene(sceneWith("[1.6, 1.2, 2.0]"), (folder / "scene.json").string()));
        FAIL() << "an adaptive domain's cache was stretched over the whole domain";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("fluid_data_0001.vdb: grid \"density\": expected file_base_resolution = "
                               "volume.blender_domain.dimensions / the file's voxel of 0.125 m, each rounded "
                               "(12.8 × 9.6 × 16), found 8 × 6 × 9: "),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("adaptive domain"), std::string::npos) << message;
    }
    // The dimensions that make 8 × 6 × 9 cells of 0.125 m (1.0 × 0.75 × 1.125 m, within rounding) are taken.
    EXPECT_NO_THROW(SceneFields(parseScene(sceneWith("[1.0, 0.75, 1.125]"), (folder / "scene.json").string())));
    fs::remove_all(folder);
}

// Blender's noise cache (fluid_noise_####.vdb, what Quick Smoke renders):
// its density is the grid density_noise, and it holds no heat, flame or
// velocity. The preset used to look for density, temperature, flame and
// velocity there and refuse the file until four grid names were given; now
// it reads density_noise by the file's name, placed as the data cache is.
TEST(VolumePlacement, BlendersNoiseCacheIsReadByItsGridNames) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_blender_noise";
    fs::remove_all(folder);
    fs::create_directories(folder);
    openvdb::initialize();
    const glm::ivec3 resolution(8, 8, 8);  // a 1 m cube at resolution_max 4 with noise upres 2
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density_noise");
    density->setTransform(openvdb::math::Transform::createLinearTransform(1.0 / 8));
    density->insertMeta("file_base_resolution",
                        openvdb::Vec3IMetadata(openvdb::Vec3i(resolution.x, resolution.y, resolution.z)));
    auto accessor = density->getAccessor();
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) accessor.setValue(openvdb::Coord(i, j, k), float(i + 2 * j + 4 * k));
    openvdb::io::File((folder / "fluid_noise_0001.vdb").string()).write({density});
    const nlohmann::json root = nlohmann::json::parse(R"({
      "grid": {"resolution": [4, 4, 4], "bounds": {"min": [-0.25, 0.25, -0.25], "max": [0.25, 0.75, 0.25]}},
      "lights": [{"type": "point", "position": [0, 5, 0], "power": 1}],
      "volume": {"path": "fluid_noise_####.vdb", "preset": "blender",
                 "blender_domain": {"location": [0, 0, 0.5], "dimensions": [1, 1, 1]}}})");
    const SceneFields fields(parseScene(root, (folder / "scene.json").string()));
    const auto arrays = fields.exportArrays();
    ASSERT_EQ(arrays.size(), 1u) << "density alone: no temperature, flame or velocity";
    ASSERT_EQ(arrays[0].name, "density");
    const GridSpec& grid = fields.fields().grid;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                const glm::dvec3 x = grid.cellCentre(i, j, k);
                const glm::dvec3 blender(x.x, -x.z, x.y);  // eikon's (x, y, z) is Blender's (x, −z, y)
                const glm::dvec3 u = (blender - glm::dvec3(0, 0, 0.5) + 0.5) * 8.0 - 0.5;  // the cache's cell coordinate
                EXPECT_NEAR(arrays[0].values[grid.linearIndex(i, j, k)], u.x + 2.0 * u.y + 4.0 * u.z, 1e-4)
                    << i << ", " << j << ", " << k;
            }
    fs::remove_all(folder);
}

// A domain whose origin was moved off its box's centre: its Location is the
// origin, and the preset put the cache's box centred there, silently off by
// the origin's move (0.8 m in the round trip that found it). `center`, the
// box's centre in Blender's world, places it: a cache given `center` lands
// exactly as one whose origin is at that centre, and `location` beside
// `center` is refused.
TEST(VolumePlacement, ABlenderDomainWithAMovedOriginIsPlacedByItsCentre) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_blender_origin";
    fs::remove_all(folder);
    fs::create_directories(folder);
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setTransform(openvdb::math::Transform::createLinearTransform(1.0 / 8));
    density->insertMeta("file_base_resolution", openvdb::Vec3IMetadata(openvdb::Vec3i(8, 8, 8)));
    auto accessor = density->getAccessor();
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) accessor.setValue(openvdb::Coord(i, j, k), float(i + 2 * j + 4 * k));
    openvdb::io::File((folder / "fluid_data_0001.vdb").string()).write({density});
    // The origin at (0, 0, 0), the box's centre 0.8 m above it, turned 90° about z.
    const auto sceneWith = [](const std::string& placement) {
        return nlohmann::json::parse(R"({
          "grid": {"resolution": [4, 4, 4], "bounds": {"min": [-0.25, 0.55, -0.25], "max": [0.25, 1.05, 0.25]}},
          "lights": [{"type": "point", "position": [0, 5, 0], "power": 1}],
          "volume": {"path": "fluid_data_####.vdb", "preset": "blender", "grids": {"temperature": "", "flame": "",
                     "velocity": ""}, "blender_domain": {)" + placement +
                                     R"(, "rotation_deg": [0, 0, 90], "dimensions": [1, 1, 1]}}})");
    };
    const SceneFields fields(parseScene(sceneWith(R"("center": [0, 0, 0.8])"), (folder / "scene.json").string()));
    const auto values = fields.exportArrays()[0].values;
    const GridSpec& grid = fields.fields().grid;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                const glm::dvec3 x = grid.cellCentre(i, j, k);
                const glm::dvec3 blender(x.x, -x.z, x.y);
                const glm::dvec3 q = blender - glm::dvec3(0, 0, 0.8);    // from the box's centre
                const glm::dvec3 local(q.y, -q.x, q.z);                   // turned back by −90° about z
                const glm::dvec3 u = (local + 0.5) * 8.0 - 0.5;
                EXPECT_NEAR(values[grid.linearIndex(i, j, k)], u.x + 2.0 * u.y + 4.0 * u.z, 1e-4) << i << j << k;
            }
    try {
        SceneFields refused(
            parseScene(sceneWith(R"("center": [0, 0, 0.8], "location": [0, 0, 0])"), (folder / "scene.json").string()));
        FAIL() << "center and location together";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("volume.blender_domain.center: expected either `center` or `location`"),
                  std::string::npos)
            << error.what();
    }
    fs::remove_all(folder);
}

// grid.fit "volume": the grid's bounds become the box of the volume's
// active voxels as the placement turns them (whole voxels −4 … 4 of
// 0.125 m: ±0.5625 m), here scaled 2× along x, turned 90° about z and
// moved by (1, 2, 3): x ±0.5625, y ±1.125 about (1, 2, 3), worked out by hand.
TEST(VolumePlacement, GridFitVolumeSizesTheGridToTheTurnedVolume) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_grid_fit";
    fs::remove_all(folder);
    fs::create_directories(folder);
    test::writeVdbFile(folder / "cache.vdb", {{"density", 1, [](double, double, double, int) { return 1.0f; }}}, 0.125,
                       -0.5, 0.5);
    const auto sceneWith = [](const std::string& grid, const std::string& volume) {
        return nlohmann::json::parse(R"({"grid": )" + grid + R"(,
          "lights": [{"type": "point", "position": [0, 5, 0], "power": 1}])" + volume + "}");
    };
    const std::string volume = R"(, "volume": {"path": "cache.vdb", "grids": {"temperature": ""},
        "transform": {"translate": [1, 2, 3], "rotate_deg": [0, 0, 90], "scale": [2, 1, 1]}})";
    const std::string scenePath = (folder / "scene.json").string();
    const Scene scene = parseScene(sceneWith(R"({"resolution": [8, 16, 8], "fit": "volume"})", volume), scenePath);
    const glm::dvec3 expectedMin(0.4375, 0.875, 2.4375), expectedMax(1.5625, 3.125, 3.5625);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(scene.grid.boundsMin[axis], expectedMin[axis], 1e-12) << axis;
        EXPECT_NEAR(scene.grid.boundsMax[axis], expectedMax[axis], 1e-12) << axis;
    }
    const auto refusal = [&](const std::string& grid, const std::string& withVolume) {
        try {
            parseScene(sceneWith(grid, withVolume), scenePath);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("nothing refused");
    };
    EXPECT_NE(refusal(R"({"fit": "volume", "bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}})", volume)
                  .find("grid.bounds: expected no bounds beside fit \"volume\""),
              std::string::npos);
    EXPECT_NE(refusal(R"({"fit": "volume"})", "").find("grid.fit: expected a `volume` section to fit the grid to"),
              std::string::npos);
    fs::remove_all(folder);
}

}  // namespace
}  // namespace eikon::sim
