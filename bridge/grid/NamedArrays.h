// Per-cell arrays by name on a cell-centred grid: what the simulation hands
// to export (velocity, temperature, …) and what the VTK and OpenVDB writers
// (io/vtk, io/vdb) write.
#pragma once

#include "bridge/grid/GridSpec.h"

#include <string>
#include <vector>

namespace eikon {

// A named per-cell array: `components` floats per cell, x fastest, e.g.
// fluence (3 components).
struct NamedArray {
    std::string name;
    int components = 1;
    std::vector<float> values;
};

// One exported frame: its grid and its arrays.
struct ExportFrame {
    GridSpec grid;
    std::vector<NamedArray> arrays;

    const NamedArray* find(const std::string& name) const;
};

}  // namespace eikon
