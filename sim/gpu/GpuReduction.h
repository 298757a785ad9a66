// Reductions of solver vectors on the GPU — a sum, the largest magnitude, a
// dot product — into a small buffer of float64 results that later passes
// read where they are (a CG step's α and β) or the host reads when it must
// decide (a stopping test). Two passes over a fixed partition
// (shaders/sim/reduce.comp): the same inputs give the same bits every run.
#pragma once

#include "gl/GlObjects.h"

#include <array>
#include <cstddef>
#include <vector>

namespace eikon::sim::gpu {

class GpuReduction {
public:
    enum class Operation { Sum, MaxAbs, Dot };
    enum class Element { Float, Double };
    static constexpr int kSlots = 32;  // results a reduction buffer holds

    GpuReduction();

    // results[slot] = the operation over the first `count` elements of a
    // (and b, for Dot), both of `element` type. Runs on the GPU; nothing is read back.
    void run(Operation operation, Element element, const gl::Buffer& a, std::size_t count, int slot,
             const gl::Buffer* b = nullptr);
    // One result, read back (waits for the passes before it).
    double read(int slot) const;
    // The result buffer, for passes that read results[slot] themselves.
    const gl::Buffer& results() const { return results_; }
    void bindResults(GLuint binding) const { results_.bindStorage(binding); }
    // Sets results[slot] from the host.
    void write(int slot, double value);

private:
    static constexpr unsigned kGroups = 256;  // work groups of the first pass: the partials
    const gl::Program& program(Operation operation, Element element, int pass);

    gl::Buffer partials_;
    gl::Buffer results_;
    // Compiled on first use: [operation][element][pass].
    std::array<std::array<std::array<gl::Program, 2>, 2>, 3> programs_;
};

}  // namespace eikon::sim::gpu
