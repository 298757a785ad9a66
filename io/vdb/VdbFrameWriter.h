// Per-frame OpenVDB export for DCC tools (Blender, Houdini): every array of
// an exported frame becomes a named grid — one component a FloatGrid, three
// a Vec3SGrid — in DIR/vdb/NAME_NNNNN.vdb. Index (i, j, k) of a grid is
// render cell (i, j, k): the transform scales by the voxel size and
// translates to the centre of cell (0, 0, 0), OpenVDB's cell-centred
// convention. Values equal to 0 stay inactive background, so empty regions
// stay sparse (tools::copyFromDense). The file metadata holds "frame" and
// "time" (s). Files are written to a temporary name and renamed.
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
    VdbFrameWriter(const std::filesystem::path& outputFolder, std::string baseName);

    // std::runtime_error naming the path when the file cannot be written;
    // InternalError for a negative frame or arrays that do not fit the grid.
    void writeFrame(int frame, double time, const ExportFrame& arrays) const;

    std::filesystem::path framePath(int frame) const;

private:
    std::filesystem::path directory_;
    std::string baseName_;
};

}  // namespace eikon::io
