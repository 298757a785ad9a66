// A symmetric seven-point operator on a cell lattice, matrix-free:
//   (A x)_c = diag_c · x_c − Σ_{n coupled to c} w_axis(c,n) · x_n
// for the unknowns; other cells (solids, held samples) map to 0. Both the
// pressure Poisson matrix ([Bridson15] §5.3) and the backward-Euler
// diffusion matrix (I + Δt·D·L) have this form; Dirichlet neighbours (open
// boundaries, held samples) add to diag_c without a coupling.
#pragma once

#include "shaders/common/cpp_shim.h"

#include <glm/vec3.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <array>
#include <functional>

#include <cstdint>
#include <vector>

namespace eikon::sim {

struct SevenPointOperator {
    glm::ivec3 size{0};
    glm::dvec3 weight{0.0};  // coupling per axis; change it with setWeight
    // The diagonal's constant term: 0 for the Poisson matrix, 1 for I + Δt·D·L.
    double identity = 0.0;
    // Per cell: the bits of the faces whose weight adds to the diagonal
    // (coupled neighbours and Dirichlet faces), or kNotUnknown. The diagonal
    // depends on nothing else, so it is tabulated per class: a sweep reads one
    // byte per cell for it and multiplies by its reciprocal.
    std::vector<std::uint8_t> diagonalClass;
    std::vector<std::uint8_t> coupled;  // bit 2·axis + side: the lower (0) or upper (1) neighbour is an unknown
    // Per row (j, k): 1 when its cells 1 … size.x − 2 are all coupled on every
    // side (the bulk of the lattice), so kernels update them without a branch
    // or a table lookup per cell. Set by classifyRows; empty: no row is plain.
    std::vector<std::uint8_t> plainRow;

    static constexpr std::uint8_t bit(int axis, int side) { return static_cast<std::uint8_t>(1u << (2 * axis + side)); }
    // The encoding the GPU reads too (shaders/common/stencil_flags.glsl).
    static constexpr std::uint8_t kAllCoupled = shader::kCoupledBits;
    static constexpr std::uint8_t kNotUnknown = shader::kNotUnknown;

    // Sets the weights and tabulates identity + Σ w over each class's faces.
    void setWeight(glm::dvec3 w);
    // Fills plainRow from coupled and diagonalClass; call once they are set.
    void classifyRows();
    bool isPlainRow(int j, int k) const {
        return !plainRow.empty() && plainRow[static_cast<std::size_t>(j) + static_cast<std::size_t>(size.y) * k];
    }
    // Runs bulk(c) on the cells i = first, first + step, … of row (j, k) in
    // a plain row's bulk, and any(c) on the others.
    template <class Any, class Bulk>
    void forRowCells(int j, int k, int first, int step, const Any& any, const Bulk& bulk) const {
        const std::size_t row = index(0, j, k);
        int i = first;
        if (isPlainRow(j, k)) {
            for (; i < 1; i += step) any(row + static_cast<std::size_t>(i));
            for (; i + 1 < size.x; i += step) bulk(row + static_cast<std::size_t>(i));
        }
        for (; i < size.x; i += step) any(row + static_cast<std::size_t>(i));
    }
    // The diagonal and its reciprocal in a plain row's bulk.
    double bulkDiagonal() const { return diagonalOfClass_[kAllCoupled]; }
    double bulkInverseDiagonal() const { return inverseOfClass_[kAllCoupled]; }
    bool isUnknown(std::size_t c) const { return diagonalClass[c] != kNotUnknown; }
    double diagonal(std::size_t c) const { return diagonalOfClass_[diagonalClass[c]]; }
    double inverseDiagonal(std::size_t c) const { return inverseOfClass_[diagonalClass[c]]; }  // 0 off the unknowns

