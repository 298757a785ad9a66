// The selection a scene's `export` section applies to a frame's arrays
// (bridge/grid/NamedArrays.h) before they are written: which fields, a
// region of interest and block-averaged downsampling. Shared by the VTK and
// OpenVDB writers so both see the same cells.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/grid/GridSpec.h"
#include "bridge/grid/NamedArrays.h"
#include "bridge/scene/ExportDesc.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace eikon::io {

// index (n_ref + δn, float32), delta_index, and extinction, scattering,
// anisotropy and emission where the field set has them. `outsideDeltaIndex`
// is δn outside the grid — a simulated scene's ambient fluid, which render
// cells outside the solver's box see too; 0 elsewhere — and so the
// background of delta_index, and n_ref + it that of index.
std::vector<NamedArray> fieldArrays(const ConstFieldViews& fields, double outsideDeltaIndex = 0.0);

// The cells [first, first + count) of `grid` whose centres lie in `region`
// (each count >= 1), or nullopt when no cell centre does.
struct CellRange {
    glm::ivec3 first{0};
    glm::ivec3 count{0};
};
std::optional<CellRange> cellsInRegion(const GridSpec& grid, const ExportRegion& region);

// The arrays `selection` wants, cropped to its region (InputError naming
// `where` when the region holds no cell centre) and averaged over
// d×d×d blocks (d = downsample, reduced to the cropped size on short axes;
// cells past the last whole block are dropped). Checks every array's size
// (InternalError otherwise).
ExportFrame selectCells(const ExportFrame& frame, const ExportSelection& selection, const std::string& where);

}  // namespace eikon::io
