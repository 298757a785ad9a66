// Per-frame OpenVDB export for DCC tools (Blender, Houdini): every array of
// an exported frame becomes a named grid — one component a FloatGrid, three
// a Vec3SGrid — in DIR/vdb/NAME_NNNNN.vdb. Index (i, j, k) of a grid is
// render cell (i, j, k): the transform scales by the voxel size and
// translates to the centre of cell (0, 0, 0), OpenVDB's cell-centred
// convention. Each grid's background is the array's value outside the grid
// (NamedArray::meaning: the ambient n and δn for index and delta_index,
// the ambient temperature, else 0);
// values within 1e-6 of the array's largest distance from it stay inactive
// background, so empty regions stay sparse (tools::copyFromDense), and a grid
// that is background everywhere is not written at all. Density-like scalars
// are fog volumes, velocities and directions contravariant-relative vectors,
// other vectors invariant; each grid's metadata holds its "units". The file
// metadata holds "frame", "time" (s) and "scene". Files are written to a
// temporary name and renamed.
//
// The header keeps OpenVDB out of its includes; only the .cpp sees it.
#pragma once

#include "io/export/ExportArrays.h"

#include <filesystem>
#include <string>

namespace eikon::io {

class VdbFrameWriter {
public:
    // Creates DIR/vdb/. `baseName`: letters, digits, '_', '-', '.'.
    // `sceneName` goes into each file's metadata ("scene"); `zUp` writes a
    // Z-up world (VdbExportDesc::upAxis).
    VdbFrameWriter(const std::filesystem::path& outputFolder, std::string baseName, std::string sceneName = "",
                   bool zUp = false);

    // std::runtime_error naming the path when the file cannot be written;
    // InternalError for a negative frame or arrays that do not fit the grid.
    void writeFrame(int frame, double time, const ExportFrame& arrays) const;

    std::filesystem::path framePath(int frame) const;

private:
    std::filesystem::path directory_;
    std::string baseName_;
    std::string sceneName_;
    bool zUp_ = false;
};

}  // namespace eikon::io
