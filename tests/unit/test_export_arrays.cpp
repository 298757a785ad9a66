// Selection of exported arrays: fields, region of interest, block averaging.
#include "bridge/core/Error.h"
#include "io/export/ExportArrays.h"

#include <gtest/gtest.h>

namespace eikon::io {
namespace {

// A 6×4×2 grid over [0, 6]×[0, 4]×[0, 2] (1 m voxels); scalar "s" holds the
// linear cell index, vector "v" holds (i, j, k) per cell.
ExportFrame makeFrame() {
    ExportFrame frame;
    frame.grid.resolution = {6, 4, 2};
    frame.grid.boundsMin = {0, 0, 0};
    frame.grid.boundsMax = {6, 4, 2};
    NamedArray s{"temperature", 1, {}}, v{"velocity", 3, {}};
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 6; ++i) {
                s.values.push_back(static_cast<float>(frame.grid.linearIndex(i, j, k)));
                v.values.insert(v.values.end(), {float(i), float(j), float(k)});
            }
    frame.arrays = {s, v};
    return frame;
}

TEST(ExportArrays, WholeGridIsCopiedBitExact) {
    const ExportFrame frame = makeFrame();
    const ExportFrame out = selectCells(frame, ExportSelection{}, "export.vtk");
    EXPECT_EQ(out.grid.resolution, frame.grid.resolution);
    EXPECT_EQ(out.grid.boundsMin, frame.grid.boundsMin);
    EXPECT_EQ(out.grid.boundsMax, frame.grid.boundsMax);
    ASSERT_EQ(out.arrays.size(), 2u);
    EXPECT_EQ(out.arrays[0].values, frame.arrays[0].values);
    EXPECT_EQ(out.arrays[1].values, frame.arrays[1].values);
}

TEST(ExportArrays, FieldListPicksArrays) {
    ExportSelection selection;
    selection.fields = {"velocity"};
    const ExportFrame out = selectCells(makeFrame(), selection, "export.vtk");
    ASSERT_EQ(out.arrays.size(), 1u);
    EXPECT_EQ(out.arrays[0].name, "velocity");
    EXPECT_EQ(out.find("temperature"), nullptr);
}

TEST(ExportArrays, RegionKeepsCellsWhoseCentresLieInside) {
    ExportSelection selection;
    // Centres at x = 0.5 … 5.5: [1.2, 3.5] holds 1.5, 2.5, 3.5 (inclusive); y: 0.5, 1.5; z: 1.5.
    selection.region = ExportRegion{{1.2, -3.0, 1.0}, {3.5, 1.9, 9.0}};
    const ExportFrame out = selectCells(makeFrame(), selection, "export.vtk");
    EXPECT_EQ(out.grid.resolution, glm::ivec3(3, 2, 1));
    EXPECT_EQ(out.grid.boundsMin, glm::dvec3(1, 0, 1));
    EXPECT_EQ(out.grid.boundsMax, glm::dvec3(4, 2, 2));
    const NamedArray& v = *out.find("velocity");
    // Output cell (2, 1, 0) is input cell (3, 1, 1).
    const std::size_t cell = out.grid.linearIndex(2, 1, 0);
    EXPECT_EQ(v.values[3 * cell + 0], 3.0f);
    EXPECT_EQ(v.values[3 * cell + 1], 1.0f);
    EXPECT_EQ(v.values[3 * cell + 2], 1.0f);
}

TEST(ExportArrays, DownsamplingAveragesBlocksAndDropsPartialOnes) {
    ExportSelection selection;
    selection.downsample = 4;  // x: one block of 4 (cells 4, 5 dropped); y: one of 4; z: short axis, block of 2
    const ExportFrame out = selectCells(makeFrame(), selection, "export.vtk");
    EXPECT_EQ(out.grid.resolution, glm::ivec3(1, 1, 1));
    EXPECT_EQ(out.grid.boundsMax, glm::dvec3(4, 4, 2));
    // Mean of i over 0..3 is 1.5, of j 1.5, of k 0.5; the index i + 6j + 24k averages to 1.5 + 9 + 12.
    EXPECT_FLOAT_EQ(out.find("velocity")->values[0], 1.5f);
    EXPECT_FLOAT_EQ(out.find("velocity")->values[1], 1.5f);
    EXPECT_FLOAT_EQ(out.find("velocity")->values[2], 0.5f);
    EXPECT_FLOAT_EQ(out.find("temperature")->values[0], 22.5f);

    selection.downsample = 2;
    const ExportFrame half = selectCells(makeFrame(), selection, "export.vtk");
    EXPECT_EQ(half.grid.resolution, glm::ivec3(3, 2, 1));
    EXPECT_EQ(half.grid.voxelSize(), glm::dvec3(2.0));
    // Block (2, 1, 0) covers i 4..5, j 2..3, k 0..1: mean i 4.5, j 2.5.
    const std::size_t cell = half.grid.linearIndex(2, 1, 0);
    EXPECT_FLOAT_EQ(half.find("velocity")->values[3 * cell + 0], 4.5f);
    EXPECT_FLOAT_EQ(half.find("velocity")->values[3 * cell + 1], 2.5f);
}

TEST(ExportArrays, RegionOutsideTheGridIsAnInputError) {
    ExportSelection selection;
    selection.region = ExportRegion{{10, 0, 0}, {11, 1, 1}};
    try {
        selectCells(makeFrame(), selection, "export.vtk");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("export.vtk.region"), std::string::npos) << error.what();
    }
    EXPECT_FALSE(cellsInRegion(makeFrame().grid, {{0.6, 0, 0}, {1.4, 4, 2}}).has_value());  // between two centres
}

}  // namespace
}  // namespace eikon::io
