// The solver's NaN/Inf guard on the GPU (FiniteCheck.h): each check of a
// substep marks the first non-finite sample of one field in a slot of its
// own, on the GPU; finish() reads the slots back in one transfer and throws
// the CPU backend's NumericalBreakdown (field, sample, phase, value) for the first
// check, in substep order, that found one.
#pragma once

#include "gl/GlObjects.h"
#include "sim/fluid/FiniteCheck.h"
#include "sim/gpu/GpuField.h"

#include <cstdint>
#include <string>
#include <vector>

namespace eikon::sim::gpu {

class GpuFiniteCheck {
public:
    static constexpr int kSlots = 64;  // checks a substep may make

    GpuFiniteCheck();

    // Clears the slots: call at the start of a substep.
    void begin();
    // Checks `field` on the GPU; `name`, `sample` and `when` as in requireFinite.
    void check(const GpuField& field, const std::string& name, const std::string& sample, const SolverPhase& when);
    // Reads the slots back; throws for the first check that found a non-finite sample.
    void finish();
    // Bytes the last finish() read back.
    std::uint64_t bytesRead() const { return bytesRead_; }

private:
    struct Check {
        const GpuField* field;
        std::string name, sample;
        SolverPhase when;
    };
    gl::Buffer firstBad_;  // per slot its first non-finite sample, then per slot that sample's bits
    gl::Program find_, record_;
    std::vector<Check> checks_;
    std::uint64_t bytesRead_ = 0;
};

}  // namespace eikon::sim::gpu
