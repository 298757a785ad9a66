// Non-owning views of one frame's optical fields, wherever their memory
// lives: a FieldSet's vectors, or a slot of the renderer's ring of
// persistently mapped GPU buffers (render/stages/FieldRing.h), so that the
// simulation writes its output straight into memory the GPU reads.
// Layout as in FieldSet: δn one float per cell, κ and σs three (RGB), g one,
// the sharp surfaces' tree nodes and triangles as FieldSet lays them out, ε
// three; an empty span is a field the scene does not have.
#pragma once

#include "bridge/grid/FieldSet.h"

#include <span>
#include <string>

namespace eikon {

template <typename Value>  // float, or const float for read-only views
struct BasicFieldViews {
    GridSpec grid;
    double referenceIndex = 1.0;
    std::span<Value> deltaIndex;
    std::span<Value> extinction;
    std::span<Value> scattering;
    std::span<Value> anisotropy;
    std::span<Value> surfaceNodes;
    std::span<Value> surfaceTriangles;
    std::span<Value> emission{};  // RGB per cell; host memory only (an imported volume's), never in the ring

    bool hasExtinction() const { return !extinction.empty(); }
    bool hasScattering() const { return !scattering.empty(); }
    bool hasAnisotropy() const { return !anisotropy.empty(); }
    bool hasEmission() const { return !emission.empty(); }

    operator BasicFieldViews<const float>() const {
        return {grid,       referenceIndex, deltaIndex,   extinction,       scattering,
                anisotropy, surfaceNodes,   surfaceTriangles, emission};
    }
};
using FieldViews = BasicFieldViews<float>;
using ConstFieldViews = BasicFieldViews<const float>;

// Views of `fields`' vectors (valid while they are not resized).
FieldViews viewsOf(FieldSet& fields);
ConstFieldViews viewsOf(const FieldSet& fields);

// validateFields (FieldSet.h) for fields in any memory.
void validateFields(const ConstFieldViews& fields, const FieldOrigin& origin);

}  // namespace eikon