    std::size_t cellCount() const { return coupled.size(); }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(size.x) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(size.y) * static_cast<std::size_t>(k));
    }

    // Σ_{n coupled to cell c} w · x_n. Inline: every sweep calls it per cell.
    double neighbourSum(const std::vector<double>& x, std::size_t c) const {
        const std::uint8_t bits = coupled[c];
        const std::size_t sy = static_cast<std::size_t>(size.x);
        const std::size_t sz = sy * static_cast<std::size_t>(size.y);
        if (bits == kAllCoupled) return bulkNeighbourSum(x, c);  // no branch per neighbour
        double s = 0.0;
        if (bits & bit(0, 0)) s += weight.x * x[c - 1];
        if (bits & bit(0, 1)) s += weight.x * x[c + 1];
        if (bits & bit(1, 0)) s += weight.y * x[c - sy];
        if (bits & bit(1, 1)) s += weight.y * x[c + sy];
        if (bits & bit(2, 0)) s += weight.z * x[c - sz];
        if (bits & bit(2, 1)) s += weight.z * x[c + sz];
        return s;
    }

    // neighbourSum for a cell coupled on every side.
    double bulkNeighbourSum(const std::vector<double>& x, std::size_t c) const {
        const std::size_t sy = static_cast<std::size_t>(size.x);
        const std::size_t sz = sy * static_cast<std::size_t>(size.y);
        return weight.x * (x[c - 1] + x[c + 1]) + weight.y * (x[c - sy] + x[c + sy]) + weight.z * (x[c - sz] + x[c + sz]);
    }

    // y = A x, and returns x · y: the two passes of a CG step over p in one.
    double applyAndDot(const std::vector<double>& x, std::vector<double>& y) const;
    // r = b − A x
    void residual(const std::vector<double>& b, const std::vector<double>& x, std::vector<double>& r) const;
    // Subtracts the mean over the unknowns and sets the other cells to zero:
    // the projection onto the complement of the constant null space of a
    // pure-Neumann Poisson problem.
    void removeMeanOverUnknowns(std::vector<double>& values) const;

    // Slice kernels, to be chained as stages of one pass over memory
    // (WavefrontSlices.h). Colour c is the cells with (i + j + k) % 2 == c;
    // each red–black half-sweep reads only the other colour.
    // The Gauss–Seidel update of the cells of `colour` in slice k.
    void relaxSlice(const std::vector<double>& b, std::vector<double>& x, int k, int colour) const;
    // The first half-sweep from x = 0: colour 0, whose neighbours are all of
    // colour 1 and still zero, takes b / diag; colour 1 is cleared.
    void relaxSliceFromZero(const std::vector<double>& b, std::vector<double>& x, int k) const;
    // r = b − A x on the cells of `colour` in slice k and 0 on the others,
    // right after a half-sweep over the other colour left those equations
    // exactly solved: the whole residual for half the stencil work.
    void residualSliceAfterSweep(const std::vector<double>& b, const std::vector<double>& x, std::vector<double>& r,
                                 int k, int colour) const;
    // Σ b · x over slice k.
    double dotSlice(const std::vector<double>& b, const std::vector<double>& x, int k) const;
    // Whether passes over this lattice are worth running on several threads.
    bool passesInParallel() const;

private:
    std::array<double, kNotUnknown + 1> diagonalOfClass_{};  // 0 for kNotUnknown
    std::array<double, kNotUnknown + 1> inverseOfClass_{};   // likewise
};

// Runs body(k) for every slice k of the operator's lattice: in parallel,
// except on the small coarse levels of multigrid, where starting tasks would
// cost more than the work.
constexpr std::size_t kSerialSliceCells = 16384;  // below this many cells, one thread does a whole pass

template <class Body>
void forEachSlice(const SevenPointOperator& op, const Body& body) {
    if (!op.passesInParallel()) {
        for (int k = 0; k < op.size.z; ++k) body(k);
    } else {
        tbb::parallel_for(0, op.size.z, body);
    }
}

// Σ over slices k of body(k), reduced like forEachSlice runs; in parallel, by
// a deterministic reduction, so the bits do not depend on the threads' timing.
template <class Body>
double sumOverSlices(const SevenPointOperator& op, const Body& body) {
    if (!op.passesInParallel()) {
        double total = 0.0;
        for (int k = 0; k < op.size.z; ++k) total += body(k);
        return total;
    }
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<int>(0, op.size.z), 0.0,
        [&](const tbb::blocked_range<int>& slices, double partial) {
            for (int k = slices.begin(); k < slices.end(); ++k) partial += body(k);
            return partial;
        },
        std::plus<>());
}

// The pressure operator Σ_n (p_c − p_n)/h² over fluid cells (active != 0):
// solid neighbours and closed walls are Neumann (no term), open faces are
// Dirichlet p = 0 ([Bridson15] §5.3, eq. 5.14 generalised to 3D).
SevenPointOperator poissonOperator(glm::ivec3 size, glm::dvec3 h, const std::vector<std::uint8_t>& active,
                                   const bool openFaces[6]);

}  // namespace eikon::sim
