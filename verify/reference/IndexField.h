// An index field in closed form: n(x) and ∇n(x) in double precision, for the
// reference tracer (ReferenceTracer) and for voxelizing accuracy cases onto a
// grid. Positions in metres.
#pragma once

#include <glm/vec3.hpp>

namespace eikon::reference {

class IndexField {
public:
    virtual ~IndexField() = default;
    virtual double index(const glm::dvec3& x) const = 0;
    virtual glm::dvec3 gradient(const glm::dvec3& x) const = 0;
};

}  // namespace eikon::reference
