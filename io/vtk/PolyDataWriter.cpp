#include "io/vtk/PolyDataWriter.h"

#include "bridge/core/Error.h"
#include "io/vtk/VtkXmlCommon.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

namespace eikon::io {

namespace {

vtkNew<vtkCellArray> cellArray(const std::vector<std::vector<std::uint32_t>>& cells, std::size_t points) {
    vtkNew<vtkCellArray> array;
    std::vector<vtkIdType> ids;
    for (const auto& cell : cells) {
        ids.assign(cell.begin(), cell.end());
        for (vtkIdType id : ids) EIKON_CHECK_MSG(static_cast<std::size_t>(id) < points, "PolyData point index");
        array->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    return array;
}

void checkArray(const NamedArray& array, std::size_t tuples) {
    EIKON_CHECK_MSG(array.components >= 1 && array.values.size() == static_cast<std::size_t>(array.components) * tuples,
                    "PolyData array \"" + array.name + "\" size");
}

}  // namespace

PolyData triangleMesh(const std::vector<glm::vec3>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                      std::vector<NamedArray> vertexArrays) {
    PolyData data;
    data.points = vertices;
    for (const auto& t : triangles) data.addTriangle(t[0], t[1], t[2]);
    data.pointArrays = std::move(vertexArrays);
    return data;
}

void writePolyData(const std::filesystem::path& path, const PolyData& data, double time,
                   VtkExportDesc::Compression compression) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(static_cast<vtkIdType>(data.points.size()));
    for (std::size_t i = 0; i < data.points.size(); ++i)
        points->SetPoint(static_cast<vtkIdType>(i), data.points[i].x, data.points[i].y, data.points[i].z);
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetPolys(cellArray(data.polygons, data.points.size()));
    poly->SetLines(cellArray(data.lines, data.points.size()));
    for (const NamedArray& array : data.pointArrays) {
        checkArray(array, data.points.size());
        poly->GetPointData()->AddArray(makeFloatArray(array.name, array.components, array.values));
    }
    // VTK orders a PolyData's cells verts, lines, polys, strips; this writer
    // has no verts or strips, and a cell array lists polygons first, so the
    // arrays are reordered to VTK's lines-then-polygons order.
    const std::size_t polygons = data.polygons.size(), lines = data.lines.size();
    for (const NamedArray& array : data.cellArrays) {
        checkArray(array, polygons + lines);
        const auto c = static_cast<std::size_t>(array.components);
        std::vector<float> ordered(array.values.begin() + static_cast<std::ptrdiff_t>(c * polygons), array.values.end());
        ordered.insert(ordered.end(), array.values.begin(), array.values.begin() + static_cast<std::ptrdiff_t>(c * polygons));
        poly->GetCellData()->AddArray(makeFloatArray(array.name, array.components, ordered));
    }
    addTimeValue(*poly, time);
    addUnits(*poly, data.pointArrays);
    addUnits(*poly, data.cellArrays);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(poly);
    writeVtkXmlAtomically(*writer, compression, path);
}

PolyDataSeries::PolyDataSeries(const std::filesystem::path& outputFolder, const std::string& baseName,
                               VtkExportDesc::Compression compression)
    : compression_(compression), index_(outputFolder / "vtk", baseName, "vtp") {
    std::error_code error;
    std::filesystem::create_directories(outputFolder / "vtk", error);
    if (error) throw InputError((outputFolder / "vtk").string() + ": cannot create the VTK export folder (" + error.message() + ")");
}

void PolyDataSeries::writeFrame(int frame, double time, const PolyData& data) {
    writePolyData(index_.framePath(frame), data, time, compression_);
    index_.add(frame, time);
}

}  // namespace eikon::io
