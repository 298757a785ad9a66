#include "sim/voxelize/VolumePainter.h"

#include "sim/voxelize/AnalyticVoxelizer.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace eikon::sim {

namespace {

constexpr double kCutoffSigmas = 4.0;

// One placement of the brush: centre, orthonormal frame (tangent first) and weight.
struct Stamp {
    glm::dvec3 centre;
    glm::dmat3 frame;
    double weight;
};

glm::dmat3 brushFrame(const glm::dvec3& tangent) {
    const glm::dvec3 up = std::abs(tangent.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 normal = glm::normalize(glm::cross(tangent, up));
    return {tangent, normal, glm::cross(normal, tangent)};
}

std::vector<Stamp> stampsOf(const PaintStroke& stroke) {
    const double sigma = 0.5 * stroke.radius;
    if (stroke.path.size() == 1) return {{stroke.path.front(), glm::dmat3(1.0), 1.0}};
    std::vector<Stamp> stamps;
    for (std::size_t s = 0; s + 1 < stroke.path.size(); ++s) {
        const glm::dvec3 a = stroke.path[s], b = stroke.path[s + 1];
        const double length = glm::length(b - a);
        if (length == 0.0) continue;
        const int count = std::max(1, static_cast<int>(std::ceil(length / sigma)));
        const double step = length / count;
        const glm::dmat3 frame = brushFrame((b - a) / length);
        for (int k = 0; k < count; ++k)
            stamps.push_back({a + (b - a) * ((k + 0.5) / count), frame, step / (std::sqrt(2.0 * M_PI) * sigma)});
    }
    return stamps;
}

std::uint32_t hash(glm::ivec3 lattice, unsigned seed) {
    std::uint32_t h = seed * 0x9E3779B9u;
    for (int axis = 0; axis < 3; ++axis) {
        h ^= static_cast<std::uint32_t>(lattice[axis]) + 0x7F4A7C15u + (h << 6) + (h >> 2);
        h *= 0x85EBCA6Bu;
        h ^= h >> 13;
    }
    return h;
}

double latticeValue(glm::ivec3 lattice, unsigned seed) { return (hash(lattice, seed) & 0xFFFFFFu) / double(0xFFFFFF); }

// Trilinear value noise with smoothstep weights, in [0, 1].
double valueNoise(const glm::dvec3& x, unsigned seed) {
    const glm::dvec3 cell = glm::floor(x);
    const glm::dvec3 t = x - cell;
    const glm::dvec3 w = t * t * (3.0 - 2.0 * t);
    const glm::ivec3 base(cell);
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const double weight = (offset.x ? w.x : 1.0 - w.x) * (offset.y ? w.y : 1.0 - w.y) * (offset.z ? w.z : 1.0 - w.z);
        sum += weight * latticeValue(base + offset, seed);
    }
    return sum;
}

double objectCoverage(const Scene& scene, const GridSpec& grid, int i, int j, int k) {
    double covered = 0.0;
    for (const auto& object : scene.objects) {
        if (object.kind != ObjectDesc::Kind::Sphere && object.kind != ObjectDesc::Kind::Box) continue;
        covered = std::max(covered, coverage(object, grid, i, j, k, scene.grid.supersampling));
    }
    return covered;
}

void paintStroke(const Scene& scene, const PaintStroke& stroke, const FieldViews& fields, const CellBox& region) {
    const GridSpec& grid = fields.grid;
    const double sigma = 0.5 * stroke.radius;
    const double reach = kCutoffSigmas * sigma;
    const glm::dvec3 h = grid.voxelSize();
    for (const Stamp& stamp : stampsOf(stroke)) {
        const glm::ivec3 lo = glm::max(glm::ivec3(glm::floor((stamp.centre - reach - grid.boundsMin) / h)), region.min);
        const glm::ivec3 hi =
            glm::min(glm::ivec3(glm::ceil((stamp.centre + reach - grid.boundsMin) / h)), region.max);
        if (glm::any(glm::greaterThanEqual(lo, hi))) continue;
        tbb::parallel_for(lo.z, hi.z, [&](int k) {
            for (int j = lo.y; j < hi.y; ++j)
                for (int i = lo.x; i < hi.x; ++i) {
                    const glm::dvec3 offset = grid.cellCentre(i, j, k) - stamp.centre;
                    const double r2 = glm::dot(offset, offset);
                    if (r2 > reach * reach) continue;
                    double w = stamp.weight * std::exp(-r2 / (2.0 * sigma * sigma));
                    if (stroke.brush == PaintStroke::Brush::Smoke)
                        w *= smokePattern(glm::transpose(stamp.frame) * offset / stroke.radius, stroke.seed);
                    if (stroke.where == PaintStroke::Where::InsideObjects) w *= objectCoverage(scene, grid, i, j, k);
                    if (stroke.where == PaintStroke::Where::OutsideObjects) w *= 1.0 - objectCoverage(scene, grid, i, j, k);
                    if (w == 0.0) continue;
                    const std::size_t cell = grid.linearIndex(i, j, k);
                    fields.deltaIndex[cell] += static_cast<float>(stroke.index * w);
                    for (int channel = 0; channel < 3; ++channel) {
                        if (fields.hasExtinction())
                            fields.extinction[3 * cell + channel] += static_cast<float>(stroke.extinction[channel] * w);
                        if (fields.hasScattering())
                            fields.scattering[3 * cell + channel] += static_cast<float>(stroke.scattering[channel] * w);
                    }
                }
        });
    }
}

bool anyStroke(const Scene& scene, Rgb PaintStroke::*amount) {
    return std::any_of(scene.paint.begin(), scene.paint.end(),
                       [&](const PaintStroke& stroke) { return stroke.*amount != Rgb(0.0); });
}

}  // namespace

bool strokeReaches(const PaintStroke& stroke, const glm::dvec3& at) {
    const double reach = kCutoffSigmas * 0.5 * stroke.radius;
    const std::vector<Stamp> stamps = stampsOf(stroke);
    return std::any_of(stamps.begin(), stamps.end(), [&](const Stamp& stamp) {
        const glm::dvec3 offset = at - stamp.centre;
        return glm::dot(offset, offset) <= reach * reach;
    });
}

double smokePattern(const glm::dvec3& local, unsigned seed) {
    double sum = 0.0, norm = 0.0, amplitude = 1.0, frequency = 2.0;
    for (int octave = 0; octave < 3; ++octave) {
        sum += amplitude * valueNoise(local * frequency, seed + static_cast<unsigned>(octave));
        norm += amplitude;
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    return sum / norm;
}

void paintStrokes(const Scene& scene, FieldSet& fields, const CellBox* region) {
    if (scene.paint.empty()) return;
    const std::size_t cells = fields.grid.cellCount();
    if (anyStroke(scene, &PaintStroke::extinction) && fields.extinction.empty()) fields.extinction.assign(3 * cells, 0.0f);
    if (anyStroke(scene, &PaintStroke::scattering) && fields.scattering.empty()) fields.scattering.assign(3 * cells, 0.0f);
    paintStrokes(scene, viewsOf(fields), region);
}

void paintStrokes(const Scene& scene, const FieldViews& fields, const CellBox* region) {
    const CellBox box = region ? *region : CellBox::whole(fields.grid);
    for (const PaintStroke& stroke : scene.paint) paintStroke(scene, stroke, fields, box);
}

}  // namespace eikon::sim
