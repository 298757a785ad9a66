// Gradient-index lenses with closed-form foci: the Luneburg lens, Maxwell's
// fish-eye and a glass sphere (paraxial focus, and against the reference
// tracer on the same smoothed field, and the camera's exit rays in image
// space against the exact sharp sphere); their receiver maps are in
// MapCases.cpp.
#include "verify/accuracy/Cases.h"

#include "verify/accuracy/ImageSpaceRows.h"
#include "verify/reference/AnalyticFields.h"
#include "verify/reference/ReferenceTracer.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <utility>

namespace eikon::accuracy {

namespace {

Scene cubeScene(double halfSize, long long photons) {
    Scene scene;
    scene.grid.boundsMin = glm::dvec3(-halfSize);
    scene.grid.boundsMax = glm::dvec3(halfSize);
    scene.render.width = 8;
    scene.render.height = 8;
    scene.render.photons = photons;
    return scene;
}

LightDesc beam(glm::dvec3 direction) {
    LightDesc light;
    light.kind = LightDesc::Kind::Directional;
    light.direction = glm::normalize(direction);
    light.irradiance = Rgb(1.0);
    return light;
}

// Solves the 3×3 system [A | b] by Gaussian elimination with partial pivoting.
std::array<double, 3> solveNormalEquations(double m[3][4]) {
    for (int col = 0; col < 3; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 3; ++r)
            if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
        for (int c = 0; c < 4; ++c) std::swap(m[col][c], m[pivot][c]);
        for (int r = col + 1; r < 3; ++r) {
            const double f = m[r][col] / m[col][col];
            for (int c = col; c < 4; ++c) m[r][c] -= f * m[col][c];
        }
    }
    std::array<double, 3> x{};
    for (int r = 2; r >= 0; --r) {
        double sum = m[r][3];
        for (int c = r + 1; c < 3; ++c) sum -= m[r][c] * x[static_cast<std::size_t>(c)];
        x[static_cast<std::size_t>(r)] = sum / m[r][r];
    }
    return x;
}

// The straight line a photon leaves along: its last two vertices (the point
// where it left the grid and the end of its straight flight).
struct ExitRay {
    glm::dvec3 point, direction;
};
ExitRay exitRay(const PhotonPath& path) {
    const glm::dvec3 a = path[path.size() - 2], b = path.back();
    return {a, glm::normalize(b - a)};
}

// Luneburg lens n = √(2 − (r/R)²), R = 0.4 m, in a 1 m cube of 64³ voxels,
// lit by a parallel beam along +z. Every ray focuses on the far surface at
// (0, 0, R). Error: where the exit ray crosses the plane z = R, its distance
// from the focus over R (RMS over rays with impact parameter < 0.9 R), and in voxels.
class LuneburgCase final : public AccuracyCase {
public:
    std::string name() const override { return "luneburg"; }
    std::vector<RunSettings> sweep(bool quick) const override { return standardSweep(quick, {}); }
    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        constexpr double kRadius = 0.4;
        const reference::LuneburgField field(glm::dvec3(0.0), kRadius);
        Scene scene = cubeScene(0.5, pathCasePhotons(quick));
        scene.lights.push_back(beam({0.0, 0.0, 1.0}));
        applySettings(scene, settings, glm::ivec3(64));
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(field, grid, 1.0), pathRequest(scene, 2.0 / h, settings.stepVoxels));
        const glm::dvec3 focus(0.0, 0.0, kRadius);
        std::vector<double> relative, voxels;
        for (const PhotonPath& path : trace.paths) {
            if (path.size() < 3 || std::hypot(path[0].x, path[0].y) > 0.9 * kRadius) continue;
            const ExitRay ray = exitRay(path);
            if (ray.direction.z <= 0.0) continue;
            const double miss = glm::length(linePlaneIntersection(ray.point, ray.direction, focus, {0, 0, 1}) - focus);
            relative.push_back(miss / kRadius);
            voxels.push_back(miss / h);
        }
        Measurement m{name(), "distance of the exit ray from the focus (0,0,R) in the plane z = R, over R (RMS)",
                      rms(relative), rms(voxels), static_cast<int>(relative.size())};
        return {makeRecord(scene, settings, trace, m, 0.75)};
    }
};

