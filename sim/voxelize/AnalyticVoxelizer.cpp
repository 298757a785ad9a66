#include "sim/voxelize/AnalyticVoxelizer.h"

#include "sim/optics/AirOptics.h"
#include "sim/voxelize/VolumePainter.h"

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

namespace {

bool anyPositive(const std::vector<ObjectDesc>& objects, Rgb Material::*property) {
    return std::any_of(objects.begin(), objects.end(),
                       [&](const ObjectDesc& object) { return positive(object.material.*property); });
}

void ensureSized(std::vector<float>& field, std::size_t size, float value) {
    if (field.empty()) field.assign(size, value);
}

}  // namespace

void paintObjects(const Scene& scene, FieldSet& fields) {
    if (scene.objects.empty()) return;
    const std::size_t cells = fields.grid.cellCount();
    const bool anyAnisotropy = std::any_of(scene.objects.begin(), scene.objects.end(),
                                           [](const ObjectDesc& object) { return object.material.anisotropy != 0.0; });
    if (anyPositive(scene.objects, &Material::extinction)) ensureSized(fields.extinction, 3 * cells, 0.0f);
    if (anyPositive(scene.objects, &Material::scattering)) ensureSized(fields.scattering, 3 * cells, 0.0f);
    if (anyAnisotropy) ensureSized(fields.anisotropy, cells, 0.0f);
    paintObjects(scene, viewsOf(fields));
}

void paintObjects(const Scene& scene, const FieldViews& fields) {
    const glm::ivec3 r = fields.grid.resolution;
    tbb::parallel_for(0, r.z, [&](int k) {
        for (int j = 0; j < r.y; ++j)
            for (int i = 0; i < r.x; ++i) {
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                Material m;
                m.index = fields.referenceIndex + fields.deltaIndex[cell];
                for (int channel = 0; channel < 3; ++channel) {
                    if (fields.hasExtinction()) m.extinction[channel] = fields.extinction[3 * cell + channel];
                    if (fields.hasScattering()) m.scattering[channel] = fields.scattering[3 * cell + channel];
                }
                if (fields.hasAnisotropy()) m.anisotropy = fields.anisotropy[cell];
                bool covered = false;
                for (const auto& object : scene.objects) {
                    const double c = coverage(object, fields.grid, i, j, k, scene.grid.supersampling);
                    if (c <= 0.0) continue;
                    covered = true;
                    m.index += c * (object.material.index - m.index);
                    m.extinction += c * (object.material.extinction - m.extinction);
                    m.scattering += c * (object.material.scattering - m.scattering);
                    m.anisotropy += c * (object.material.anisotropy - m.anisotropy);
                }
                if (!covered) continue;
                fields.deltaIndex[cell] = static_cast<float>(m.index - fields.referenceIndex);
                for (int channel = 0; channel < 3; ++channel) {
                    if (fields.hasExtinction()) fields.extinction[3 * cell + channel] = static_cast<float>(m.extinction[channel]);
                    if (fields.hasScattering()) fields.scattering[3 * cell + channel] = static_cast<float>(m.scattering[channel]);
                }
                if (fields.hasAnisotropy()) fields.anisotropy[cell] = static_cast<float>(m.anisotropy);
            }
    });
}

double airProfileIndex(const AirTemperatureProfile& profile, double y) {
    const double height = std::max(y - profile.groundHeight, 0.0);
    const double temperature =
        profile.airTemperature + (profile.groundTemperature - profile.airTemperature) * std::exp(-height / profile.scaleHeight);
    return 1.0 + GladstoneDale{}.refractivityAt(temperature, profile.pressure);
}

void writeAirProfile(const AirTemperatureProfile& profile, FieldSet& fields) {
    const glm::ivec3 r = fields.grid.resolution;
    for (int j = 0; j < r.y; ++j) {
        const auto delta =
            static_cast<float>(airProfileIndex(profile, fields.grid.cellCentre(0, j, 0).y) - fields.referenceIndex);
        for (int k = 0; k < r.z; ++k)
            for (int i = 0; i < r.x; ++i) fields.deltaIndex[fields.grid.linearIndex(i, j, k)] = delta;
    }
}

FieldSet voxelizeScene(const Scene& scene) {
    FieldSet fields;
    fields.grid = GridSpec{scene.grid.resolution, scene.grid.boundsMin, scene.grid.boundsMax};
    fields.referenceIndex = scene.medium.index;
    const std::size_t cells = fields.grid.cellCount();
    fields.deltaIndex.assign(cells, 0.0f);
    if (scene.airProfile) writeAirProfile(*scene.airProfile, fields);
    auto uniform = [&](std::vector<float>& field, const Rgb& value) {
        field.resize(3 * cells);
        for (std::size_t c = 0; c < cells; ++c)
            for (int channel = 0; channel < 3; ++channel) field[3 * c + channel] = static_cast<float>(value[channel]);
    };
    if (positive(scene.medium.extinction)) uniform(fields.extinction, scene.medium.extinction);
    if (positive(scene.medium.scattering)) uniform(fields.scattering, scene.medium.scattering);
    if (scene.medium.anisotropy != 0.0) fields.anisotropy.assign(cells, static_cast<float>(scene.medium.anisotropy));
    paintObjects(scene, fields);
    paintStrokes(scene, fields);
    fields.indexVersion = fields.extinctionVersion = fields.scatteringVersion = 1;
    return fields;
}

}  // namespace eikon::sim
