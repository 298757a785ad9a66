// The scene description: plain data, in SI units, after validation.
//
// This is what a scene file (docs/scene-format.md) means once parsed; every
// value here has been range-checked by SceneParser, so consumers may rely on
// the invariants stated beside each field.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/scene/ComputeDevice.h"
#include "bridge/scene/DiagnosticDesc.h"
#include "bridge/scene/ExportDesc.h"
#include "bridge/scene/FloatImage.h"
#include "bridge/scene/MeshObjectDesc.h"
#include "bridge/scene/VolumeDesc.h"

#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon {

using Rgb = glm::dvec3;  // one value per RGB channel

struct GridDesc {
    glm::ivec3 resolution{64, 64, 64};  // cells per axis, each >= 1
    glm::dvec3 boundsMin{-1.0};         // metres; boundsMax > boundsMin on every axis
    glm::dvec3 boundsMax{1.0};
    double smoothingSigmaVoxels = 1.5;  // Gaussian σ of index smoothing in voxels ([Sun08] §4.1: 9³ window, σ = 9/6); 0: none
    int smoothingWindowVoxels = 0;      // odd kernel width; 0: 2·floor(3σ) + 1 (9 for σ = 1.5)
    int supersampling = 4;              // coverage samples per voxel axis ([Sun08] §4.1: 4)
    bool fitVolume = false;             // grid.fit "volume": the bounds are the volume's (io/scene/GridFit.h)

    // The cells and world box this describes.
    GridSpec spec() const { return {resolution, boundsMin, boundsMax}; }
};

// Optical properties of a region: refractive index n > 0, extinction κ ≥ 0
// and scattering σs ≥ 0 per channel in 1/m, with σs ≤ κ.
struct Material {
    double index = 1.0;
    Rgb extinction{0.0};
    Rgb scattering{0.0};
    double anisotropy = 0.0;  // Henyey–Greenstein g of the scattering, in (−1, 1)
};

// Still air over a hot (or cold) ground: T(y) = T_air + (T_ground − T_air)·
// exp(−(y − y0)/H) above the ground height y0 (T_ground below it), turned
// into index by Gladstone–Dale (sim/optics/AirOptics.h, its reference state).
// The thin hot layer over a road in the sun bends grazing rays up: the
// inferior mirage.
struct AirTemperatureProfile {
    double groundHeight = 0.0;         // y0, m
    double groundTemperature = 330.0;  // K, > 0
    double airTemperature = 300.0;     // K, > 0: far above the ground
    double scaleHeight = 0.1;          // H, m, > 0
    double pressure = 101325.0;        // Pa, > 0
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
    enum class Kind { Sphere, Box, Mesh, Water } kind = Kind::Sphere;
    SphereShape sphere;  // valid when kind == Sphere
    BoxShape box;        // valid when kind == Box
    MeshObjectDesc mesh; // valid when kind == Mesh
    WaterDesc water;     // valid when kind == Water
    Material material;
    // sharp: the boundary is exact — rays find where each step crosses it and
    // refract (Snell) and reflect (Fresnel) there, and the inside is the
    // object's index on top of the graded field; smooth: the object is
    // voxelized into the index field and Gaussian-smoothed ([Sun08] §4.1).
    // Every kind is sharp by default. Spheres and boxes are exact shapes; a
    // mesh or water surface is its triangles (sim/SharpMeshSurfaces.h).
    enum class Surface { Sharp, Smooth } surface = Surface::Sharp;
    bool fresnel = true;  // sharp: reflect at the surface by Fresnel; false: transmit only (total internal reflection stays)

    bool isSharp() const { return surface == Surface::Sharp; }
    // A sharp mesh or water object: its surface reaches the tracers as triangles.
    bool hasTriangleSurface() const { return isSharp() && (kind == Kind::Mesh || kind == Kind::Water); }
};

// A brush dragged along a path through the volume ([Sun08] §6.2.1, volume
// painting): a pattern of material added to the fields, scaled to the brush
// radius and turned to follow the path.
struct PaintStroke {
    enum class Brush {
        Soft,   // Gaussian, σ = radius/2
        Smoke,  // the Gaussian modulated by fractal value noise fixed to the brush
    } brush = Brush::Soft;
    enum class Where { Everywhere, InsideObjects, OutsideObjects } where = Where::Everywhere;
    std::vector<glm::dvec3> path;  // metres; one point stamps once, more drag the brush along the polyline
    double radius = 0.05;          // metres, > 0
    // Added on the stroke's centre line: index Δn (any sign; n > 0 is checked
    // after painting), extinction κ and scattering σs in 1/m (σs ≤ κ).
    double index = 0.0;
    Rgb extinction{0.0};
    Rgb scattering{0.0};
    unsigned seed = 1;  // the smoke pattern
};

