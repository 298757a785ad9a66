#include "io/export/ExportArrays.h"

#include "bridge/core/Error.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace eikon::io {

std::vector<NamedArray> fieldArrays(const ConstFieldViews& fields, double outsideDeltaIndex) {
    const std::size_t cells = fields.grid.cellCount();
    EIKON_CHECK_MSG(fields.deltaIndex.size() == cells, "deltaIndex size");
    std::vector<NamedArray> arrays;
    // n = n_ref + δn for viewing; float32 spacing near 1.0003 is ~1.2e-7, too
    // coarse for a mirage's Δn ≈ 1e-5 gradients (and for δn's own float32
    // precision), so δn itself goes out too, exactly as the FieldSet holds it.
    // The backgrounds are rounded as the cells are, so that a cell holding
    // the outside value is exactly background.
    const auto outside = static_cast<float>(outsideDeltaIndex);
    const auto indexOf = [&](float deltaIndex) {
        return static_cast<float>(fields.referenceIndex + static_cast<double>(deltaIndex));
    };
    NamedArray index{"index", 1, std::vector<float>(cells), {"1", ArrayRole::Scalar, indexOf(outside)}};
    for (std::size_t c = 0; c < cells; ++c) index.values[c] = indexOf(fields.deltaIndex[c]);
    arrays.push_back(std::move(index));
    // Then each exported optical field the frame has, as it holds it; δn's
    // background is the outside δn.
    const auto add = [&](std::span<const float> values, const char* name, int channels, const char* unit,
                         ArrayRole role, float background) {
        if (values.empty()) return;
        arrays.push_back({name, channels, std::vector<float>(values.begin(), values.end()), {unit, role, background}});
    };
#define EIKON_EXPORT_FIELD(member, channels, version, format, ring, exportName, unit, role, ...) \
    if (*exportName)                                                                          \
        add(fields.member, exportName, channels, unit, ArrayRole::role,                       \
            std::string_view(#member) == "deltaIndex" ? outside : 0.0f);
    EIKON_OPTICAL_FIELDS(EIKON_EXPORT_FIELD)
#undef EIKON_EXPORT_FIELD
    return arrays;
}

std::optional<CellRange> cellsInRegion(const GridSpec& grid, const ExportRegion& region) {
    CellRange range;
    const glm::dvec3 h = grid.voxelSize();
    for (int axis = 0; axis < 3; ++axis) {
        // Cell i's centre is boundsMin + (i + ½)·h: inside when min <= centre <= max.
        const double low = std::ceil((region.min[axis] - grid.boundsMin[axis]) / h[axis] - 0.5);
        const double high = std::floor((region.max[axis] - grid.boundsMin[axis]) / h[axis] - 0.5);
        const double first = std::max(low, 0.0);
        const double last = std::min(high, static_cast<double>(grid.resolution[axis] - 1));
        if (!(last >= first)) return std::nullopt;
        range.first[axis] = static_cast<int>(first);
        range.count[axis] = static_cast<int>(last - first) + 1;
    }
    return range;
}

ExportFrame selectCells(const ExportFrame& frame, const ExportSelection& selection, const std::string& where) {
    const GridSpec& grid = frame.grid;
    CellRange range{glm::ivec3(0), grid.resolution};
    if (selection.region) {
        const auto cells = cellsInRegion(grid, *selection.region);
        if (!cells) throw InputError(where + ".region", "a box holding at least one cell centre of the grid", "none");
        range = *cells;
    }
    const glm::ivec3 block = glm::min(glm::ivec3(selection.downsample), range.count);
    const glm::ivec3 out = range.count / block;
    const glm::dvec3 h = grid.voxelSize();

    ExportFrame result;
    result.grid.resolution = out;
    result.grid.boundsMin = grid.boundsMin + glm::dvec3(range.first) * h;
    result.grid.boundsMax = result.grid.boundsMin + glm::dvec3(out * block) * h;
    const double blockCells = static_cast<double>(block.x) * block.y * block.z;
    for (const NamedArray& array : frame.arrays) {
        const auto c = static_cast<std::size_t>(array.components);
        EIKON_CHECK_MSG(array.components >= 1 && array.values.size() == c * grid.cellCount(),
                        "export array \"" + array.name + "\" size");
        if (!selection.wants(array.name)) continue;
        NamedArray selected{array.name, array.components, std::vector<float>(c * result.grid.cellCount()),
                            array.meaning, array.constant};
        std::vector<double> sum(c);
        for (int k = 0; k < out.z; ++k)
            for (int j = 0; j < out.y; ++j)
                for (int i = 0; i < out.x; ++i) {
                    std::fill(sum.begin(), sum.end(), 0.0);
                    const glm::ivec3 base = range.first + glm::ivec3(i, j, k) * block;
                    for (int bk = 0; bk < block.z; ++bk)
                        for (int bj = 0; bj < block.y; ++bj)
                            for (int bi = 0; bi < block.x; ++bi) {
                                const std::size_t cell = grid.linearIndex(base.x + bi, base.y + bj, base.z + bk);
                                for (std::size_t m = 0; m < c; ++m) sum[m] += array.values[c * cell + m];
                            }
                    const std::size_t target = result.grid.linearIndex(i, j, k);
                    for (std::size_t m = 0; m < c; ++m)
                        selected.values[c * target + m] = static_cast<float>(sum[m] / blockCells);
                }
        result.arrays.push_back(std::move(selected));
    }
    return result;
}

}  // namespace eikon::io
