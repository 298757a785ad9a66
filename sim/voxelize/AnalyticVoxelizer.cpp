#include "sim/voxelize/AnalyticVoxelizer.h"

#include "bridge/core/Error.h"
#include "sim/optics/AirOptics.h"
#include "sim/voxelize/Compositor.h"
#include "sim/voxelize/VolumePainter.h"

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

}  // namespace

double coverage(const ObjectDesc& object, const GridSpec& grid, int i, int j, int k, int supersampling) {
    EIKON_CHECK(object.kind == ObjectDesc::Kind::Sphere || object.kind == ObjectDesc::Kind::Box);
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

double airProfileIndex(const AirTemperatureProfile& profile, double y) {
    const double height = std::max(y - profile.groundHeight, 0.0);
    const double temperature =
        profile.airTemperature + (profile.groundTemperature - profile.airTemperature) * std::exp(-height / profile.scaleHeight);
    return 1.0 + GladstoneDale{}.refractivityAt(temperature, profile.pressure);
}

FieldSet voxelizeScene(const Scene& scene) {
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.referenceIndex = scene.medium.index;
    fields.deltaIndex.assign(fields.grid.cellCount(), 0.0f);
    const CellBox whole = CellBox::whole(fields.grid);
    fillMedium(scene, fields, whole);
    paintObjects(scene, fields);
    paintStrokes(scene, fields);
    fields.indexVersion = fields.extinctionVersion = fields.scatteringVersion = 1;
    return fields;
}

}  // namespace eikon::sim
