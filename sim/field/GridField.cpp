#include "sim/field/GridField.h"

namespace eikon::sim {

GridField::GridField(glm::ivec3 sampleCount, glm::dvec3 sampleOffset, double value)
    : size(sampleCount),
      offset(sampleOffset),
      values(static_cast<std::size_t>(sampleCount.x) * static_cast<std::size_t>(sampleCount.y) *
                 static_cast<std::size_t>(sampleCount.z),
             value) {}

}  // namespace eikon::sim
