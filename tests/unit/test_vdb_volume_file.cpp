// Reading OpenVDB files: grids sampled at render cell centres, the
// structural checks accepting what OpenVDB writes, and errors that name the
// file and list its grids.
#include "bridge/core/Error.h"
#include "io/vdb/VdbFileCheck.h"
#include "io/vdb/VdbVolumeFile.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;
using test::VdbTestGrid;

fs::path tempPath(const std::string& name) { return fs::path(::testing::TempDir()) / name; }

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Linear fields are reproduced exactly by trilinear sampling inside the
// active region: density = 1 + x + 2y − z, velocity = (y, −x, 3).
std::vector<VdbTestGrid> linearGrids(bool half) {
    return {{"smoke density", 1, [](double x, double y, double z, int) { return float(1 + x + 2 * y - z); }, half},
            {"velocity", 3, [](double x, double y, double, int c) { return float(c == 0 ? y : c == 1 ? -x : 3.0); }}};
}

// A render grid of 4³ cells over [-0.2, 0.2]³: centres at ±0.05, ±0.15, all
// inside the active box [-0.5, 0.5]³ of the file.
GridSpec renderGrid() { return GridSpec{{4, 4, 4}, glm::dvec3(-0.2), glm::dvec3(0.2)}; }

void expectLinearSamples(const VdbVolumeFile& file, double tolerance, const glm::dvec3& offset) {
    const GridSpec spec = renderGrid();
    const auto density = file.sample("smoke density", 1, spec, offset);
    const auto velocity = file.sample("velocity", 3, spec, offset);
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                const glm::dvec3 x = spec.cellCentre(i, j, k) - offset;
                const std::size_t c = spec.linearIndex(i, j, k);
                EXPECT_NEAR(density[c], 1 + x.x + 2 * x.y - x.z, tolerance);
                EXPECT_NEAR(velocity[3 * c + 0], x.y, 1e-5);
                EXPECT_NEAR(velocity[3 * c + 1], -x.x, 1e-5);
                EXPECT_NEAR(velocity[3 * c + 2], 3.0, 1e-5);
            }
}

TEST(VdbVolumeFile, SamplesLinearGridsExactly) {
    const fs::path path = tempPath("linear.vdb");
    test::writeVdbFile(path, linearGrids(false), 0.05, -0.5, 0.5);
    const VdbVolumeFile file(path);
    EXPECT_EQ(file.gridNames(), (std::vector<std::string>{"smoke density", "velocity"}));
    expectLinearSamples(file, 1e-5, glm::dvec3(0.0));
    expectLinearSamples(file, 1e-5, glm::dvec3(0.1, -0.05, 0.02));  // the volume moved by `offset`
}

// Half floats hold 11 significant bits: |error| <= 2^-11 · |value| (values < 3.5 here).
TEST(VdbVolumeFile, ReadsHalfFloatGrids) {
    const fs::path path = tempPath("half.vdb");
    test::writeVdbFile(path, linearGrids(true), 0.05, -0.5, 0.5);
    const std::string bytes = readAll(path);
    const VdbFileLayout layout = checkVdbHeader(bytes, path.string());
    ASSERT_EQ(layout.grids.size(), 2u);
    EXPECT_TRUE(layout.grids[0].halfFloat);
    EXPECT_EQ(layout.grids[0].valueType, "float");
    expectLinearSamples(VdbVolumeFile(path), 3.5 / 2048, glm::dvec3(0.0));
}

TEST(VdbVolumeFile, OutsideTheActiveVoxelsIsTheBackground) {
    const fs::path path = tempPath("small.vdb");
    test::writeVdbFile(path, {{"density", 1, [](double, double, double, int) { return 2.0f; }}}, 0.1, 0.0, 0.3);
    const GridSpec spec{{2, 1, 1}, {-1.0, 0.0, 0.0}, {1.0, 0.2, 0.2}};  // centres x = −0.5, 0.5
    const auto values = VdbVolumeFile(path).sample("density", 1, spec, glm::dvec3(0.0));
    EXPECT_EQ(values[0], 0.0f);
    EXPECT_EQ(values[1], 0.0f);
    const GridSpec inside{{1, 1, 1}, glm::dvec3(0.1), glm::dvec3(0.2)};  // centre 0.15 between voxels 1 and 2
    EXPECT_FLOAT_EQ(VdbVolumeFile(path).sample("density", 1, inside, glm::dvec3(0.0))[0], 2.0f);
}

