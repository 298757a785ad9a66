// OpenVDB export: named float and vec3 grids whose voxel (i, j, k) is the
// render cell (i, j, k), bit-exact, sparse where the values are 0.
#include "io/vdb/VdbFrameWriter.h"
#include "io/vdb/VdbVolumeFile.h"

#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

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

}  // namespace
}  // namespace eikon::io
