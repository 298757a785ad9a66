// OpenVDB export: named float and vec3 grids whose voxel (i, j, k) is the
// render cell (i, j, k), bit-exact, sparse where the values are 0.
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

// A 5×3×2 grid with non-cubic voxels; "density" is zero in half the cells.
ExportFrame makeFrame(const glm::dvec3& max) {
    ExportFrame frame;
    frame.grid = GridSpec{{5, 3, 2}, {-0.5, 0.25, 1.0}, max};
    NamedArray density{"density", 1, {}}, index{"index", 1, {}}, velocity{"velocity", 3, {}};
    for (std::size_t c = 0; c < frame.grid.cellCount(); ++c) {
        density.values.push_back(c % 2 ? 0.0f : 0.1f * static_cast<float>(c) + 1e-7f);
        index.values.push_back(1.0f + 1.234567e-5f * static_cast<float>(c));
        velocity.values.insert(velocity.values.end(), {float(c), -0.5f * float(c), 1e-3f});
    }
    frame.arrays = {density, index, velocity};
    return frame;
}

void expectRoundTrip(const ExportFrame& frame, const fs::path& path) {
    openvdb::io::File file(path.string());
    file.open(false);
    const auto meta = file.getMetadata();
    EXPECT_EQ(meta->metaValue<int32_t>("frame"), 4);
    EXPECT_EQ(meta->metaValue<double>("time"), 0.125);
    const auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    const auto index = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("index"));
    const auto velocity = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("velocity"));
    ASSERT_TRUE(density && index && velocity);
    file.close();
    const GridSpec& spec = frame.grid;
    std::size_t nonzero = 0;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 5; ++i) {
                const openvdb::Coord ijk(i, j, k);
                const std::size_t c = spec.linearIndex(i, j, k);
                EXPECT_EQ(density->tree().getValue(ijk), frame.arrays[0].values[c]);
                EXPECT_EQ(density->tree().isValueOn(ijk), frame.arrays[0].values[c] != 0.0f);
                nonzero += frame.arrays[0].values[c] != 0.0f;
                EXPECT_EQ(index->tree().getValue(ijk), frame.arrays[1].values[c]);
                const openvdb::Vec3s v = velocity->tree().getValue(ijk);
                for (int a = 0; a < 3; ++a) EXPECT_EQ(v[a], frame.arrays[2].values[3 * c + static_cast<std::size_t>(a)]);
                const openvdb::Vec3d world = density->transform().indexToWorld(ijk);
                const glm::dvec3 centre = spec.cellCentre(i, j, k);
                for (int a = 0; a < 3; ++a) EXPECT_NEAR(world[a], centre[a], 1e-12);
            }
    EXPECT_EQ(density->activeVoxelCount(), nonzero);
    EXPECT_EQ(index->activeVoxelCount(), spec.cellCount());
}

TEST(VdbExport, CubicAndBoxVoxelsRoundTripBitExact) {
    const fs::path root = fs::path(::testing::TempDir()) / "eikon_vdb_export";
    fs::remove_all(root);
    const VdbFrameWriter writer(root, "fields");
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
