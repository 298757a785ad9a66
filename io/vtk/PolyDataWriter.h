// VTK XML PolyData (.vtp) for surfaces and curves: receivers as quads,
// photon paths as polylines, and any caller's mesh (a deformed surface:
// vertices, triangles and named per-vertex arrays). Written atomically,
// with a Float64 TimeValue, like the ImageData frames; PolyDataSeries adds
// the .pvd and .series index files of a time series.
//
// The header keeps VTK out of its includes; only the .cpp sees it.
#pragma once

#include "io/export/ExportArrays.h"
#include "io/vtk/VtkSeriesIndex.h"
#include "bridge/scene/ExportDesc.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace eikon::io {

struct PolyData {
    std::vector<glm::vec3> points;
    // Cells as index lists into `points`: polygons (triangles, quads, …) and
    // polylines. A cell array has one tuple per polygon, then per line.
    std::vector<std::vector<std::uint32_t>> polygons;
    std::vector<std::vector<std::uint32_t>> lines;
    std::vector<NamedArray> pointArrays;
    std::vector<NamedArray> cellArrays;

    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { polygons.push_back({a, b, c}); }
};

// A triangle mesh (a deformed surface, say) with named per-vertex arrays,
// each holding `components` values per vertex in `vertices` order.
PolyData triangleMesh(const std::vector<glm::vec3>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                      std::vector<NamedArray> vertexArrays = {});

// Writes `data` to `path` (temporary name, fsync, rename). InternalError for
// indices past the points or arrays whose size does not match;
// std::runtime_error naming the path when it cannot be written.
void writePolyData(const std::filesystem::path& path, const PolyData& data, double time,
                   VtkExportDesc::Compression compression = VtkExportDesc::Compression::Zlib);

// DIR/vtk/NAME_NNNNN.vtp frames with NAME.pvd and NAME.vtp.series.
class PolyDataSeries {
public:
    PolyDataSeries(const std::filesystem::path& outputFolder, const std::string& baseName,
                   VtkExportDesc::Compression compression = VtkExportDesc::Compression::Zlib);
    void writeFrame(int frame, double time, const PolyData& data);
    const VtkSeriesIndex& index() const { return index_; }
    VtkSeriesIndex& index() { return index_; }

private:
    VtkExportDesc::Compression compression_;
    VtkSeriesIndex index_;
};

}  // namespace eikon::io
