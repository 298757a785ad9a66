// Several dependent passes over the z-slices of a lattice in one pass over
// memory: the red–black Gauss–Seidel sweeps of multigrid smoothing and of
// diffusion, with the residual, prolongation or dot product beside them.
//
// Stage q (0 ≤ q < stages) is a pass over the slices. Stage q on slice k may
// read what stage q − 1 left on slices k − 1, k and k + 1, and what it reads
// must not yet have been overwritten by stage q + 1 there — as in a
// red–black sweep, where each half-sweep reads the other colour and writes
// its own. Run one after the other, each stage streams the whole lattice.
// Run as a wavefront — stage q on slice t − q at step t — every update
// still reads exactly the values it would have read there, so the result is
// the same bit for bit, but a slice's data is still in cache when the later
// stages reach it (temporal blocking; [Wellein09]).
//
// In parallel the slices are cut into chunks of at least 16 and 2·stages
// slices; where that leaves fewer chunks than threads, the stages run one
// after the other instead, each over all slices in parallel.
// Phase 1 runs the wavefront inside each chunk, stage q on the slices at
// least q from its ends; phase 2 finishes, around each chunk boundary e (and
// at the ends of the lattice), stage q on slices e − q … e + q − 1, stage by
// stage. Partial results are combined in an order fixed by the slice and
// thread counts, so a run repeats exactly; what the stages write does not
// depend on the threads at all.
#pragma once

#include "bridge/core/Error.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <vector>

namespace eikon::sim {

constexpr int kMaxWavefrontStages = 8;
using StageTotals = std::array<double, kMaxWavefrontStages>;

// stage(q, k) runs stage q on slice k and returns a partial result (identity
// when it has none); returns each stage's partial results combined.
template <class Stage, class Combine>
StageTotals runStagesAsWavefront(int slices, int stages, bool parallel, double identity, const Stage& stage,
                                 const Combine& combine) {
    EIKON_CHECK(stages >= 1 && stages <= kMaxWavefrontStages);
    StageTotals totals;
    totals.fill(identity);
    // Chunks of at least 16 slices, so that finishing their boundaries costs
    // little; a few per thread, so that the threads share them out evenly.
    const int minChunk = std::max(16, 2 * stages);
    const int threads = tbb::this_task_arena::max_concurrency();
    const int chunks = parallel ? std::min(slices / minChunk, 4 * threads) : 1;
    if (parallel && chunks < threads) {
        // Too few chunks to keep every thread busy: one stage at a time, each
        // over all slices in parallel, the slices' results combined in order.
        std::vector<double> perSlice(static_cast<std::size_t>(slices));
        for (int q = 0; q < stages; ++q) {
            tbb::parallel_for(0, slices, [&](int k) { perSlice[k] = stage(q, k); });
            for (const double partial : perSlice) totals[q] = combine(totals[q], partial);
        }
        return totals;
    }
    if (chunks < 2) {
        for (int t = 0; t < slices + stages - 1; ++t)
            for (int q = 0; q < stages; ++q)
                if (const int k = t - q; k >= 0 && k < slices) totals[q] = combine(totals[q], stage(q, k));
        return totals;
    }
    const auto chunkBegin = [&](int chunk) { return static_cast<int>(static_cast<long long>(chunk) * slices / chunks); };
    std::vector<StageTotals> chunkTotals(static_cast<std::size_t>(chunks), totals);
    tbb::parallel_for(0, chunks, [&](int chunk) {
        const int begin = chunkBegin(chunk), end = chunkBegin(chunk + 1);
        StageTotals& partial = chunkTotals[chunk];
        for (int t = begin; t < end + stages - 1; ++t)
            for (int q = 0; q < stages; ++q)
                if (const int k = t - q; k >= begin + q && k < end - q) partial[q] = combine(partial[q], stage(q, k));
    });
    std::vector<StageTotals> boundaryTotals(static_cast<std::size_t>(chunks + 1), totals);
    tbb::parallel_for(0, chunks + 1, [&](int boundary) {
        const int e = chunkBegin(boundary);
        StageTotals& partial = boundaryTotals[boundary];
        for (int q = 1; q < stages; ++q)
            for (int k = std::max(e - q, 0); k < std::min(e + q, slices); ++k) partial[q] = combine(partial[q], stage(q, k));
    });
    for (const StageTotals& partial : chunkTotals)
        for (int q = 0; q < stages; ++q) totals[q] = combine(totals[q], partial[q]);
    for (const StageTotals& partial : boundaryTotals)
        for (int q = 0; q < stages; ++q) totals[q] = combine(totals[q], partial[q]);
    return totals;
}

}  // namespace eikon::sim