struct LightDesc {
    enum class Kind { Point, Spot, Directional } kind = Kind::Point;
    glm::dvec3 position{0.0};        // point, spot: metres
    Rgb power{0.0};                  // point: W per channel emitted isotropically; spot: W per channel inside its cone; ≥ 0
    glm::dvec3 direction{0, -1, 0};  // spot: unit axis of the cone; directional: unit vector the light travels along
    double coneAngleDeg = 30.0;      // spot: half-angle of the cone, in (0, 180)
    double falloffDeg = 5.0;         // spot: width of the soft edge inside the cone, in [0, coneAngleDeg]
    Rgb irradiance{0.0};             // directional: W/m² per channel on a plane ⟂ direction, ≥ 0

    friend bool operator==(const LightDesc&, const LightDesc&) = default;
};

// A diffuse (Lambertian) plane that records photon irradiance on a square
// map of `size` metres centred on `point`.
struct ReceiverDesc {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 1, 0};  // unit
    Rgb albedo{0.8};             // each channel in [0, 1]
    double size = 2.0;           // metres, edge of the recorded square, > 0
    int resolution = 256;        // texels per edge, >= 1
    bool bounce = false;         // reflect photons diffusely (power × albedo) instead of stopping them
    // How the map turns photon tallies into irradiance: the 3×3 binomial
    // kernel (less noise, some blur), or each texel's own tally (unbiased).
    enum class Filter { Binomial, None, Adaptive } filter = Filter::Binomial;
};

struct CameraDesc {
    glm::dvec3 position{0, 0, 3};
    glm::dvec3 target{0.0};   // != position
    glm::dvec3 up{0, 1, 0};   // not parallel to target - position
    // Perspective: rays from `position` through the pixels; orthographic:
    // parallel rays along target − position, one from each pixel of a
    // widthM-wide image plane through `position` (height from the image's aspect).
    enum class Projection { Perspective, Orthographic } projection = Projection::Perspective;
    double fovDeg = 40.0;     // perspective: vertical field of view, in (0, 180)
    double widthM = 1.0;      // orthographic: the view's width, m, > 0

    bool orthographic() const { return projection == Projection::Orthographic; }
};

// What a camera ray sees when it leaves the scene.
struct EnvironmentDesc {
    enum class Kind { Uniform, Sky, Hdr } kind = Kind::Uniform;
    Rgb radiance{0.02, 0.025, 0.03};  // uniform: W/(m²·sr)
    // sky: a zenith-to-horizon gradient above a checkerboard ground plane
    Rgb zenith{0.10, 0.16, 0.30};
    Rgb horizon{0.45, 0.50, 0.55};
    Rgb groundA{0.30, 0.30, 0.30};
    Rgb groundB{0.05, 0.05, 0.05};
    double groundHeight = 0.0;   // m
    double checkerSize = 0.1;    // m, > 0
    // hdr: an equirectangular Radiance .hdr image (+y up), scaled
    std::string path;            // resolved against the scene file's folder
    std::shared_ptr<const FloatImage> image;  // the map at `path`, read with the scene
    double intensity = 1.0;      // >= 0
    double rotationDeg = 0.0;    // about +y
};

struct RenderDesc {
    long long photons = 1 << 20;  // >= 1
    int width = 640;              // >= 1
    int height = 480;             // >= 1
    unsigned seed = 1;
    double exposureEv = 0.0;      // exposure compensation in stops
    double stepVoxels = 1.0;      // camera-ray step in media, in voxels, > 0 ([Sun08] §4.5: one voxel)
    int surfaceDepth = 4;         // sharp-surface events that split a camera ray into reflection and refraction, 0..8
    // Camera rays per pixel, 1..1024, through stratified points of the pixel
    // (render/stages/PixelSamples.h), averaged: a box filter over the pixel.
    int samplesPerPixel = 4;
    EnvironmentDesc environment;  // `background` in the file sets a uniform environment's radiance
    bool writeHdr = true;         // also write the linear image as Radiance .hdr
    // Estimate each frame's noise and discretisation error
    // (render/stages/ErrorEstimateStage.h) and warn, once a run, where
    // either exceeds warnError (relative, > 0).
    bool errorEstimate = true;
    double warnError = 0.05;
    // How the image is formed: eikonal (curved rays through the fields, the
    // default) or image space (the raster pipeline's two-interface
    // refraction and light-space caustic maps, [Wyman06] and [Hu07];
    // surfaces in a uniform medium only, bridge/scene/ImageSpaceScope.h).
    enum class Method { Eikonal, ImageSpace } method = Method::Eikonal;
    // What image space does with a scene it cannot show whole: refuse it
    // (none), or draw the surfaces and drop the media, saying so once.
    enum class MethodFallback { None, SurfacesOnly } methodFallback = MethodFallback::None;
    int causticMapTexels = 256;  // image space: texels per edge of each light's caustic map (photons: its square)
    // Where the grid passes (prepare, step structure) run: compute shaders or
    // native loops over the same kernels (render/stages/StageDevice.h).
    ComputeDevice device = ComputeDevice::Auto;
};