// The map the structural walk reads from a grid's bytes (which the check
// before frame 0 places the render grid by) is the one OpenVDB applies once
// it has read the grid: translation, scale, scale-and-translate and affine
// maps, each to 1e-12 at points about the grid.
TEST(VdbVolumeFile, TheCheckedMapIsTheOneOpenVdbApplies) {
    openvdb::initialize();
    openvdb::math::Mat4d affine = openvdb::math::Mat4d::identity();
    affine.preRotate(openvdb::math::Z_AXIS, 0.3);
    affine.preScale(openvdb::Vec3d(0.1, 0.2, 0.05));
    affine.postTranslate(openvdb::Vec3d(1.0, -2.0, 0.5));
    const std::vector<openvdb::math::Transform::Ptr> transforms{
        openvdb::math::Transform::createLinearTransform(0.25),
        openvdb::math::Transform::createLinearTransform(affine),
        openvdb::math::Transform::Ptr(new openvdb::math::Transform(
            openvdb::math::MapBase::Ptr(new openvdb::math::TranslationMap(openvdb::Vec3d(0.5, 1.0, -2.0))))),
        openvdb::math::Transform::Ptr(new openvdb::math::Transform(openvdb::math::MapBase::Ptr(
            new openvdb::math::ScaleTranslateMap(openvdb::Vec3d(0.1, 0.2, 0.3), openvdb::Vec3d(-1.0, 2.0, 0.5)))))};
    const fs::path path = tempPath("maps.vdb");
    for (std::size_t t = 0; t < transforms.size(); ++t) {
        SCOPED_TRACE(transforms[t]->baseMap()->type());
        auto grid = openvdb::FloatGrid::create(0.0f);
        grid->setName("density");
        grid->tree().setValue(openvdb::Coord(1, 2, 3), 1.0f);
        grid->setTransform(transforms[t]);
        openvdb::io::File(path.string()).write({grid});
        const std::string bytes = readAll(path);
        const glm::dmat4 worldToIndex =
            checkVdbGrid(bytes, checkVdbHeader(bytes, path.string()).grids[0], path.string()).worldToIndex;
        for (const glm::dvec3& world : {glm::dvec3(0.0), glm::dvec3(1.5, -0.25, 3.0), glm::dvec3(-7.0, 2.0, 0.125)}) {
            const openvdb::Vec3d expected = transforms[t]->worldToIndex(openvdb::Vec3d(world.x, world.y, world.z));
            const glm::dvec3 index(worldToIndex * glm::dvec4(world, 1.0));
            for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(index[axis], expected[axis], 1e-12 * (1.0 + std::abs(expected[axis])));
        }
    }
}

// The structural walk must accept, byte for byte, every layout OpenVDB writes.
TEST(VdbVolumeFile, ChecksAcceptEveryCompressionOpenVdbWrites) {
    for (unsigned compression : {0x0u, 0x1u, 0x2u, 0x3u, 0x4u, 0x6u}) {
        SCOPED_TRACE("compression " + std::to_string(compression));
        const fs::path path = tempPath("compression" + std::to_string(compression) + ".vdb");
        auto grids = linearGrids(compression & 1);
        grids.push_back({"flame", 1, [](double x, double, double, int) { return x > 0 ? 1.0f : 0.0f; }});
        grids.push_back({"staggered vel", 3, [](double, double y, double, int c) { return float(c * y); }, false, true});
        test::writeVdbFile(path, grids, 0.05, -0.3, 0.3, compression);
        const std::string bytes = readAll(path);
        const VdbFileLayout layout = checkVdbHeader(bytes, path.string());
        ASSERT_EQ(layout.grids.size(), 4u);
        for (const VdbGridEntry& grid : layout.grids) EXPECT_NO_THROW(checkVdbGrid(bytes, grid, path.string())) << grid.name;
        expectLinearSamples(VdbVolumeFile(path), (compression & 1) ? 3.5 / 2048 : 1e-5, glm::dvec3(0.0));
    }
}

