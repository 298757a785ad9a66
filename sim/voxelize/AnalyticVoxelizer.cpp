#include "sim/voxelize/AnalyticVoxelizer.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

bool inside(const ObjectDesc& object, const glm::dvec3& p) {
    if (object.kind == ObjectDesc::Kind::Sphere) {
        const glm::dvec3 d = p - object.sphere.center;
        return glm::dot(d, d) <= object.sphere.radius * object.sphere.radius;
    }
    return glm::all(glm::greaterThanEqual(p, object.box.min)) && glm::all(glm::lessThanEqual(p, object.box.max));
}

// Signed distance bound: negative inside. Exact for spheres; for boxes the
// exact distance outside and the distance to the nearest face inside.
double signedDistance(const ObjectDesc& object, const glm::dvec3& p) {
    if (object.kind == ObjectDesc::Kind::Sphere) return glm::length(p - object.sphere.center) - object.sphere.radius;
    const glm::dvec3 centre = 0.5 * (object.box.min + object.box.max);
    const glm::dvec3 q = glm::abs(p - centre) - 0.5 * (object.box.max - object.box.min);
    return glm::length(glm::max(q, 0.0)) + std::min(std::max({q.x, q.y, q.z}), 0.0);
}

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

}  // namespace

double coverage(const ObjectDesc& object, const GridSpec& grid, int i, int j, int k, int supersampling) {
    const glm::dvec3 centre = grid.cellCentre(i, j, k);
    const glm::dvec3 h = grid.voxelSize();
    const double distance = signedDistance(object, centre);
    const double halfDiagonal = 0.5 * glm::length(h);
    if (distance >= halfDiagonal) return 0.0;
    if (distance <= -halfDiagonal) return 1.0;
    int hits = 0;
    for (int c = 0; c < supersampling; ++c)
        for (int b = 0; b < supersampling; ++b)
            for (int a = 0; a < supersampling; ++a) {
                const glm::dvec3 offset = (glm::dvec3(a, b, c) + 0.5) / static_cast<double>(supersampling) - 0.5;
                hits += inside(object, centre + offset * h);
            }
    return static_cast<double>(hits) / (supersampling * supersampling * supersampling);
}

FieldSet voxelizeScene(const Scene& scene) {
    FieldSet fields;
    fields.grid = GridSpec{scene.grid.resolution, scene.grid.boundsMin, scene.grid.boundsMax};
    fields.referenceIndex = scene.medium.index;
    bool anyExtinction = positive(scene.medium.extinction);
    bool anyScattering = positive(scene.medium.scattering);
    bool anyAnisotropy = scene.medium.anisotropy != 0.0;
    for (const auto& object : scene.objects) {
        anyExtinction = anyExtinction || positive(object.material.extinction);
        anyScattering = anyScattering || positive(object.material.scattering);
        anyAnisotropy = anyAnisotropy || object.material.anisotropy != 0.0;
    }
    const std::size_t cells = fields.grid.cellCount();
    fields.deltaIndex.assign(cells, 0.0f);
    if (anyExtinction) fields.extinction.assign(3 * cells, 0.0f);
    if (anyScattering) fields.scattering.assign(3 * cells, 0.0f);
    if (anyAnisotropy) fields.anisotropy.assign(cells, 0.0f);

    const glm::ivec3 r = fields.grid.resolution;
    tbb::parallel_for(0, r.z, [&](int k) {
        for (int j = 0; j < r.y; ++j)
            for (int i = 0; i < r.x; ++i) {
                Material m = scene.medium;
                for (const auto& object : scene.objects) {
                    const double c = coverage(object, fields.grid, i, j, k, scene.grid.supersampling);
                    if (c <= 0.0) continue;
                    m.index += c * (object.material.index - m.index);
                    m.extinction += c * (object.material.extinction - m.extinction);
                    m.scattering += c * (object.material.scattering - m.scattering);
                    m.anisotropy += c * (object.material.anisotropy - m.anisotropy);
                }
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                if (anyAnisotropy) fields.anisotropy[cell] = static_cast<float>(m.anisotropy);
                fields.deltaIndex[cell] = static_cast<float>(m.index - scene.medium.index);
                for (int channel = 0; channel < 3; ++channel) {
                    if (anyExtinction) fields.extinction[3 * cell + channel] = static_cast<float>(m.extinction[channel]);
                    if (anyScattering) fields.scattering[3 * cell + channel] = static_cast<float>(m.scattering[channel]);
                }
            }
    });
    fields.indexVersion = fields.extinctionVersion = fields.scatteringVersion = 1;
    return fields;
}

}  // namespace eikon::sim