// Maxwell's fish-eye n = 2/(1 + (r/R)²), R = 0.5 m, in a 2 m cube of 64³
// voxels. A spot light at P = (0.4, 0, 0) aimed at −x (25° cone) images to
// P' = −R²P/|P|² = (−0.625, 0, 0); a receiver there, facing +x, stops each
// photon where it crosses that plane. Error: distance of the hit from P' over
// |P' − P| (RMS over rays), and in voxels.
class FishEyeCase final : public AccuracyCase {
public:
    std::string name() const override { return "fisheye"; }
    std::vector<RunSettings> sweep(bool quick) const override { return standardSweep(quick, {}); }
    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        const reference::FishEyeField field(2.0, 0.5);
        const glm::dvec3 source(0.4, 0.0, 0.0), image = field.image(source);
        Scene scene = cubeScene(1.0, pathCasePhotons(quick));
        LightDesc spot;
        spot.kind = LightDesc::Kind::Spot;
        spot.position = source;
        spot.direction = glm::dvec3(-1.0, 0.0, 0.0);
        spot.power = Rgb(1.0);
        spot.coneAngleDeg = 25.0;  // inside the cone toward the receiver, which the emitter also bounds
        spot.falloffDeg = 0.0;
        scene.lights.push_back(spot);
        ReceiverDesc receiver;
        receiver.point = image;
        receiver.normal = glm::dvec3(1.0, 0.0, 0.0);
        receiver.size = 0.8;
        receiver.resolution = 8;
        scene.receivers.push_back(receiver);
        applySettings(scene, settings, glm::ivec3(64));
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(field, grid, 1.0), pathRequest(scene, 2.0 / h, settings.stepVoxels));
        const double span = glm::length(image - source);
        std::vector<double> relative, voxels;
        for (const PhotonPath& path : trace.paths) {
            const glm::dvec3 hit = path.back();
            if (path.size() < 3 || std::abs(hit.x - image.x) > 1e-4) continue;  // not stopped by the receiver
            relative.push_back(glm::length(hit - image) / span);
            voxels.push_back(glm::length(hit - image) / h);
        }
        Measurement m{name(), "distance of each ray from the image -R^2 P/|P|^2 in its plane, over |P'-P| (RMS)",
                      rms(relative), rms(voxels), static_cast<int>(relative.size())};
        return {makeRecord(scene, settings, trace, m, 0.75)};
    }
};

