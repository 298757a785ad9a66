// The native backend's loop over a grid's cells: TBB chunks of rows (x
// fastest, the layout of every field and texture), each calling its own copy
// of `kernel` — a struct that compiles one of the shared kernels of
// shaders/common (through cpp_shim.h) over host arrays — for every cell of
// its rows.
#pragma once

#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace eikon::render {

template <class Kernel>
void forEachCell(const glm::ivec3& cells, const Kernel& kernel) {
    tbb::parallel_for(tbb::blocked_range<int>(0, cells.y * cells.z), [&](const tbb::blocked_range<int>& rows) {
        Kernel local = kernel;  // the shared kernels are written as GLSL: non-const functions
        for (int row = rows.begin(); row != rows.end(); ++row) {
            glm::ivec3 cell(0, row % cells.y, row / cells.y);
            for (cell.x = 0; cell.x < cells.x; ++cell.x) local(cell);
        }
    });
}

// x + r.x·(y + r.y·z): a cell's place in a field of `cells`.
inline std::size_t cellOffset(const glm::ivec3& cell, const glm::ivec3& cells) {
    return static_cast<std::size_t>(cell.x) +
           static_cast<std::size_t>(cells.x) * (static_cast<std::size_t>(cell.y) +
                                                static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(cell.z));
}

}  // namespace eikon::render
