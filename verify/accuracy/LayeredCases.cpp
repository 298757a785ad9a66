// Layered media, where n·cosθ = C is invariant along a ray: the catenary of
// a linear-gradient slab and the turning height of an exponential mirage
// (their receiver maps are in MapCases.cpp).
#include "verify/accuracy/Cases.h"

#include "verify/reference/AnalyticFields.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::accuracy {

namespace {

Scene layeredScene(glm::dvec3 boundsMax, glm::dvec3 lightDirection, long long photons) {
    Scene scene;
    scene.grid.boundsMin = glm::dvec3(0.0);
    scene.grid.boundsMax = boundsMax;
    scene.render.width = 8;
    scene.render.height = 8;
    scene.render.photons = photons;
    LightDesc light;
    light.kind = LightDesc::Kind::Directional;
    light.direction = glm::normalize(lightDirection);
    light.irradiance = Rgb(1.0);
    scene.lights.push_back(light);
    return scene;
}

// Inside the grid's x–y extent shrunk by `margin` (where the sampled field
// is not clamped at the faces; the field does not vary along z).
bool inside(const glm::dvec3& x, const GridSpec& grid, double margin) {
    return x.x > grid.boundsMin.x + margin && x.x < grid.boundsMax.x - margin && x.y > grid.boundsMin.y + margin &&
           x.y < grid.boundsMax.y - margin;
}

// n = 1 + 0.25·y on 128×64×32 voxels of 1 cm, light along (1, −0.2, 0). Rays
// entering through the x = 0 face follow the catenary
// n(y(x)) = C·cosh(b(x − x_v)/C) fixed by n·cosθ = C. Error: at the last
// vertex at least two voxels inside the grid, the distance to the catenary
// over the arc length travelled (RMS over photons), and in voxels. A second
// measure, where rays leave through the far x face: the relative error of the
// invariant n(x)·cosθ at the exit point.
class LinearSlabCase final : public AccuracyCase {
public:
    std::string name() const override { return "linear_slab"; }
    std::vector<RunSettings> sweep(bool quick) const override { return standardSweep(quick, {}); }
    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        const double a = 1.0, b = 0.25;
        const glm::dvec3 light(1.0, -0.2, 0.0);
        Scene scene = layeredScene(glm::dvec3(1.28, 0.64, 0.32), light, pathCasePhotons(quick));
        // A screen 10 cm past the far x face, beyond the longest step: an
        // escaping path ends on the grid's boundary, but one flying to a
        // receiver keeps its vertex past the face, and the flight from there
        // carries the exact exit direction.
        ReceiverDesc screen;
        screen.point = glm::dvec3(1.38, 0.32, 0.16);
        screen.normal = glm::dvec3(-1.0, 0.0, 0.0);
        screen.size = 0.64;
        screen.resolution = 8;
        scene.receivers.push_back(screen);
        // Photons aim at what the scene states: a smooth box of the field's
        // own extent (the sampled field below replaces whatever it would
        // voxelize to) keeps the whole grid in their region beside the screen.
        ObjectDesc medium;
        medium.kind = ObjectDesc::Kind::Box;
        medium.surface = ObjectDesc::Surface::Smooth;
        medium.box = {scene.grid.boundsMin, scene.grid.boundsMax};
        scene.objects.push_back(medium);
        applySettings(scene, settings, glm::ivec3(128, 64, 32));
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const reference::LinearSlabField field(a, b);
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(field, grid, 1.0), pathRequest(scene, 1.6 / h, settings.stepVoxels));

