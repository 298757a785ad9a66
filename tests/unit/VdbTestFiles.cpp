#include "tests/unit/VdbTestFiles.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>

namespace eikon::test {

namespace {

template <class GridT, class Convert>
typename GridT::Ptr makeGrid(const VdbTestGrid& spec, double voxel, double lo, double hi, Convert convert) {
    auto grid = GridT::create();
    grid->setName(spec.name);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->setSaveFloatAsHalf(spec.halfFloat);
    if (spec.staggered) grid->setGridClass(openvdb::GRID_STAGGERED);
    auto accessor = grid->getAccessor();
    const int first = static_cast<int>(std::ceil(lo / voxel)), last = static_cast<int>(std::floor(hi / voxel));
    for (int k = first; k <= last; ++k)
        for (int j = first; j <= last; ++j)
            for (int i = first; i <= last; ++i)
                accessor.setValue(openvdb::Coord(i, j, k), convert(i * voxel, j * voxel, k * voxel));
    return grid;
}

}  // namespace

void writeVdbFile(const std::filesystem::path& path, const std::vector<VdbTestGrid>& grids, double voxel, double lo,
                  double hi, unsigned compression) {
    openvdb::initialize();
    openvdb::GridPtrVec out;
    for (const VdbTestGrid& spec : grids) {
        if (spec.components == 1) {
            out.push_back(makeGrid<openvdb::FloatGrid>(spec, voxel, lo, hi, [&](double x, double y, double z) {
                return spec.value(x, y, z, 0);
            }));
        } else {
            out.push_back(makeGrid<openvdb::Vec3SGrid>(spec, voxel, lo, hi, [&](double x, double y, double z) {
                return openvdb::Vec3s(spec.value(x, y, z, 0), spec.value(x, y, z, 1), spec.value(x, y, z, 2));
            }));
        }
    }
    openvdb::io::File file(path.string());
    file.setCompression(compression);
    file.write(out);
    file.close();
}

void writeScatteredVdbFile(const std::filesystem::path& path, const std::string& name, int perAxis) {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create();
    grid->setName(name);
    auto accessor = grid->getAccessor();
    for (int k = 0; k < perAxis; ++k)
        for (int j = 0; j < perAxis; ++j)
            for (int i = 0; i < perAxis; ++i) accessor.setValue(openvdb::Coord(4096 * i, 4096 * j, 4096 * k), 1.0f);
    openvdb::io::File file(path.string());
    file.write({grid});
    file.close();
}

}  // namespace eikon::test
