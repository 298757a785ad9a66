// The diagnostics' test object (docs/accuracy.md, "Diagnostics"): a 3D
// Gaussian index bump δn = A·exp(−r²/σ²) in air (n_ref = 1) on a 96³ grid
// over [−0.5, 0.5]³ m, and its closed forms for parallel light along −z in
// the paraxial limit: a ray at ρ from the axis gathers
// OPD(ρ) = ∫ δn dz = A·σ·√π·exp(−ρ²/σ²) and leaves deflected by
// ε = ∇⊥OPD / n_ref = −2ρ/σ² · OPD(ρ), toward the bump's centre. Sampled at
// the render cells' centres; no smoothing. Shared by test_diagnostics and
// test_shadowgraph_bos.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"
#include "tests/integration/TraceHelpers.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace eikon::test {

inline constexpr int kBumpCells = 96;        // over [−0.5, 0.5]³ m: σ is 14.4 voxels
inline constexpr double kBumpSigma = 0.15;   // m; the bump is 1.5e-5 of its peak at the grid's faces
inline constexpr double kBumpViewWidth = 0.8;  // the orthographic view: ±2.7 σ
inline constexpr double kBumpAmplitude = 1e-4;

struct Bump {
    double amplitude = kBumpAmplitude;
    glm::dvec3 centre{0.0};

    double deltaIndex(const glm::dvec3& x) const {
        const glm::dvec3 r = x - centre;
        return amplitude * std::exp(-glm::dot(r, r) / (kBumpSigma * kBumpSigma));
    }
    // At (x, y) on the image plane (the camera looks down −z, x right, y up).
    double opd(glm::dvec2 p) const {
        const glm::dvec2 rho = p - glm::dvec2(centre);
        return peakOpd() * std::exp(-glm::dot(rho, rho) / (kBumpSigma * kBumpSigma));
    }
    glm::dvec2 deflection(glm::dvec2 p) const {
        return -2.0 / (kBumpSigma * kBumpSigma) * (p - glm::dvec2(centre)) * opd(p);
    }
    double peakOpd() const { return amplitude * kBumpSigma * std::sqrt(std::numbers::pi); }
    double peakDeflection() const { return amplitude * std::sqrt(2.0 * std::numbers::pi) * std::exp(-0.5); }
};

// The grid, a light, and an orthographic camera 2 m up the z axis looking
// at the origin, `kBumpViewWidth` wide.
inline Scene bumpScene(int width, int height, const DiagnosticDesc& diagnostic) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), kBumpCells);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.camera.position = glm::dvec3(0.0, 0.0, 2.0);
    scene.camera.target = glm::dvec3(0.0);
    scene.camera.projection = CameraDesc::Projection::Orthographic;
    scene.camera.widthM = kBumpViewWidth;
    scene.render.width = width;
    scene.render.height = height;
    scene.diagnostic = diagnostic;
    return scene;
}

inline FieldSet sampledBump(const Scene& scene, const Bump& bump) {
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < kBumpCells; ++k)
        for (int j = 0; j < kBumpCells; ++j)
            for (int i = 0; i < kBumpCells; ++i)
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] =
                    static_cast<float>(bump.deltaIndex(fields.grid.cellCentre(i, j, k)));
    fields.indexVersion = 1;
    return fields;
}

// Pixel (i, j)'s point on the orthographic image plane (row 0 at the top), m.
inline glm::dvec2 pixelPoint(const Scene& scene, double i, double j) {
    const double pixel = kBumpViewWidth / scene.render.width;
    return {(i + 0.5 - 0.5 * scene.render.width) * pixel, (0.5 * scene.render.height - j - 0.5) * pixel};
}

}  // namespace eikon::test