        const glm::dvec3 d = glm::normalize(light);
        std::vector<double> relative, voxels, invariant;
        for (const PhotonPath& path : trace.paths) {
            if (path.size() < 4 || path[1].x > 0.01 * h || path[1].y < 2 * h || path[1].y > grid.boundsMax.y - 2 * h) continue;
            const double n0 = a + b * path[1].y, c = n0 * d.x;
            const double vertexX = path[1].x + c / b * std::acosh(n0 / c);
            // The last vertex before the path first leaves the grid shrunk by two voxels
            // (after its entry through the x = 0 face).
            std::size_t last = 1;
            double arc = 0.0, travelled = 0.0;
            for (std::size_t v = 2; v < path.size() && grid.contains(path[v]); ++v) {
                travelled += glm::length(path[v] - path[v - 1]);
                if (inside(path[v], grid, 2 * h)) {
                    last = v;
                    arc = travelled;
                } else if (last > 1) {
                    break;
                }
            }
            if (arc < 20 * h) continue;
            const glm::dvec3 x = path[last];
            const double predicted = (c * std::cosh(b * (x.x - vertexX) / c) - a) / b;
            const double slope = std::sinh(b * (x.x - vertexX) / c);
            const double distance = std::abs(x.y - predicted) / std::sqrt(1.0 + slope * slope);
            relative.push_back(distance / arc);
            voxels.push_back(distance / h);
            // Exit through the far x face: the final straight flight carries the exit direction.
            const glm::dvec3 exit = path[path.size() - 2];
            if (exit.x >= grid.boundsMax.x && exit.y > 2 * h && exit.y < grid.boundsMax.y - 2 * h) {
                const glm::dvec3 direction = glm::normalize(path.back() - exit);
                invariant.push_back(((a + b * exit.y) * direction.x - c) / c);
            }
        }
        Measurement catenary{name(), "distance from the catenary over arc length (RMS over rays)", rms(relative),
                             rms(voxels), static_cast<int>(relative.size())};
        Measurement cosine{name() + "_invariant", "relative error of n*cos(theta) where rays leave the far face (RMS)",
                           rms(invariant), -1.0, static_cast<int>(invariant.size())};
        return {makeRecord(scene, settings, trace, catenary, 0.48), makeRecord(scene, settings, trace, cosine)};
    }
};

// Hot air over a road, exaggerated so the ray turns within 2.56 m:
// n = 1.05 − 0.05·exp(−y/0.1 m) on 256×48×32 voxels of 1 cm, light along
// (1, −0.15, 0). A ray entering the x = 0 face at height y0 turns where
// n(y_t) = C = n(y0)·cosθ0: y_t = −L·ln((n∞ − C)/δ). Error: the lowest point
// of the path (a parabola through the three lowest vertices) against y_t,
// over the height the ray descends (RMS), and in voxels.
class MirageCase final : public AccuracyCase {
public:
    std::string name() const override { return "mirage"; }
    std::vector<RunSettings> sweep(bool quick) const override { return standardSweep(quick, {}); }
    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        const reference::MirageField field(1.05, 0.05, 0.1);
        const glm::dvec3 light(1.0, -0.15, 0.0);
        Scene scene = layeredScene(glm::dvec3(2.56, 0.48, 0.32), light, pathCasePhotons(quick));
        scene.medium.index = 1.05;
        applySettings(scene, settings, glm::ivec3(256, 48, 32));
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(field, grid, 1.05), pathRequest(scene, 2.8 / h, settings.stepVoxels));

        const glm::dvec3 d = glm::normalize(light);
        std::vector<double> relative, voxels;
        for (const PhotonPath& path : trace.paths) {
            if (path.size() < 5 || path[1].x > 0.01 * h || path[1].y > grid.boundsMax.y - 3 * h) continue;
            const double c = field.index(path[1]) * d.x;
            const double expected = field.turningHeight(c);
            if (!(expected > 3 * h) || expected > path[1].y) continue;
            std::size_t lowest = 1;
            for (std::size_t v = 1; v < path.size() && grid.contains(path[v]); ++v)
                if (path[v].y < path[lowest].y) lowest = v;
            if (lowest < 2 || lowest + 1 >= path.size() || !inside(path[lowest + 1], grid, h)) continue;
            // Parabola y(x) through the lowest vertex and its neighbours; its minimum.
            const glm::dvec3 p0 = path[lowest - 1], p1 = path[lowest], p2 = path[lowest + 1];
            const double d01 = (p1.y - p0.y) / (p1.x - p0.x), d12 = (p2.y - p1.y) / (p2.x - p1.x);
            const double curvature = (d12 - d01) / (p2.x - p0.x);
            double turning = p1.y;
            if (curvature > 0.0) {
                const double slopeAtP1 = d01 + curvature * (p1.x - p0.x);
                turning = p1.y - slopeAtP1 * slopeAtP1 / (4.0 * curvature);
            }
            relative.push_back((turning - expected) / (path[1].y - expected));
            voxels.push_back((turning - expected) / h);
        }
        Measurement m{name(), "turning height error over the descent (RMS over rays)", rms(relative), rms(voxels),
                      static_cast<int>(relative.size())};
        return {makeRecord(scene, settings, trace, m, 1.92)};
    }
};

}  // namespace

std::unique_ptr<AccuracyCase> makeLinearSlabCase() { return std::make_unique<LinearSlabCase>(); }
std::unique_ptr<AccuracyCase> makeMirageCase() { return std::make_unique<MirageCase>(); }

}  // namespace eikon::accuracy
