// The solver's guard against NaN and Inf: every field is scanned after every
// phase, and the first non-finite sample stops the run with its field, its
// lattice index and the phase that produced it (docs/architecture.md,
// Errors and outputs: never traced silently).
#pragma once

#include "sim/field/GridField.h"

#include <string>

namespace eikon::sim {

// Throws InputError "sim: field <name>, <sample> (i, j, k) <when>: expected
// a finite value, found nan" for the first non-finite value; <when> is, say,
// "after advection".
// `sample` is "cell" for cell-centred fields and "face" for velocities.
void requireFinite(const GridField& field, const std::string& name, const std::string& sample,
                   const std::string& when);

// The same error for sample `index` of a lattice of `size` holding `value`
// (a backend that found it elsewhere: sim/gpu/GpuFiniteCheck.h).
[[noreturn]] void throwNotFinite(const std::string& name, const std::string& sample, glm::ivec3 size,
                                 std::size_t index, double value, const std::string& when);

}  // namespace eikon::sim
