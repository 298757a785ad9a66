// OpenVDB files for tests, written with OpenVDB's own C++ API: grids as
// Blender (fluid_data_####.vdb: density, temperature, flame, velocity) and
// Houdini (density, temperature, vel) write them.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace eikon::test {

struct VdbTestGrid {
    std::string name;
    int components = 1;                                         // 1: FloatGrid, 3: Vec3SGrid
    std::function<float(double x, double y, double z, int c)> value;  // world position, component
    bool halfFloat = false;
    bool staggered = false;
};

// Writes a .vdb whose grids have voxel size `voxel` and active voxels over
// the world box [lo, hi] (cell-centred index space: voxel (i,j,k) sits at
// (i,j,k)·voxel), each voxel set to value(its centre). `compression`:
// OpenVDB's io flags (COMPRESS_ZIP | COMPRESS_ACTIVE_MASK by default).
void writeVdbFile(const std::filesystem::path& path, const std::vector<VdbTestGrid>& grids, double voxel,
                  double lo, double hi, unsigned compression = 0x3);

// Writes a .vdb of one float grid `name`, voxel size 1, with perAxis³
// active voxels of value 1 spaced 4096 apart: each in a 32³ node, a 16³
// node and a leaf of its own, so that OpenVDB reading it allocates about
// 300 KiB a voxel from a file of a few KiB a voxel.
void writeScatteredVdbFile(const std::filesystem::path& path, const std::string& name, int perAxis);

}  // namespace eikon::test
