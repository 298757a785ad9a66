// The scene description: plain data, in SI units, after validation.
//
// This is what a scene file (docs/scene-format.md) means once parsed; every
// value here has been range-checked by SceneParser, so consumers may rely on
// the invariants stated beside each field.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace eikon {

using Rgb = glm::dvec3;  // one value per RGB channel

struct GridDesc {
    glm::ivec3 resolution{64, 64, 64};  // cells per axis, each >= 1
    glm::dvec3 boundsMin{-1.0};         // metres; boundsMax > boundsMin on every axis
    glm::dvec3 boundsMax{1.0};
    double smoothingSigmaVoxels = 1.5;  // Gaussian σ of index smoothing in voxels (Sun et al. 2008 §4.1: 9³ window, σ = 9/6)
    int supersampling = 4;              // coverage samples per voxel axis (Sun et al. 2008 §4.1: 4)
};

// Optical properties of a region: refractive index n > 0, extinction κ ≥ 0
// and scattering σs ≥ 0 per channel in 1/m, with σs ≤ κ.
struct Material {
    double index = 1.0;
    Rgb extinction{0.0};
    Rgb scattering{0.0};
};

struct SphereShape {
    glm::dvec3 center{0.0};
    double radius = 1.0;  // > 0
};

struct BoxShape {
    glm::dvec3 min{-0.5};
    glm::dvec3 max{0.5};  // > min on every axis
};

struct ObjectDesc {
    enum class Kind { Sphere, Box } kind = Kind::Sphere;
    SphereShape sphere;  // valid when kind == Sphere
    BoxShape box;        // valid when kind == Box
    Material material;
};

struct LightDesc {
    enum class Kind { Point, Directional } kind = Kind::Point;
    glm::dvec3 position{0.0};    // point: metres
    Rgb power{0.0};              // point: W per channel, ≥ 0, emitted isotropically
    glm::dvec3 direction{0, -1, 0};  // directional: unit vector the light travels along
    Rgb irradiance{0.0};         // directional: W/m² per channel on a plane ⟂ direction, ≥ 0
};

// A diffuse (Lambertian) plane that records photon irradiance on a square
// map of `size` metres centred on `point`.
struct ReceiverDesc {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 1, 0};  // unit
    Rgb albedo{0.8};             // each channel in [0, 1]
    double size = 2.0;           // metres, edge of the recorded square, > 0
    int resolution = 256;        // texels per edge, >= 1
};

struct CameraDesc {
    glm::dvec3 position{0, 0, 3};
    glm::dvec3 target{0.0};   // != position
    glm::dvec3 up{0, 1, 0};   // not parallel to target - position
    double fovDeg = 40.0;     // vertical field of view, in (0, 180)
};

struct RenderDesc {
    long long photons = 1 << 20;  // >= 1
    int width = 640;              // >= 1
    int height = 480;             // >= 1
    unsigned seed = 1;
    double exposureEv = 0.0;      // exposure compensation in stops
    double stepVoxels = 0.5;      // photon step Δs in voxels, > 0
    Rgb background{0.02, 0.025, 0.03};  // radiance of the environment, W/(m²·sr)
};

struct Scene {
    std::string sourcePath;  // file the scene came from, for messages
    GridDesc grid;
    Material medium;         // background medium; medium.index is n_ref
    std::vector<ObjectDesc> objects;
    std::vector<LightDesc> lights;
    std::vector<ReceiverDesc> receivers;
    CameraDesc camera;
    RenderDesc render;
};

}  // namespace eikon
