// OpenVDB export: named float and vec3 grids whose voxel (i, j, k) is the
// render cell (i, j, k), bit-exact, sparse where the values are the
// background (the value outside the grid, within 1e-6 of the array's
// range), with the grid classes, vector types and units Blender and
// Houdini read; a grid that is background everywhere is not written.
#include "io/vdb/VdbFrameWriter.h"
#include "io/vdb/VdbVolumeFile.h"

#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <csignal>
#include <sys/resource.h>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

// A 5×3×2 grid with non-cubic voxels; "density" is zero in half the cells
// and 1e-7 in cell 0, within the tolerance of 1e-6 × its largest value 2.8;
// "index" is its background 1.0 in cell 0; "dye" is 0 everywhere.
ExportFrame makeFrame(const glm::dvec3& max) {
    ExportFrame frame;
    frame.grid = GridSpec{{5, 3, 2}, {-0.5, 0.25, 1.0}, max};
    NamedArray density{"density", 1, {}, {"1/m", ArrayRole::Density}}, index{"index", 1, {}, {"1", ArrayRole::Scalar, 1.0f}},
        velocity{"velocity", 3, {}, {"m/s", ArrayRole::Velocity}},
        dye{"dye", 1, std::vector<float>(frame.grid.cellCount(), 0.0f), {"1", ArrayRole::Density}};
    for (std::size_t c = 0; c < frame.grid.cellCount(); ++c) {
        density.values.push_back(c % 2 ? 0.0f : 0.1f * static_cast<float>(c) + 1e-7f);
        index.values.push_back(1.0f + 1.234567e-5f * static_cast<float>(c));
        velocity.values.insert(velocity.values.end(), {float(c), -0.5f * float(c), 1e-3f});
    }
    frame.arrays = {density, index, velocity, dye};
    return frame;
}

void expectRoundTrip(const ExportFrame& frame, const fs::path& path) {
    openvdb::io::File file(path.string());
    file.open(false);
    const auto meta = file.getMetadata();
    EXPECT_EQ(meta->metaValue<int32_t>("frame"), 4);
    EXPECT_EQ(meta->metaValue<double>("time"), 0.125);
    EXPECT_EQ(meta->metaValue<std::string>("scene"), "lens");
    EXPECT_FALSE(file.hasGrid("dye")) << "all background: not written";
    const auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    const auto index = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("index"));
    const auto velocity = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("velocity"));
    ASSERT_TRUE(density && index && velocity);
    file.close();
    EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
    EXPECT_EQ(index->getGridClass(), openvdb::GRID_UNKNOWN);
    EXPECT_EQ(velocity->getVectorType(), openvdb::VEC_CONTRAVARIANT_RELATIVE);
    EXPECT_EQ(density->background(), 0.0f);
    EXPECT_EQ(index->background(), 1.0f) << "n outside the grid";
    EXPECT_EQ(density->metaValue<std::string>("units"), "1/m");
    EXPECT_EQ(velocity->metaValue<std::string>("units"), "m/s");
    const GridSpec& spec = frame.grid;
    std::size_t nonzero = 0;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 5; ++i) {
                const openvdb::Coord ijk(i, j, k);
                const std::size_t c = spec.linearIndex(i, j, k);
                const float d = frame.arrays[0].values[c];
                const bool active = d > 1e-6f * 2.8f;
                EXPECT_EQ(density->tree().getValue(ijk), active ? d : 0.0f);
                EXPECT_EQ(density->tree().isValueOn(ijk), active);
                nonzero += active;
                EXPECT_EQ(index->tree().getValue(ijk), frame.arrays[1].values[c]);
                EXPECT_EQ(index->tree().isValueOn(ijk), c != 0);
                const openvdb::Vec3s v = velocity->tree().getValue(ijk);
                for (int a = 0; a < 3; ++a) EXPECT_EQ(v[a], frame.arrays[2].values[3 * c + static_cast<std::size_t>(a)]);
                const openvdb::Vec3d world = density->transform().indexToWorld(ijk);
                const glm::dvec3 centre = spec.cellCentre(i, j, k);
                for (int a = 0; a < 3; ++a) EXPECT_NEAR(world[a], centre[a], 1e-12);
            }
    EXPECT_EQ(density->activeVoxelCount(), nonzero);
    EXPECT_EQ(nonzero, spec.cellCount() / 2 - 1) << "cell 0's 1e-7 is background";
    EXPECT_EQ(index->activeVoxelCount(), spec.cellCount() - 1);
}