// The tree size the walk reports is what OpenVDB allocates reading the grid
// (its own memUsage) within 10%: dense grids of float and vec3s values, and
// a file of 64 voxels each in nodes of its own (about 300 KiB a voxel).
TEST(VdbVolumeFile, TheWalkSizesTheTreeOpenVdbReads) {
    const fs::path dense = tempPath("tree_dense.vdb"), scattered = tempPath("tree_scattered.vdb");
    test::writeVdbFile(dense, linearGrids(true), 0.05, -0.6, 0.6);
    test::writeScatteredVdbFile(scattered, "density", 4);
    for (const fs::path& path : {dense, scattered}) {
        const std::string bytes = readAll(path);
        openvdb::io::File file(path.string());
        file.open();
        for (const VdbGridEntry& grid : checkVdbHeader(bytes, path.string()).grids) {
            const VdbTreeSize size = checkVdbGrid(bytes, grid, path.string()).tree;
            const double openVdb = static_cast<double>(file.readGrid(grid.name)->memUsage());
            EXPECT_NEAR(static_cast<double>(size.memoryBytes()) / openVdb, 1.0, 0.1) << path << " " << grid.name;
        }
    }
}

TEST(VdbVolumeFile, MissingGridListsTheGridsTheFileHas) {
    const fs::path path = tempPath("houdini.vdb");
    test::writeVdbFile(path,
                       {{"density", 1, [](double, double, double, int) { return 1.0f; }},
                        {"temperature", 1, [](double, double, double, int) { return 1.0f; }},
                        {"vel", 3, [](double, double, double, int) { return 0.0f; }}},
                       0.1, 0.0, 0.2);
    const VdbVolumeFile file(path);
    try {
        file.sample("velocity", 3, renderGrid(), glm::dvec3(0.0));
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), path.string() + ": expected a grid named \"velocity\", found the grids "
                                                             "\"density\", \"temperature\", \"vel\"");
    }
    try {
        file.sample("vel", 1, renderGrid(), glm::dvec3(0.0));
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("grid \"vel\": expected a float grid, found a grid of type "
                                                 "\"Tree_vec3s_5_4_3\""),
                  std::string::npos)
            << error.what();
    }
}

TEST(VdbVolumeFile, NonFiniteSamplesAreInputErrors) {
    const fs::path path = tempPath("nan.vdb");
    test::writeVdbFile(path, {{"density", 1, [](double x, double, double, int) {
                                   return x > 0.15 ? std::numeric_limits<float>::quiet_NaN() : 1.0f;
                               }}},
                       0.1, -0.5, 0.5);
    const VdbVolumeFile file(path);
    EXPECT_NO_THROW(file.sample("density", 1, GridSpec{{1, 1, 1}, glm::dvec3(-0.2), glm::dvec3(0.0)}, glm::dvec3(0.0)));
    try {
        file.sample("density", 1, renderGrid(), glm::dvec3(0.0));  // cell x = 3 (centre 0.15) blends the voxels at x = 0.1 and 0.2
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("grid \"density\": expected finite values, found a non-finite value "
                                                 "sampled at (0.15, -0.15, -0.15) m"),
                  std::string::npos)
            << error.what();
    }
}

TEST(VdbVolumeFile, NotAVdbFileIsAnInputError) {
    const fs::path path = tempPath("text.vdb");
    std::ofstream(path) << "just some text, long enough to hold a header";
    EXPECT_THROW(VdbVolumeFile{path}, InputError);
    EXPECT_THROW(VdbVolumeFile{tempPath("does_not_exist.vdb")}, InputError);
}

}  // namespace
}  // namespace eikon::io
