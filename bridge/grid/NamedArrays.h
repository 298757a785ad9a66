// Per-cell arrays by name on a cell-centred grid: what the simulation hands
// to export (velocity, temperature, …) and what the VTK and OpenVDB writers
// (io/vtk, io/vdb) write.
#pragma once

#include "bridge/grid/GridSpec.h"

#include <string>
#include <vector>

namespace eikon {

// What an array means to the tools that read it (ParaView, Blender,
// Houdini): how it behaves — a plain scalar; a density-like quantity, 0
// where nothing is (OpenVDB's fog volume); a velocity or a direction (a
// vector that turns with the grid) — its unit, and its value outside the grid.
enum class ArrayRole { Scalar, Density, Velocity, Direction };

struct ArrayMeaning {
    std::string unit;  // SI ("1/m", "K", "1" for dimensionless); "cache units" for an imported cache's own
    ArrayRole role = ArrayRole::Scalar;
    float background = 0.0f;  // the value outside the grid (the ambient n and δn, the ambient temperature)
};

// A named per-cell array: `components` floats per cell, x fastest, e.g.
// fluence (3 components).
struct NamedArray {
    std::string name;
    int components = 1;
    std::vector<float> values;
    ArrayMeaning meaning{};
    // The run can never change it (a solver field no source drives,
    // sim/fluid/SolverExport.h): VTK export writes it once, not every frame
    // (io/vtk/VtkSeriesWriter.h).
    bool constant = false;
};

// One exported frame: its grid and its arrays.
struct ExportFrame {
    GridSpec grid;
    std::vector<NamedArray> arrays;

    const NamedArray* find(const std::string& name) const;
};

}  // namespace eikon
