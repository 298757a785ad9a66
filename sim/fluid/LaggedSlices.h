// Two passes over the z-slices of a lattice in one pass over memory, for the
// red–black Gauss–Seidel sweeps of multigrid smoothing and of diffusion.
//
// A red–black sweep is two half-sweeps: `first` updates the cells of one
// colour, reading only the other colour, and `second` the other colour,
// reading only the first. Run one after the other, each streams the whole
// lattice. Run lagged — first on slice k, then second on slice k − 1, whose
// first-colour neighbours on k − 2, k − 1 and k are then all updated — the
// data of a slice is still in cache when the second pass reaches it. The
// result is bit for bit that of the two passes run one after the other: every
// update reads exactly the values it would have read there.
//
// In parallel the slices are cut into chunks. A chunk runs its first pass on
// all its slices and the second on all but its two end slices, which need the
// first pass of the neighbouring chunks; a second parallel loop finishes
// those. The chunks depend only on the slice count, and the partial results
// are combined in chunk order, so the result does not depend on the threads.
#pragma once

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <vector>

namespace eikon::sim {

// first(k) and second(k) update slice k and return a partial result (0 or
// identity when there is nothing to report); returns the combination of all
// of them.
template <class First, class Second, class Combine>
double lagSecondPassBySlice(int slices, bool parallel, double identity, const First& first, const Second& second,
                            const Combine& combine) {
    if (slices <= 0) return identity;
    if (!parallel) {
        double total = identity;
        for (int k = 0; k < slices; ++k) {
            total = combine(total, first(k));
            if (k > 0) total = combine(total, second(k - 1));
        }
        return combine(total, second(slices - 1));
    }
    // Chunks of at least 16 slices, so that redoing their end slices costs
    // little; a few per thread, so that the threads share them out evenly.
    constexpr int kMinChunkSlices = 16;
    const int perThread = 4 * tbb::this_task_arena::max_concurrency();
    const int chunks = std::clamp(std::min(slices / kMinChunkSlices, perThread), 1, slices);
    const auto chunkBegin = [&](int chunk) { return static_cast<int>(static_cast<long long>(chunk) * slices / chunks); };
    std::vector<double> partial(static_cast<std::size_t>(chunks), identity);
    tbb::parallel_for(0, chunks, [&](int chunk) {
        const int begin = chunkBegin(chunk), end = chunkBegin(chunk + 1);
        double p = identity;
        for (int k = begin; k < end; ++k) {
            p = combine(p, first(k));
            if (k - 1 > begin) p = combine(p, second(k - 1));
        }
        partial[chunk] = p;
    });
    tbb::parallel_for(0, chunks, [&](int chunk) {
        const int begin = chunkBegin(chunk), end = chunkBegin(chunk + 1);
        double p = combine(partial[chunk], second(begin));
        if (end - 1 > begin) p = combine(p, second(end - 1));
        partial[chunk] = p;
    });
    double total = identity;
    for (const double p : partial) total = combine(total, p);
    return total;
}

}  // namespace eikon::sim
