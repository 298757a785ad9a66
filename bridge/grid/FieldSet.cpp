#include "bridge/grid/FieldSet.h"

#include "bridge/grid/FieldViews.h"

#include "bridge/core/Error.h"

#include <cmath>
#include <string>
#include <utility>

namespace eikon {

namespace {

std::string cellName(const GridSpec& grid, std::size_t index) {
    const auto nx = static_cast<std::size_t>(grid.resolution.x);
    const auto ny = static_cast<std::size_t>(grid.resolution.y);
    return "cell (" + std::to_string(index % nx) + ", " + std::to_string((index / nx) % ny) + ", " +
           std::to_string(index / (nx * ny)) + ")";
}

void checkSize(std::span<const float> values, std::size_t expected, const std::string& where) {
    if (values.size() != expected)
        throw InputError(where, std::to_string(expected) + " values", std::to_string(values.size()));
}

}  // namespace

void validateFields(const ConstFieldViews& fields, const std::string& source) {
    const std::size_t cells = fields.grid.cellCount();
    checkSize(fields.deltaIndex, cells, source + ": field delta_index");
    for (std::size_t c = 0; c < cells; ++c) {
        const double n = fields.referenceIndex + fields.deltaIndex[c];
        if (!std::isfinite(fields.deltaIndex[c]) || n <= 0.0)
            throw InputError(source + ": field index, " + cellName(fields.grid, c), "a finite index > 0",
                             std::to_string(n));
    }
    if (fields.hasExtinction()) checkSize(fields.extinction, 3 * cells, source + ": field extinction");
    if (fields.hasScattering()) checkSize(fields.scattering, 3 * cells, source + ": field scattering");
    if (fields.hasAnisotropy()) {
        checkSize(fields.anisotropy, cells, source + ": field anisotropy");
        for (std::size_t c = 0; c < cells; ++c)
            if (!(std::abs(fields.anisotropy[c]) < 1.0f))
                throw InputError(source + ": field anisotropy, " + cellName(fields.grid, c), "a value in (-1, 1)",
                                 std::to_string(fields.anisotropy[c]));
    }
    if (fields.hasEmission()) {
        checkSize(fields.emission, 3 * cells, source + ": field emission");
        for (std::size_t v = 0; v < fields.emission.size(); ++v)
            if (!std::isfinite(fields.emission[v]) || fields.emission[v] < 0.0f)
                throw InputError(source + ": field emission, " + cellName(fields.grid, v / 3), "a finite value >= 0",
                                 std::to_string(fields.emission[v]));
    }
    if (fields.surfaceTriangles.size() % kSurfaceTriangleFloats != 0)
        throw InputError(source + ": sharp surface triangles", "a multiple of " + std::to_string(kSurfaceTriangleFloats) +
                         " floats", std::to_string(fields.surfaceTriangles.size()));
    for (std::size_t v = 0; v < fields.surfaceTriangles.size(); ++v)
        if (!std::isfinite(fields.surfaceTriangles[v]))
            throw InputError(source + ": sharp surface triangle " + std::to_string(v / kSurfaceTriangleFloats),
                             "finite corners and normals", std::to_string(fields.surfaceTriangles[v]));
    for (std::size_t v = 0; v < 3 * cells; ++v) {
        const float kappa = fields.hasExtinction() ? fields.extinction[v] : 0.0f;
        const float sigma = fields.hasScattering() ? fields.scattering[v] : 0.0f;
        if (!std::isfinite(kappa) || kappa < 0.0f)
            throw InputError(source + ": field extinction, " + cellName(fields.grid, v / 3),
                             "a finite value >= 0", std::to_string(kappa));
        if (!std::isfinite(sigma) || sigma < 0.0f || sigma > kappa)
            throw InputError(source + ": field scattering, " + cellName(fields.grid, v / 3),
                             "a finite value in [0, extinction = " + std::to_string(kappa) + "]",
                             std::to_string(sigma));
        if (!fields.hasExtinction() && !fields.hasScattering()) break;
    }
}

void publishField(std::vector<float>& current, std::vector<float>&& next, std::uint64_t& version) {
    if (current == next) return;
    current = std::move(next);
    ++version;
}

void validateFields(const FieldSet& fields, const std::string& source) {
    validateFields(viewsOf(fields), source);
}

}  // namespace eikon
