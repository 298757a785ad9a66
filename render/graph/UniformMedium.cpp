#include "render/graph/UniformMedium.h"

#include <algorithm>

namespace eikon::render {

bool holdsOneValue(const FieldSource& field, int components) {
    if (field.floats == 0) return true;
    if (!field.host) return false;
    const float* first = field.host;
    for (std::size_t i = static_cast<std::size_t>(components); i < field.floats; i += static_cast<std::size_t>(components))
        if (!std::equal(first, first + components, field.host + i)) return false;
    return true;
}

}  // namespace eikon::render