// How photons are marched ([Sun08] §4.2–4.4 and §5.3).
struct TracerDesc {
    enum class Integrator { Euler, Leapfrog, Rk4 } integrator = Integrator::Leapfrog;
    enum class StepPolicy { Uniform, Octree } stepPolicy = StepPolicy::Octree;
    double stepVoxels = 0.5;      // uniform: Δs; octree: Δs_min. In voxels, > 0
    // Octree tolerances, as fractions of the field's whole index range (so
    // glass and hot air need no retuning). [Sun08] used absolute ε = 0.005,
    // ε′ = 0.02 (0.01, 0.04 of a glass sphere's range) with an 8-voxel cap; on
    // the glass-sphere caustic that doubled the error of uniform half-voxel
    // steps, while ε = ε′ = 0.002 beats uniform steps with 3.6× fewer
    // (docs/accuracy.md), so the capped tier is off by default.
    double maxStepVoxels = 8.0;   // octree: step cap in nodes whose index varies by ε..ε′, >= stepVoxels
    double epsilon = 0.002;       // octree: relative index variation below which a node counts as uniform, > 0
    double epsilonPrime = 0.002;  // octree: relative variation below which the capped step applies, >= epsilon
    bool renormalize = false;     // rescale |v| to n(x) after every step
    double powerCutoff = 1e-4;    // stop a photon below this fraction of its emitted power, in [0, 1)
    long long maxSteps = 0;       // per photon; 0: four grid crossings at the smallest step
    Rgb dispersion{1.0};          // per-channel scale of δn = n − n_ref (Cauchy-style), each > 0
    bool dispersive() const { return dispersion.r != dispersion.g || dispersion.g != dispersion.b; }
    bool storeFluence = false;    // keep the fluence grid even where nothing scatters
    // How receivers' irradiance is estimated: photon splatting (Monte Carlo,
    // the reference; also for scattering media), or adaptive wavefront
    // tracing by the intensity law ([Ihrke07] §4.2; noise-free).
    enum class Estimator { Photons, Wavefront } estimator = Estimator::Photons;
    struct Wavefront {
        int gridCells = 64;           // cells per edge of a light's emission square at depth 0 (two patches each)
        int maxDepth = 10;            // times a patch may split in four
        double splitTexels = 1.5;     // a patch whose footprint has a longer edge (texels) splits
        double tearTexels = 0.25;     // a patch whose corners disagree splits while larger than this (texels)
        double splitVoxels = 0.5;     // where fluence is stored, a patch whose tube is wider (voxels) splits
        double minPower = 0.01;       // a patch carrying less of a texel's (voxel's) unobstructed power does not split
        long long maxPatches = 1 << 18;  // patches one refinement level holds; beyond, patches stop splitting
        int reflections = 1;          // Fresnel branches followed: reflected at the first, second, … Fresnel event
        double reflectionSplit = 1e-3;  // a branch's patch splits while its corners' reflected power differs by this share of a start patch's
    } wavefront;
    // Light scattered more than once: not followed (single scattering only),
    // or diffused on a lattice ([Bernabei12] §III-C; render/stages/LatticeScattering).
    enum class MultipleScattering { None, Lbm } multipleScattering = MultipleScattering::None;
    struct Lattice {
        int directions = 14;       // links per voxel: 6 ([Bernabei12]'s), 14 (axes and body diagonals) or 18 (axes and face diagonals)
        double tolerance = 1e-3;   // converged below this estimated remaining relative change at the probes, > 0
        int maxIterations = 4000;  // steps per channel and frame, >= 1
    } lattice;
};

// The built-in fluid solver (sim/fluid) and the optics that turn its
// temperature, concentration and dye into n, κ, σs (sim/optics). Defaults
// here are those of air; the parser switches to the liquid defaults
// (docs/scene-format.md, `sim`) when `fluid` is "liquid".
struct SimDesc {
    enum class Fluid { Air, Liquid } fluid = Fluid::Air;
    enum class Boundary { Closed, Open };   // closed: wall, no flow through; open: pressure 0, free outflow
    enum class Mixing { Linear, LorentzLorenz };