TEST(VdbExport, CubicAndBoxVoxelsRoundTripBitExact) {
    const fs::path root = fs::path(::testing::TempDir()) / "eikon_vdb_export";
    fs::remove_all(root);
    const VdbFrameWriter writer(root, "fields", "lens");
    for (const glm::dvec3 max : {glm::dvec3(2.0, 1.75, 2.0), glm::dvec3(1.5, 1.75, 2.0)}) {  // h = 0.5; then 0.4 × 0.5 × 0.5
        const ExportFrame frame = makeFrame(max);
        writer.writeFrame(4, 0.125, frame);
        EXPECT_EQ(writer.framePath(4), root / "vdb" / "fields_00004.vdb");
        expectRoundTrip(frame, writer.framePath(4));
        // Our importer reads what we export: cell centres sample their own voxel.
        const VdbVolumeFile file(writer.framePath(4));
        const auto index = file.sample("index", 1, frame.grid, glm::dvec3(0.0));
        for (std::size_t c = 0; c < index.size(); ++c) EXPECT_NEAR(index[c], frame.arrays[1].values[c], 1e-6);
    }
    int files = 0;
    for (const auto& entry : fs::directory_iterator(root / "vdb")) files += entry.path().extension() == ".vdb";
    EXPECT_EQ(files, 1);  // no temporaries left
    fs::remove_all(root);
}

// For Blender, Z up: eikon's (x, y, z) lands at (x, −z, y), and a velocity
// turns with it.
TEST(VdbExport, ZUpFilesTurnPositionsAndVelocities) {
    const fs::path root = fs::path(::testing::TempDir()) / "eikon_vdb_zup";
    fs::remove_all(root);
    const VdbFrameWriter writer(root, "fields", "lens", /*zUp=*/true);
    const ExportFrame frame = makeFrame(glm::dvec3(1.5, 1.75, 2.0));
    writer.writeFrame(0, 0.0, frame);
    openvdb::io::File file(writer.framePath(0).string());
    file.open(false);
    const auto velocity = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("velocity"));
    file.close();
    ASSERT_TRUE(velocity);
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 5; ++i) {
                const openvdb::Coord ijk(i, j, k);
                const glm::dvec3 centre = frame.grid.cellCentre(i, j, k);
                const openvdb::Vec3d world = velocity->transform().indexToWorld(ijk);
                EXPECT_NEAR(world[0], centre.x, 1e-12);
                EXPECT_NEAR(world[1], -centre.z, 1e-12);
                EXPECT_NEAR(world[2], centre.y, 1e-12);
                const std::size_t c = frame.grid.linearIndex(i, j, k);
                const openvdb::Vec3s v = velocity->tree().getValue(ijk);
                EXPECT_EQ(v[0], frame.arrays[2].values[3 * c]);
                EXPECT_EQ(v[1], -frame.arrays[2].values[3 * c + 2]);
                EXPECT_EQ(v[2], frame.arrays[2].values[3 * c + 1]);
            }
    fs::remove_all(root);
}

// A full disk, simulated by a file-size limit (writes past it fail with
// EFBIG, as they fail with ENOSPC on a full disk): openvdb::io::File closed
// such a truncated file as if whole. The export must fail with an error,
// leave no file under the final name (the last good frame stays whole) and
// no temporary.
TEST(VdbExport, AWriteFailureLeavesNeitherAFinalFileNorATemporary) {
    const fs::path root = fs::path(::testing::TempDir()) / "eikon_vdb_full";
    fs::remove_all(root);
    const VdbFrameWriter writer(root, "fields");
    ExportFrame frame;
    frame.grid = GridSpec{{48, 48, 48}, glm::dvec3(0.0), glm::dvec3(1.0)};
    NamedArray noise{"noise", 1, {}};
    for (std::size_t c = 0; c < frame.grid.cellCount(); ++c) noise.values.push_back(1.0f + 1e-3f * static_cast<float>(c % 977));
    frame.arrays = {noise};
    writer.writeFrame(0, 0.0, frame);  // under no limit: the frame before the disk fills
    const auto whole = fs::file_size(writer.framePath(0));

    rlimit previous{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &previous), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = previous;
    limited.rlim_cur = whole / 2;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
    bool failed = false;
    try {
        writer.writeFrame(1, 0.04, frame);
    } catch (const std::runtime_error&) {
        failed = true;
    }
    setrlimit(RLIMIT_FSIZE, &previous);
    std::signal(SIGXFSZ, oldHandler);
    EXPECT_TRUE(failed) << "a truncated frame was taken for a whole one";
    EXPECT_FALSE(fs::exists(writer.framePath(1)));
    EXPECT_EQ(fs::file_size(writer.framePath(0)), whole);
    int files = 0;
    for (const auto& entry : fs::directory_iterator(root / "vdb")) {
        ++files;
        EXPECT_EQ(entry.path().extension(), ".vdb") << entry.path();
    }
    EXPECT_EQ(files, 1);
    fs::remove_all(root);
}

}  // namespace
}  // namespace eikon::io
