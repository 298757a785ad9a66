// Scene objects whose shape is a triangle mesh that may change with time: a
// mesh file with an optional deformer, or a water body whose surface obeys a
// damped wave equation (docs/scene-format.md, "mesh" and "water").
#pragma once

#include "bridge/scene/ComputeDevice.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace eikon {

// Scale, then rotate about x, then y, then z (degrees), then translate.
struct Placement {
    glm::dvec3 translate{0.0};  // m
    glm::dvec3 rotateDeg{0.0};
    double scale = 1.0;         // > 0
};

// A pose at a time; between keys poses are interpolated linearly (each of
// translate, rotate_deg, scale), before the first and after the last they
// hold. Times strictly increase along a list.
struct PoseKey {
    double time = 0.0;  // s
    Placement pose;
};

struct AmountKey {
    double time = 0.0;  // s
    double value = 0.0;
};

// A group of vertices (those whose placed rest position lies in the region)
// moved rigidly by keyed poses about their centroid at rest.
struct HandleDesc {
    glm::dvec3 regionMin{0.0};
    glm::dvec3 regionMax{0.0};
    std::vector<PoseKey> keys;
};

struct DeformerDesc {
    enum class Kind { None, Rigid, Twist, Bend, Arap } kind = Kind::None;
    std::vector<PoseKey> keys;       // rigid: the object's pose over time (applied after placement)
    glm::dvec3 origin{0.0};          // twist, bend: a point on the axis, m
    glm::dvec3 axis{0, 1, 0};        // twist, bend: unit axis
    glm::dvec3 toward{1, 0, 0};      // bend: unit direction the axis curves toward, ⟂ axis
    std::vector<AmountKey> amount;   // twist: rotation, degrees per metre along the axis; bend: curvature, degrees per metre
    std::vector<HandleDesc> handles; // arap: at least one
    int iterations = 8;              // arap: local/global iterations per frame, >= 1
};

struct MeshObjectDesc {
    std::string path;  // resolved against the scene file's folder
    Placement placement;
    DeformerDesc deformer;
};

// A wave source: a Gaussian dip of the surface dropped at one time, or a
// Gaussian pressure moving at constant velocity between two times.
struct WaterDrop {
    double time = 0.0;          // s
    glm::dvec2 position{0.0};   // (x, z), m
    double amplitude = 0.005;   // m, depth of the dip (> 0 lowers the surface)
    double radius = 0.02;       // m, Gaussian σ, > 0
};

struct WaterDisturbance {
    glm::dvec2 start{0.0};      // (x, z) at time `from`, m
    glm::dvec2 velocity{0.0};   // m/s
    double from = 0.0;          // s
    double until = 1e30;        // s, > from
    double strength = 1.0;      // m/s², peak downward acceleration of the surface
    double radius = 0.02;       // m, Gaussian σ, > 0
};

struct WaterDesc {
    glm::dvec3 basinMin{-0.5, -0.5, -0.5};  // x, z: the pool's walls; y: the bottom of the water body
    glm::dvec3 basinMax{0.5, 0.0, 0.5};     // y: the rest level of the surface
    glm::ivec2 cells{128, 128};             // height samples along x and z, each >= 3
    double waveSpeed = 0.3;                 // c, m/s, > 0
    double damping = 0.2;                   // γ, 1/s, >= 0
    // Initial swell: `waves` cosines of one wavelength in random directions
    // and phases, summed and scaled to this RMS height (0: a still surface).
    double swellAmplitude = 0.0;            // m, >= 0
    double swellWavelength = 0.1;           // m, > 0
    int swellWaves = 8;                     // >= 1
    unsigned seed = 1;
    std::vector<WaterDrop> drops;
    std::vector<WaterDisturbance> disturbances;
    // Where the wave equation, the surface's triangles and its coverage are
    // computed each frame (sim/gpu/GpuWaterBody.h: on the GPU when the water
    // is the scene's only object, sharp, and no field is exported).
    ComputeDevice device = ComputeDevice::Auto;

    // The triangles of its body (sim/deform/WaterSurface::mesh): two per
    // cell of the surface, and per cell of the boundary ring a wall's two
    // and the bottom's one.
    int triangleCount() const { return 2 * (cells.x - 1) * (cells.y - 1) + 6 * ((cells.x - 1) + (cells.y - 1)); }
};

}  // namespace eikon
