// One-dimensional passes over `count` entries (a field's samples, a vector,
// a list): the program's work groups (its local size in x, read at link
// time) laid out in x, and in y past the driver's 65 535 groups along one axis; shaders read their entry with
// entryIndex() (shaders/sim/entry_index.glsl) and check it against the count.
#pragma once

#include "gl/GlObjects.h"

#include <cstddef>

namespace eikon::sim::gpu {

void dispatchOverEntries(const gl::Program& program, std::size_t count);

}  // namespace eikon::sim::gpu