    struct Obstacle {
        enum class Kind { Box, Sphere } kind = Kind::Box;
        BoxShape box;        // valid when kind == Box
        SphereShape sphere;  // valid when kind == Sphere
    };
    struct Source {
        enum class Kind { HotPlate, Jet } kind = Kind::HotPlate;
        BoxShape region;                // cells whose centres lie inside are driven
        double temperature = 373.15;    // hot plate: K, > 0, held fixed
        glm::dvec3 velocity{0.0};       // jet: m/s, imposed on the faces inside the region
        double concentration = 1.0;     // jet: fraction of liquid B in [0, 1]
        double dye = 0.0;               // jet: dye concentration, >= 0
    };

    // Where the substeps run (ComputeDevice.h).
    using Device = ComputeDevice;
    Device device = Device::Auto;
    glm::ivec3 resolution{32, 32, 32};  // solver cells per axis, each >= 1
    std::optional<BoxShape> bounds;     // metres; absent: the render grid's bounds
    double frameTime = 1.0 / 30.0;      // s of simulated time per rendered frame, > 0
    int substeps = 1;                   // at least this many substeps per frame, >= 1
    double cfl = 2.0;                   // largest |u|·Δt/h of a substep, > 0 (more substeps are taken)
    int maxSubsteps = 1000;             // a frame that would need more is refused, >= substeps
    glm::dvec3 gravity{0.0, -9.81, 0.0};      // m/s²
    double thermalExpansion = 1.0 / 293.15;   // β in 1/K, >= 0 (ideal gas: 1/T_ambient)
    double concentrationExpansion = 0.0;      // α: relative density excess per unit concentration, >= 0
    double viscosity = 1.5e-5;                // kinematic, m²/s, >= 0
    double thermalDiffusivity = 2.2e-5;       // m²/s, >= 0
    double concentrationDiffusivity = 1.6e-5; // m²/s, >= 0
    double dyeDiffusivity = 0.0;              // m²/s, >= 0
    double pressureTolerance = 1e-6;          // relative max-norm residual of the pressure solve, in (0, 1)
    double vorticityConfinement = 0.0;        // ε of [Fedkiw01] eq. 11, >= 0; 0: off (sim/fluid/VorticityConfinement.h)
    std::array<Boundary, 6> boundaries{};     // x min, x max, y min, y max, z min, z max
    std::vector<Obstacle> obstacles;
    std::vector<Source> sources;
    double ambientTemperature = 293.15;  // K, > 0: initial temperature, and zero buoyancy
    double ambientPressure = 101325.0;   // Pa, > 0

    // Air: Gladstone–Dale, n − 1 = refractivity · (p/p0) · (T0/T).
    double refractivity = 2.93e-4;        // n0 − 1 at T0, p0, > 0
    double referenceTemperature = 273.15; // T0 in K, > 0
    double referencePressure = 101325.0;  // p0 in Pa, > 0
    // Liquid: index of liquid A (concentration 0) and B (concentration 1), mixed by `mixing`.
    double indexA = 1.333;   // water
    double indexB = 1.4418;  // 60 % w/w sucrose syrup
    Mixing mixing = Mixing::Linear;
    // Dye: κ and σs in 1/m per unit dye concentration, σs <= κ per channel.
    Rgb dyeExtinction{0.0};
    Rgb dyeScattering{0.0};
};

struct Scene {
    std::string sourcePath;  // file the scene came from, for messages
    GridDesc grid;
    Material medium;         // background medium; medium.index is n_ref
    std::optional<AirTemperatureProfile> airProfile;  // replaces the medium's index when present
    std::vector<ObjectDesc> objects;
    std::vector<PaintStroke> paint;  // applied after the objects, in order
    std::vector<LightDesc> lights;
    std::vector<ReceiverDesc> receivers;
    CameraDesc camera;
    RenderDesc render;
    TracerDesc tracer;
    std::optional<SimDesc> sim;  // present when the scene runs the built-in fluid solver
    double frameTime = 1.0 / 30.0;  // s of scene time per frame for deformers, > 0; sim.frame_time when there is a sim
    std::optional<VolumeDesc> volume;  // present when the scene imports an OpenVDB volume (not with sim)
    ExportDesc exports;
    std::optional<DiagnosticDesc> diagnostic;  // present: the picture is this instrument's, not the view's
};

}  // namespace eikon
