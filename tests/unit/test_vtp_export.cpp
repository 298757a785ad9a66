// PolyData export: a triangle mesh with point arrays, polylines and cell
// arrays read back bit-exact by vtkXMLPolyDataReader; receivers as quads;
// recorded photon paths as polylines.
#include "bridge/core/Error.h"
#include "io/vtk/ExportGeometry.h"
#include "io/vtk/PolyDataWriter.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cstring>
#include <fstream>
#include <sstream>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

vtkSmartPointer<vtkPolyData> readBack(const fs::path& path) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
}

void expectFloats(vtkDataArray* data, int components, const std::vector<float>& expected) {
    auto* array = vtkFloatArray::SafeDownCast(data);
    ASSERT_NE(array, nullptr);
    EXPECT_EQ(array->GetNumberOfComponents(), components);
    ASSERT_EQ(static_cast<std::size_t>(array->GetNumberOfValues()), expected.size());
    EXPECT_EQ(std::memcmp(array->GetPointer(0), expected.data(), expected.size() * sizeof(float)), 0);
}

std::vector<vtkIdType> cellPoints(vtkPolyData& poly, vtkIdType cell) {
    vtkNew<vtkIdList> ids;
    poly.GetCellPoints(cell, ids);
    return std::vector<vtkIdType>(ids->begin(), ids->end());
}

TEST(VtpExport, MeshLinesAndArraysRoundTrip) {
    const fs::path root = fs::path(::testing::TempDir()) / "eikon_vtp_roundtrip";
    fs::remove_all(root);
    // A deformed tetrahedron's four faces with a per-vertex displacement, plus a polyline.
    PolyData data = triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1.5f, 0}, {0, 0, 0.25f}},
                                 {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}},
                                 {{"displacement", 3, {0, 0, 0, 0.1f, 0, 0, 0, 0.2f, 0, 1e-7f, 0, 0.3f}}});
    data.points.push_back({2, 2, 2});
    data.pointArrays[0].values.insert(data.pointArrays[0].values.end(), {0, 0, 0});
    data.lines.push_back({3, 4});
    data.cellArrays.push_back({"id", 1, {10, 11, 12, 13, 20}});  // four faces, then the line
    PolyDataSeries series(root, "mesh");
    series.writeFrame(2, 0.5, data);
    EXPECT_EQ(series.index().framePath(2), root / "vtk" / "mesh_00002.vtp");
    EXPECT_TRUE(fs::exists(root / "vtk" / "mesh.pvd"));
    EXPECT_TRUE(fs::exists(root / "vtk" / "mesh.vtp.series"));

    const auto poly = readBack(series.index().framePath(2));
    ASSERT_EQ(poly->GetNumberOfPoints(), 5);
    EXPECT_EQ(poly->GetNumberOfPolys(), 4);
    EXPECT_EQ(poly->GetNumberOfLines(), 1);
    double p[3];
    poly->GetPoint(2, p);
    EXPECT_EQ(p[1], 1.5);
    expectFloats(poly->GetPointData()->GetArray("displacement"), 3, data.pointArrays[0].values);
    // VTK numbers lines before polygons.
    EXPECT_EQ(cellPoints(*poly, 0), (std::vector<vtkIdType>{3, 4}));
    EXPECT_EQ(cellPoints(*poly, 1), (std::vector<vtkIdType>{0, 2, 1}));
    expectFloats(poly->GetCellData()->GetArray("id"), 1, {20, 10, 11, 12, 13});
    auto* time = vtkDoubleArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("TimeValue"));
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(time->GetValue(0), 0.5);

    data.polygons.push_back({0, 9, 1});
    EXPECT_THROW(writePolyData(root / "bad.vtp", data, 0.0), InternalError);
    EXPECT_FALSE(fs::exists(root / "bad.vtp"));
    fs::remove_all(root);
}

TEST(VtpExport, ReceiversBecomeQuadsOfTheirMapTexels) {
    ReceiverDesc floor;
    floor.point = {0.0, -0.5, 0.0};
    floor.size = 2.0;  // 2 m square
    floor.normal = {0.0, 1.0, 0.0};  // axes u = (0, 0, -1), v = (1, 0, 0) (ReceiverAxes.h)
    floor.resolution = 2;  // 2 × 2 texels
    const std::vector<float> irradiance{1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4};
    const PolyData quads = receiverQuads({floor, floor}, {irradiance, irradiance});
    ASSERT_EQ(quads.points.size(), 18u);  // 3 × 3 lattice per receiver
    ASSERT_EQ(quads.polygons.size(), 8u);
    // The corner is point − (u + v): (1, −0.5, 1); the far corner (−1, −0.5, −1).
    EXPECT_EQ(quads.points[0], glm::vec3(1.0f, -0.5f, 1.0f));
    EXPECT_EQ(quads.points[8], glm::vec3(-1.0f, -0.5f, -1.0f));
    // Texel (i = 1, j = 0), the second value: one texel along u from the
    // corner, x in [0, 1], z in [−1, 0].
    const auto& texel = quads.polygons[1];
    EXPECT_EQ(quads.points[texel[0]], glm::vec3(1.0f, -0.5f, 0.0f));
    EXPECT_EQ(quads.points[texel[2]], glm::vec3(0.0f, -0.5f, -1.0f));
    EXPECT_EQ(quads.cellArrays[0].values[3 * 1], 2.0f);
    EXPECT_EQ(quads.cellArrays[1].values[5], 1.0f);  // second receiver
    EXPECT_EQ(quads.polygons[4][0], 9u);
}

TEST(VtpExport, RecordedPathsBecomePolylinesWithPower) {
    // Two slots of 3 vertices: photon 0 wrote 3, photon 1 only one (no path).
    const std::vector<glm::vec4> vertices{{0, 0, 0, 1}, {0, -1, 0, 1}, {0, -2, 0, 1}, {5, 5, 5, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    const std::vector<glm::vec4> power{{1, 1, 1, 0}, {0.5f, 0.25f, 0.125f, 0}, {0.25f, 0.0625f, 0.015625f, 0},
                                       {1, 1, 1, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    const PolyData paths = photonPolylines(vertices, power, 3);
    ASSERT_EQ(paths.lines.size(), 1u);
    EXPECT_EQ(paths.lines[0], (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(paths.points.size(), 3u);
    EXPECT_EQ(paths.pointArrays[0].values,
              (std::vector<float>{1, 1, 1, 0.5f, 0.25f, 0.125f, 0.25f, 0.0625f, 0.015625f}));
}

}  // namespace
}  // namespace eikon::io