// Glass sphere, n = 1.5, R = 0.25 m, surface smoothed by a Gaussian of the
// run's width (1 base voxel by default), in a 0.7 m cube of 64³ voxels, parallel
// light along −y. Two measures from one trace:
//   glass_sphere_focus: the paraxial focus — where exit rays cross the axis,
//     fitted by a quadratic in b² over impact parameters b < 0.35 R and extrapolated to
//     b = 0 — against nR/(2(n − 1)) from the centre, relative and in voxels;
//   glass_sphere_focus_smoothed: the same focus against the smoothed field's
//     own paraxial focus (reference tracer), which the smoothing alone moves
//     by +0.45%, +0.81%, +1.2% for widths of 0.5, 1, 2 voxels;
//   glass_sphere_reference: each exit ray against the reference tracer's ray
//     from the same start through the same smoothed field, compared in the
//     paraxial focal plane (RMS distance over R for b < 0.8 R, and in voxels).
class GlassSphereCase final : public AccuracyCase {
public:
    std::string name() const override { return "glass_sphere"; }
    std::vector<RunSettings> sweep(bool quick) const override {
        return standardSweep(quick, {.smoothing = true, .tolerances = true, .baseSmoothing = 1.0});
    }
    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        constexpr double kRadius = 0.25, kGlass = 1.5, kHalf = 0.35;
        Scene scene = cubeScene(kHalf, pathCasePhotons(quick));
        scene.lights.push_back(beam({0.0, -1.0, 0.0}));
        applySettings(scene, settings, glm::ivec3(64));
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const double width = settings.smoothingVoxels * (2.0 * kHalf / 64);  // in base voxels: fixed across the grid sweep
        const reference::GlassSphereField field(glm::dvec3(0.0), kRadius, kGlass, width);
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(field, grid, 1.0), pathRequest(scene, 1.4 / h, settings.stepVoxels));

        const double focus = field.paraxialFocusFromCentre();
        // Paraxial focus: least-squares quadratic of the axis crossing in q = (b/R)²
        // (spherical aberration and its next term), evaluated at q = 0.
        double m[3][4] = {};
        int paraxial = 0;
        const reference::ReferenceTracer reference(field, {.tolerance = 1e-12, .maxStep = 0.25 * width});
        std::vector<double> relative, voxels;
        for (const PhotonPath& path : trace.paths) {
            if (path.size() < 3) continue;
            const double b = std::hypot(path[0].x, path[0].z);
            const ExitRay ray = exitRay(path);
            if (b < 0.35 * kRadius && b > 0.02 * kRadius) {
                const glm::dvec3 p = ray.point, d = ray.direction;
                const double t = -(p.x * d.x + p.z * d.z) / (d.x * d.x + d.z * d.z);
                const double crossing = -(p.y + t * d.y);
                const double q = b * b / (kRadius * kRadius);
                // Weight q: an exit-angle error δ moves the crossing by δ·f/θ, θ ∝ b,
                // so the crossing's variance goes as 1/q.
                const double basis[3] = {1.0, q, q * q};
                for (int r = 0; r < 3; ++r) {
                    for (int c = 0; c < 3; ++c) m[r][c] += q * basis[r] * basis[c];
                    m[r][3] += q * basis[r] * crossing;
                }
                ++paraxial;
            }
            if (b < 0.8 * kRadius) {
                const reference::ReferenceResult truth =
                    reference.trace(reference.start(path[0], {0.0, -1.0, 0.0}), 10.0,
                                    [&](const reference::RayState& s) { return s.x.y + kHalf; });
                const glm::dvec3 plane(0.0, -focus, 0.0), normal(0.0, 1.0, 0.0);
                const glm::dvec3 expected =
                    linePlaneIntersection(truth.state.x, glm::normalize(truth.state.v), plane, normal);
                const double miss = glm::length(linePlaneIntersection(ray.point, ray.direction, plane, normal) - expected);
                relative.push_back(miss / kRadius);
                voxels.push_back(miss / h);
            }
        }
        const double intercept = paraxial >= 3 ? solveNormalEquations(m)[0] : 0.0;
        // The smoothed field's own paraxial focus (reference tracer, b = 0.01 R):
        // smoothing alone moves it from nR/(2(n − 1)).
        const reference::ReferenceResult paraxialTruth =
            reference.trace(reference.start(glm::dvec3(0.01 * kRadius, kHalf + 0.1, 0.0), {0.0, -1.0, 0.0}), 10.0,
                            [](const reference::RayState& s) { return s.x.x; });
        const double smoothedFocus = -paraxialTruth.state.x.y;
        Measurement focusError{"glass_sphere_focus",
                               "paraxial focus (axis crossings extrapolated to b = 0) against nR/(2(n-1)), relative",
                               std::abs(intercept - focus) / focus, std::abs(intercept - focus) / h, paraxial};
        Measurement referenceError{"glass_sphere_reference",
                                   "exit ray against the reference tracer in the focal plane, over R (RMS)",
                                   rms(relative), rms(voxels), static_cast<int>(relative.size())};
        Measurement smoothedFocusError{
            "glass_sphere_focus_smoothed",
            "paraxial focus against the smoothed field's own (reference tracer at b = 0.01R), relative",
            std::abs(intercept - smoothedFocus) / smoothedFocus, std::abs(intercept - smoothedFocus) / h, paraxial};
        return {makeRecord(scene, settings, trace, focusError, 48 * 2.0 * kHalf / 64),
                makeRecord(scene, settings, trace, smoothedFocusError), makeRecord(scene, settings, trace, referenceError)};
    }
};

}  // namespace

std::unique_ptr<AccuracyCase> makeLuneburgCase() { return std::make_unique<LuneburgCase>(); }
std::unique_ptr<AccuracyCase> makeFishEyeCase() { return std::make_unique<FishEyeCase>(); }
std::unique_ptr<AccuracyCase> makeGlassSphereCase() {
    return withImageSpaceRows(std::make_unique<GlassSphereCase>(), makeGlassSphereViewRows());
}

}  // namespace eikon::accuracy
