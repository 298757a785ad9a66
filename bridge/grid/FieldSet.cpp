#include "bridge/grid/FieldSet.h"

#include "bridge/grid/FieldViews.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"

#include <cmath>
#include <string>
#include <utility>

namespace eikon {

namespace {

void checkSize(std::span<const float> values, std::size_t expected, const FieldOrigin& origin, std::string_view field) {
    if (values.size() != expected)
        throw InputError(origin(field, nullptr) + " (the " + std::string(field) + " field)",
                         std::to_string(expected) + " values", std::to_string(values.size()));
}

// The refusal of the value of `field` in cell `cell`: its keys and position.
[[noreturn]] void refuse(const ConstFieldViews& fields, const FieldOrigin& origin, std::string_view field,
                         const char* quantity, std::size_t cell, const std::string& expected, double found) {
    const auto nx = static_cast<std::size_t>(fields.grid.resolution.x);
    const auto ny = static_cast<std::size_t>(fields.grid.resolution.y);
    const glm::dvec3 at = fields.grid.cellCentre(static_cast<int>(cell % nx), static_cast<int>((cell / nx) % ny),
                                                 static_cast<int>(cell / (nx * ny)));
    throw InputError(origin(field, &at) + " (" + quantity + " at " + formatPosition(at) + ")", expected,
                     formatRounded(found));
}

}  // namespace

void validateFields(const ConstFieldViews& fields, const FieldOrigin& origin) {
    const std::size_t cells = fields.grid.cellCount();
    checkSize(fields.deltaIndex, cells, origin, "index");
    for (std::size_t c = 0; c < cells; ++c) {
        const double n = fields.referenceIndex + fields.deltaIndex[c];
        if (!std::isfinite(fields.deltaIndex[c]) || n <= 0.0)
            refuse(fields, origin, "index", "the refractive index", c, "a finite index n > 0", n);
    }
    if (fields.hasExtinction()) checkSize(fields.extinction, 3 * cells, origin, "extinction");
    if (fields.hasScattering()) checkSize(fields.scattering, 3 * cells, origin, "scattering");
    if (fields.hasAnisotropy()) {
        checkSize(fields.anisotropy, cells, origin, "anisotropy");
        for (std::size_t c = 0; c < cells; ++c)
            if (!(std::abs(fields.anisotropy[c]) < 1.0f))
                refuse(fields, origin, "anisotropy", "the scattering anisotropy g", c, "a value in (-1, 1)",
                       fields.anisotropy[c]);
    }
    if (fields.hasEmission()) {
        checkSize(fields.emission, 3 * cells, origin, "emission");
        for (std::size_t v = 0; v < fields.emission.size(); ++v)
            if (!std::isfinite(fields.emission[v]) || fields.emission[v] < 0.0f)
                refuse(fields, origin, "emission", "the emission ε", v / 3, "a finite value >= 0 W/(m³·sr)",
                       fields.emission[v]);
    }
    if (fields.surfaceTriangles.size() % kSurfaceTriangleFloats != 0)
        throw InputError(origin("surfaces", nullptr) + " (the sharp surface triangles)",
                         "a multiple of " + std::to_string(kSurfaceTriangleFloats) + " floats",
                         std::to_string(fields.surfaceTriangles.size()));
    for (std::size_t v = 0; v < fields.surfaceTriangles.size(); ++v)
        if (!std::isfinite(fields.surfaceTriangles[v]))
            throw InputError(origin("surfaces", nullptr) + " (sharp surface triangle " +
                                 std::to_string(v / kSurfaceTriangleFloats) + ")",
                             "finite corners and normals", formatRounded(fields.surfaceTriangles[v]));
    for (std::size_t v = 0; v < 3 * cells; ++v) {
        const float kappa = fields.hasExtinction() ? fields.extinction[v] : 0.0f;
        const float sigma = fields.hasScattering() ? fields.scattering[v] : 0.0f;
        if (!std::isfinite(kappa) || kappa < 0.0f)
            refuse(fields, origin, "extinction", "the extinction κ", v / 3, "a finite value >= 0 (1/m)", kappa);
        if (!std::isfinite(sigma) || sigma < 0.0f || sigma > kappa)
            refuse(fields, origin, "scattering", "the scattering σs", v / 3,
                   "a finite value in [0, extinction = " + formatRounded(kappa) + "] (1/m)", sigma);
        if (!fields.hasExtinction() && !fields.hasScattering()) break;
    }
}

void publishField(std::vector<float>& current, std::vector<float>&& next, std::uint64_t& version) {
    if (current == next) return;
    current = std::move(next);
    ++version;
}

void validateFields(const FieldSet& fields, const FieldOrigin& origin) {
    validateFields(viewsOf(fields), origin);
}

}  // namespace eikon
