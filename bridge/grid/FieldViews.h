// Non-owning views of one frame's optical fields, wherever their memory
// lives: a FieldSet's vectors, or a slot of the renderer's ring of
// persistently mapped GPU buffers (render/stages/FieldRing.h), so that the
// simulation writes its output straight into memory the GPU reads.
// One span per optical field (OpticalFields.h), laid out as in FieldSet; an
// empty span is a field the scene does not have. ε lives in host memory
// only (an imported volume's), never in the ring.
#pragma once

#include "bridge/grid/FieldSet.h"

#include <span>
#include <string>

namespace eikon {

template <typename Value>  // float, or const float for read-only views
struct BasicFieldViews {
    GridSpec grid;
    double referenceIndex = 1.0;
#define EIKON_FIELD_SPAN(member, ...) std::span<Value> member{};
    EIKON_OPTICAL_FIELDS(EIKON_FIELD_SPAN)
#undef EIKON_FIELD_SPAN

    bool hasExtinction() const { return !extinction.empty(); }
    bool hasScattering() const { return !scattering.empty(); }
    bool hasAnisotropy() const { return !anisotropy.empty(); }
    bool hasEmission() const { return !emission.empty(); }

    operator BasicFieldViews<const float>() const {
        BasicFieldViews<const float> views;
        views.grid = grid;
        views.referenceIndex = referenceIndex;
#define EIKON_FIELD_CONST_SPAN(member, ...) views.member = member;
        EIKON_OPTICAL_FIELDS(EIKON_FIELD_CONST_SPAN)
#undef EIKON_FIELD_CONST_SPAN
        return views;
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
