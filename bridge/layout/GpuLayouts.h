// C++ mirrors of every GPU buffer layout eikon uses. These structs are the
// source of truth (after [Filament]'s UibStructs.h): the GLSL blocks in
// shaders/ declare the same members in the same order, and the
// static_asserts below pin sizes and offsets to the std140/std430 rules so a
// reordering breaks the build, not the picture. Only vec4-sized members are
// used, which packs identically under std140 and std430.
//
// The binding points, texture and image units and power-tally indices are
// listed once each, below, as X-macro lists of (name, value). A list expands
// here into its C++ enum and, in the embedded shader set
// (cmake/EmbedShaders.cmake), into the table the shader library declares
// ahead of every program as `const int NAME = VALUE;`, so GLSL writes
// layout(binding = kEmitters) and never a number.
// tests/integration/test_gpu_contract.cpp reads every block, sampler and
// image of every production program back from OpenGL and checks it against
// these names and the structs' sizes.
#pragma once

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>

// (Comments inside the lists are /* */: a // comment would swallow the line
// continuation.)

// Limits of a scene that fixed-size blocks follow (the scene parser refuses
// more). Uniform blocks, not storage buffers, hold the receivers and the
// sharp surfaces: every pass reads them, and a CPU rasterizer broadcasts a
// uniform block's values and gathers them for all the lanes of a SIMD group
// at once, where it loads a storage buffer one lane at a time.
#define EIKON_LAYOUT_LIMITS(X)                                                                                  \
    X(kMaxSharpObjects, 32) /* sharp surfaces: a ray keeps one bit per surface it is inside; SharpSurfaces' size */ \
    X(kMaxReceivers, 128)   /* receivers: the Receivers block's size (12 KiB, under GL's 16 KiB minimum) */

// Binding points shared by the C++ stages and the shaders; each names the
// GLSL block it binds, less the k.
#define EIKON_LAYOUT_BINDINGS(X)                                                                                                \
    X(kGridBlock, 0)            /* uniform GridBlock (GpuGrid) */                                                               \
    X(kCameraBlock, 1)          /* uniform CameraBlock (GpuCamera) */                                                           \
    X(kWaterBodies, 2)          /* uniform WaterBodies: per water body its basin and node grid (image space, render/stages/WaterHeightFields) */ \
    X(kEmitters, 2)             /* buffer Emitters { GpuEmitter emitters[]; } */                                                \
    X(kReceivers, 3)            /* uniform Receivers { GpuReceiver receivers[kMaxReceivers]; } */                               \
    X(kReceiverMaps, 4)         /* buffer ReceiverMaps { float irradiance[]; }: RGB per texel, W/m² */                          \
    X(kFluence, 5)              /* buffer Fluence { float fluence[]; }: RGB per cell, W/m², track-length estimator, smoothed */ \
    X(kPhotonStats, 6)          /* buffer PhotonStats (GpuPhotonStats) */                                                       \
    X(kHdrImage, 7)             /* buffer HdrImage { vec4 radiance[]; } */                                                      \
    X(kLdrImage, 8)             /* buffer LdrImage { uint rgba8[]; } */                                                         \
    X(kPhotonPaths, 9)          /* buffer PhotonPaths { vec4 vertices[]; }: optional recording for tests and export */          \
    X(kImageSpaceSurfaces, 9)   /* uniform ImageSpaceSurfaces { vec4 extinction[kMaxSharpObjects]; }: per sharp surface κ rgb, image space */ \
    X(kPhotonEnds, 10)          /* buffer PhotonEnds { vec4 ends[]; }: per recorded photon (end, fate), (power, receiver) */    \
    X(kSurfacePixels, 10)       /* buffer SurfacePixels { uint pixels[]; }: image space, the pixels that see a surface */    \
    X(kReceiverTallies, 11)     /* buffer ReceiverTallies { uint units[]; }: per texel and channel a 64-bit fixed-point sum */  \
    X(kFluenceDirection, 12)    /* buffer FluenceDirection { float direction[]; }: xyz per cell, power-weighted */              \
    X(kSurfacePixelCount, 12)   /* buffer SurfacePixelCount { uvec4 }: work groups (x, 1, 1) for them, and their count */ \
    X(kRawFluence, 13)          /* buffer RawFluence: the light pass's unsmoothed fluence, RGB per cell (float, or 64-bit units) */ \
    X(kRawFluenceDirection, 14) /* buffer RawFluenceDirection: and its unsmoothed direction sums */                             \
    X(kViewExit, 15)            /* buffer ViewExit { vec4 exit[]; }: per pixel, direction leaving the scene, w: how (tests) */  \
    X(kDiagnosticRays, 15)      /* buffer DiagnosticRays { vec4 rays[]; }: per ray (deflection on the image axes in rad, OPD in m, how it ended) */ \
    X(kDiagnosticLanding, 16)   /* buffer DiagnosticLanding { vec4 landing[]; }: shadowgraph, BOS: where the rays land behind the volume (diagnostic_rays.comp) */ \
    X(kDiagnosticReference, 17) /* buffer DiagnosticReference { uint rgba8[]; }: BOS: the background without the medium */ \
    X(kDiagnosticScreen, 18)    /* buffer DiagnosticScreen { uint tallies[]; }: shadowgraph: per pixel and channel a 64-bit fixed-point sum */ \
    X(kPhotonPathPower, 16)     /* buffer PhotonPathPower { vec4 power[]; }: RGB power at each recorded vertex */          \
    X(kSharpSurfaces, 17)       /* uniform SharpSurfaces { GpuSharpSurface surfaces[kMaxSharpObjects]; } */                     \
    X(kSurfaceNodes, 18)        /* buffer SurfaceNodes { vec4 nodes[]; }: the sharp meshes' trees (FieldSet.h) */              \
    X(kSurfaceTriangles, 19)    /* buffer SurfaceTriangles { vec4 triangles[]; }: their corners and normals (FieldSet.h) */ \
    X(kWavefrontPatches, 20)    /* buffer Patches { GpuWavefrontPatch patches[]; }: one level of the wavefront, read */    \
    X(kWavefrontChildren, 21)   /* buffer Children { GpuWavefrontPatch children[]; }: the next level, written */           \
    X(kWavefrontCounters, 22)   /* buffer Counters (GpuWavefrontCounters) */                                   \
    X(kCausticVertices, 20)     /* buffer CausticVertices { vec4 v[]; }: image space, per light texel and sheet, its photon's landing */ \
    X(kCausticTriangles, 21)    /* buffer CausticTriangles { vec4 t[]; }: image space, the caustic triangles to draw */  \
    X(kCausticDraw, 22)         /* buffer CausticDraw { uvec4 }: image space, the caustic triangles' indirect draw */   \
    X(kCausticDeposits, 23)     /* buffer CausticDeposits { vec4 d[]; }: image space, the small caustic triangles and splats added by compute */ \
    X(kCausticDepositCount, 24) /* buffer CausticDepositCount { uvec4 }: image space, their work groups (x, 1, 1) and count (w) */ \
    X(kCausticCellGroups, 25)   /* buffer CausticCellGroups { uvec4 }: image space, the cell pass's work groups (x, y, sheets) */ \
    X(kSuspendedIn, 23)         /* buffer SuspendedIn { GpuSuspendedPhoton[] }: photons a dispatch resumes */      \
    X(kSuspendedOut, 24)        /* buffer SuspendedOut { GpuSuspendedPhoton[] }: photons it suspends */           \
    X(kSuspendedCount, 25)      /* buffer SuspendedCount (GpuSuspendedCount) */                                           \
    X(kGlowCells, 26)           /* buffer GlowCells { GpuGlowCell cells[]; }: a glowing volume's emitting cells */ \
    X(kWaterNodeGrids, 26)      /* buffer WaterNodeGrids { vec4 nodes[]; }: the water bodies' node grids, written (render/stages/WaterHeightFields) */ \
    X(kWaterSlabs, 27)          /* buffer WaterSlabs { uvec4 slabs[]; }: per water body its nodes' lowest and highest y and steepest slope, ordered bits */ \
    X(kLatticeIn, 27)           /* buffer LatticeIn { float density[]; }: one channel's link densities, W, read */ \
    X(kLatticeOut, 28)          /* buffer LatticeOut { float density[]; }: the same after one step, written */ \
    X(kLatticeProbes, 28)       /* buffer LatticeProbes { float fluence[]; }: the lattice's fluence at its probes (probe pass) */ \
    X(kLatticeTallies, 28)      /* buffer LatticeTallies { vec4 tallies[]; }: per work group, the lattice's ledger (result pass) */ \
    X(kLatticeSurvey, 28)       /* buffer LatticeSurvey { GpuLatticeSurvey }: channels that differ, voxels past the depth limit */ \
    X(kRawScattered, 29)        /* buffer RawScattered { float scattered[]; }: RGB per cell, W the photons lost to scattering */ \
    X(kMultipleFluence, 30)     /* buffer MultipleFluence { float fluence[]; }: RGB per cell, W/m², light scattered ≥ once */ \
    X(kScatteredPower, 31)      /* buffer ScatteredPower { float scattered[]; }: RGB per cell, W, from the wavefront's fixed-point tallies */ \
    X(kLatticeInterfaces, 31)   /* buffer LatticeInterfaces { uvec4 interfaces[]; }: per cell the lattice's links across sharp surfaces */ \
    X(kLatticeBirth, 13)        /* buffer LatticeBirth { float share[]; }: per link slot and cell, the share of the source born on it */ \
    X(kLatticePhase, 14)        /* buffer LatticePhase { float phase_matrix[]; }: the link-to-link phase matrix of later scatterings over g (common/lattice_phase.glsl) */

// Texture (sampler) units. Unit 0 carries δn into the passes that derive
// from it (smoothing, gradient, min/max pyramid) and later the pyramid into
// the octree labels, which read no δn.
#define EIKON_LAYOUT_TEXTURE_UNITS(X)                                                                              \
    X(kIndexTexture, 0)       /* r32f δn, raw or part-smoothed */                                                  \
    X(kPyramidTexture, 0)     /* rgba32f (min δn, max δn, min κ, max κ) per octree level (octree_label) */         \
    X(kGradientTexture, 1)    /* rgba32f (∇n, δn) */                                                               \
    X(kExtinctionTexture, 2)  /* rgba32f (κ rgb, 0) */                                                             \
    X(kScatteringTexture, 3)  /* rgba32f (σs rgb, 0) */                                                            \
    X(kStepTexture, 4)        /* rgba32f (octree level, step cap in m, 1 if the node is empty of extinction, 0) */ \
    X(kEnvironmentTexture, 5) /* rgba32f equirectangular environment */                                            \
    X(kAnisotropyTexture, 6)  /* r32f Henyey–Greenstein g */                                                       \
    X(kEmissionTexture, 7)    /* rgba32f (ε rgb in W/(m³·sr), 0) */                                                 \
    X(kNearLayerTexture, 8)   /* rgba32f (octahedral normal, distance, surface + 1): the nearest surfaces a viewpoint sees */ \
    X(kFarLayerTexture, 9)    /* the same, the next surfaces behind them (image space, render/stages/SurfaceLayers) */ \
    X(kCausticAtlasTexture, 10) /* rgba32f W per receiver texel, the receivers' maps stacked (image space, render/stages/CausticPolygons) */ \
    X(kReceiverMapTexture, 11)  /* rgb32f buffer texture of the ReceiverMaps buffer: the irradiance a view reads */     \
    X(kCausticVertexTexture, 12) /* rgba32f buffer texture of the CausticVertices buffer: the photon landings the cells read */ \
    X(kSurfaceTriangleTexture, 13) /* rgba32f buffer texture of a SurfaceTriangles buffer: the corners the surface layers draw */ \
    X(kSurfaceNodeTexture, 14)  /* rgba32f buffer texture of the SurfaceNodes buffer: image space reads the meshes' root boxes */ \
    X(kReceiverTallyTexture, 15) /* rg32ui buffer texture of the ReceiverTallies buffer: (low, high) words, the filter reads */ \
    X(kHdrImageTexture, 16)     /* rgba32f buffer texture of an HdrImage buffer: the radiance the tone map reads */ \
    X(kWaterNodeTexture, 17)    /* rgba32f buffer texture of the WaterNodeGrids buffer: image space walks the water's height fields */ \
    X(kBackgroundPatternTexture, 18) /* rgba32f linear RGB of BOS's background image (common/bos_background.glsl) */

// Image units of the passes that write textures; each program binds its own.
#define EIKON_LAYOUT_IMAGE_UNITS(X)                                                              \
    X(kSmoothedIndexImage, 0) /* r32f: one axis of the Gaussian of δn, written (smooth_index) */ \
    X(kGradientImage, 0)      /* rgba32f (∇n, δn), written (prepare_gradient) */                 \
    X(kFinerLevelImage, 0)    /* rgba32f pyramid level k − 1, read (octree_minmax) */            \
    X(kPyramidLevelImage, 1)  /* rgba32f pyramid level k, written (octree_minmax) */             \
    X(kStepImage, 0)          /* rgba32f step structure, written (octree_label) */

// Energy balance tallies of a photon pass (GpuPhotonStats::power). Every
// emitted photon ends in exactly one of escaped, received, cut off, blocked
// (in this order: GpuPhotonStats::photons counts them so); absorbed collects
// what extinction took along the way, so
//   emitted = absorbed + escaped + received + cutOff + blocked.
// kReflected is power receivers send back out (bounce), or, in the wavefront
// pass, power a sharp surface reflects into a followed branch: a source, like
// kEmitted; so is kRouletteGain, what Russian roulette adds to the photons it
// lets go on (it takes as much from those it cuts off, on average).
// kUnfollowed, a sink, is what the wavefront pass does not follow: the
// Fresnel reflections at sharp surfaces beyond the branches it traces.
#define EIKON_LAYOUT_POWER_TALLIES(X) \
    X(kEmitted, 0)                    \
    X(kAbsorbed, 1)                   \
    X(kEscaped, 2)                    \
    X(kReceived, 3)                   \
    X(kCutOff, 4)                     \
    X(kBlocked, 5)                    \
    X(kReflected, 6)                  \
    X(kRouletteGain, 7)               \
    X(kUnfollowed, 8)                 \
    X(kTallyCount, 9)

// Kinds of sharp surface (GpuSharpSurface::shapeA.w): a sphere, a box, or a
// mesh or water surface given by its triangles.
#define EIKON_LAYOUT_SHARP_SURFACE_KINDS(X) \
    X(kSharpSphere, 0)                      \
    X(kSharpBox, 1)                         \
    X(kSharpTriangles, 2)

// Camera projections (GpuCamera::image.w): a pinhole, or parallel rays
// (the diagnostics' parallel light).
#define EIKON_LAYOUT_PROJECTIONS(X) \
    X(kPerspectiveProjection, 0)    \
    X(kOrthographicProjection, 1)

// Binding points of the fluid solver's and the water surface's GPU passes
// (sim/gpu, shaders/sim).
// Every pass binds what it reads right before its dispatch, so these may
// share numbers with the renderer's bindings. Fields are float32 in
// GridField order (x fastest); the Krylov vectors and reduction results are
// float64 (docs/architecture.md, "The fluid solver on the GPU").
#define EIKON_LAYOUT_SOLVER_BINDINGS(X)                                                                        \
    X(kSolverVelocityX, 0)   /* buffer VelocityX { float u[]; }: faces normal to x, m/s */                     \
    X(kSolverVelocityY, 1)   /* buffer VelocityY { float v[]; } */                                             \
    X(kSolverVelocityZ, 2)   /* buffer VelocityZ { float w[]; } */                                             \
    X(kSolverField, 3)       /* buffer Field { float values[]; }: the field a pass updates in place */         \
    X(kSolverSource, 4)      /* buffer Source { float values[]; }: a pass's input field, read */               \
    X(kSolverTarget, 5)      /* buffer Target { float values[]; }: a pass's output field, written */           \
    X(kSolverBoundsLow, 6)   /* buffer BoundsLow { float low[]; }: the MacCormack limiter's lower bounds */    \
    X(kSolverBoundsHigh, 7)  /* buffer BoundsHigh { float high[]; }: and its upper bounds */                   \
    X(kSolverCells, 8)       /* buffer Cells { uint flags[]; }: per sample, the solver's flags for a pass */   \
    X(kSolverVectorX, 9)     /* buffer VectorX { double x[]; }: a linear solve's unknowns */                   \
    X(kSolverVectorB, 10)    /* buffer VectorB { double b[]; }: its right-hand side */                         \
    X(kSolverVectorR, 11)    /* buffer VectorR { double r[]; }: its residual */                                \
    X(kSolverVectorP, 12)    /* buffer VectorP { double p[]; }: CG's search direction */                       \
    X(kSolverVectorQ, 13)    /* buffer VectorQ { double q[]; }: A·p, or the preconditioned residual */         \
    X(kSolverPartials, 14)   /* buffer Partials { double partials[]; }: per work group, a reduction's part */  \
    X(kSolverResults, 15)    /* buffer Results { double results[]; }: reductions and solver scalars */         \
    X(kSolverBackward, 16)   /* buffer Backward { vec4 ends[]; }: per cell and wall face, its characteristic over −Δt */ \
    X(kSolverForward, 17)    /* buffer Forward { vec4 ends[]; }: and over +Δt, in cells */                     \
    X(kSolverCoarse, 18)     /* buffer Coarse { float values[]; }: multigrid, the coarser level's vector */    \
    X(kSolverFine, 19)       /* buffer Fine { float values[]; }: multigrid, the finer level's vector */        \
    X(kSolverSourceCells, 20) /* buffer Held { uvec2 held[]; }: (sample, float bits) of each sample a source holds */ \
    X(kSolverVorticity, 16)   /* buffer Vorticity { vec4 omega[]; }: per cell, (ω, |ω|); shares 16 with kSolverBackward */ \
    X(kOpticsTemperature, 21) /* buffer OpticsTemperature { float theta[]; }: T − T_amb on the solver grid, read */ \
    X(kOpticsConcentration, 22) /* buffer OpticsConcentration { float concentration[]; }: on the solver grid */ \
    X(kOpticsDye, 23)         /* buffer OpticsDye { float dye[]; }: on the solver grid */                         \
    X(kOpticsDeltaIndex, 24)  /* buffer OpticsDeltaIndex { float delta_index[]; }: δn on the render grid, written */ \
    X(kOpticsExtinction, 25)  /* buffer OpticsExtinction { float extinction[]; }: κ RGB per render cell, written */ \
    X(kOpticsScattering, 26)  /* buffer OpticsScattering { float scattering[]; }: σs RGB per render cell, written */ \
    X(kOpticsAnisotropy, 27)  /* buffer OpticsAnisotropy { float anisotropy[]; }: g per render cell, written */       \
    X(kWaterHeight, 28)       /* buffer WaterHeight { double height[]; }: a water surface's h^n per node, m */        \
    X(kWaterNextHeight, 29)   /* buffer WaterNextHeight { double next_height[]; }: h^{n+1}, written */              \
    X(kWaterVelocity, 30)     /* buffer WaterVelocity { double velocity[]; }: v^{n−½} per node, m/s */             \
    X(kWaterDrop, 31)         /* buffer WaterDrop { double dip[]; }: a drop's depth per node, m */                  \
    X(kWaterVertices, 32)     /* buffer WaterVertices { dvec4 vertices[]; }: (x, y at rest, z, height node or −1) */ \
    X(kWaterTriangles, 33)    /* buffer WaterTriangles { ivec4 triangles[]; }: the water mesh's corners */         \
    X(kWaterSlots, 34)        /* buffer WaterSlots { int triangle_of_slot[]; }: the tree's leaf order */            \
    X(kWaterCornerStart, 35)  /* buffer WaterCornerStart { int corner_start[]; }: per vertex, its first triangle */ \
    X(kWaterCorners, 36)      /* buffer WaterCorners { int corner_triangles[]; }: the triangles at each vertex */   \
    X(kWaterFaceNormals, 37)  /* buffer WaterFaceNormals { dvec4 face_normal[]; }: per triangle, unit */            \
    X(kWaterFaceAngles, 38)   /* buffer WaterFaceAngles { dvec4 face_angles[]; }: per triangle, at its corners */   \
    X(kWaterNodes, 39)        /* buffer WaterNodes { ivec4 tree_nodes[]; }: (slot, count, first, second) */         \
    X(kWaterLevelNodes, 40)   /* buffer WaterLevelNodes { int level_nodes[]; }: the tree's nodes, deepest first */  \
    X(kWaterSurfaceNodes, 41) /* buffer WaterSurfaceNodes { vec4 nodes[]; }: FieldSet's node layout, written */     \
    X(kWaterSurfaceTriangles, 42) /* buffer WaterSurfaceTriangles { vec4 triangles[]; }: FieldSet's layout, written */ \
    X(kWaterBaseExtinction, 43) /* buffer WaterBaseExtinction { float base_extinction[]; }: κ RGB under the water */ \
    X(kWaterBaseScattering, 44) /* buffer WaterBaseScattering { float base_scattering[]; }: σs RGB under it */      \
    X(kWaterBaseAnisotropy, 45) /* buffer WaterBaseAnisotropy { float base_anisotropy[]; }: g under it */

// Every list above: the constants each shader program is given.
#define EIKON_LAYOUT_SHADER_CONSTANTS(X) \
    EIKON_LAYOUT_LIMITS(X)               \
    EIKON_LAYOUT_BINDINGS(X)             \
    EIKON_LAYOUT_TEXTURE_UNITS(X)        \
    EIKON_LAYOUT_IMAGE_UNITS(X)          \
    EIKON_LAYOUT_POWER_TALLIES(X)        \
    EIKON_LAYOUT_SHARP_SURFACE_KINDS(X)  \
    EIKON_LAYOUT_PROJECTIONS(X)          \
    EIKON_LAYOUT_SOLVER_BINDINGS(X)

namespace eikon::layout {

#define EIKON_LAYOUT_ENUMERATOR(name, value) name = value,
enum Limit : int { EIKON_LAYOUT_LIMITS(EIKON_LAYOUT_ENUMERATOR) };
enum Binding : unsigned { EIKON_LAYOUT_BINDINGS(EIKON_LAYOUT_ENUMERATOR) };
enum TextureUnit : unsigned { EIKON_LAYOUT_TEXTURE_UNITS(EIKON_LAYOUT_ENUMERATOR) };
enum ImageUnit : unsigned { EIKON_LAYOUT_IMAGE_UNITS(EIKON_LAYOUT_ENUMERATOR) };
enum PowerTally : unsigned { EIKON_LAYOUT_POWER_TALLIES(EIKON_LAYOUT_ENUMERATOR) };
enum SharpSurfaceKind : int { EIKON_LAYOUT_SHARP_SURFACE_KINDS(EIKON_LAYOUT_ENUMERATOR) };
enum Projection : unsigned { EIKON_LAYOUT_PROJECTIONS(EIKON_LAYOUT_ENUMERATOR) };
enum SolverBinding : unsigned { EIKON_LAYOUT_SOLVER_BINDINGS(EIKON_LAYOUT_ENUMERATOR) };
#undef EIKON_LAYOUT_ENUMERATOR
static_assert(kTallyCount == kUnfollowed + 1, "kTallyCount counts the tallies");

// uniform GridBlock (std140): the world box of the field grid.
struct GpuGrid {
    glm::vec4 boundsMin;   // xyz metres; w = n_ref
    glm::vec4 boundsMax;   // xyz metres; w unused
    glm::vec4 voxelSize;   // xyz metres; w = voxel volume in m³
    glm::ivec4 resolution; // xyz cells; w unused
};
static_assert(sizeof(GpuGrid) == 64);
static_assert(offsetof(GpuGrid, resolution) == 48);

// One light's emission, prepared on the CPU so that the photons of all lights
// carry exactly the power each light sends toward the traced region.
struct GpuEmitter {
    glm::vec4 origin;       // point, spot: position; directional: centre of the emitting disk. w: kind (0 cone, 1 disk, 2 glowing volume)
    glm::vec4 axis;         // unit central direction. w: cone: versine 1 − cos of its half-angle (2: the sphere); disk: radius (m)
    glm::vec4 tangent;      // unit, ⟂ axis
    glm::vec4 bitangent;    // unit, ⟂ axis and tangent
    glm::vec4 photonPower;  // rgb W carried by each photon where the spot profile is 1 (glowing volume: × its cell's colour); w unused
    glm::vec4 spot;         // xyz: unit spot axis; w: versine 1 − cos of the spot's outer half-angle (−1: no profile)
    glm::vec4 spotEdge;     // x: versine of the spot's inner half-angle (full intensity inside)
    glm::uvec4 photons;     // x: first photon index, y: photon count, z: strata along u1, w: strata along u2
};
static_assert(sizeof(GpuEmitter) == 128);
static_assert(offsetof(GpuEmitter, photons) == 112);

// An opaque diffuse square receiver and where its map lives in ReceiverMaps.
struct GpuReceiver {
    glm::vec4 origin;   // centre on the plane; w: edge size (m)
    glm::vec4 normal;   // unit, lit side; w: texel area (m²)
    glm::vec4 axisU;    // unit tangent; w unused
    glm::vec4 axisV;    // unit tangent; w unused
    glm::vec4 albedo;   // rgb in [0,1]; w unused
    glm::uvec4 map;     // x: first texel in ReceiverMaps, y: texels per edge, z: 1 if photons bounce
};
static_assert(sizeof(GpuReceiver) == 96);
static_assert(offsetof(GpuReceiver, map) == 80);

// Energy balance and error figures of one photon pass, accumulated with
// atomics (the tallies: PowerTally above).
// Powers are tallied in 64-bit fixed point (two 32-bit words with carry) in
// units of the largest per-photon power / 2^24 per channel: float atomics
// adding a million equal values drift by a percent, these stay exact to the
// per-photon rounding and are independent of summation order.
constexpr double kPowerUnitsPerPhoton = 16777216.0;  // 2^24
// The wavefront pass tallies in units of the brightest light's power / 2^50.
constexpr double kPowerUnitsPerWavefront = 1125899906842624.0;  // 2^50

struct GpuPhotonStats {
    std::uint32_t power[kTallyCount][3][2];  // [tally][channel][low, high word]
    glm::uvec4 photons;   // photon counts: x escaped, y received, z cut off, w blocked
    glm::uvec4 steps;     // x: low 32 bits of the step count, y: high bits; z: max |v|−n invariant error (float bits)
    glm::uvec4 deposits;  // x: low 32 bits of the voxel deposits, y: high bits
    glm::uvec4 invariant; // x low, y high word: Σ over steps of the relative invariant error in 2^-32 units
    glm::uvec4 surfaces;  // events at sharp surfaces: x reflected (Fresnel or total internal reflection), y transmitted
};
// GLSL declares every member as a scalar array (uint/float), so std430 packs
// them with 4-byte alignment, as GLM's unaligned vectors do here.
static_assert(alignof(glm::uvec4) == 4);
static_assert(sizeof(GpuPhotonStats) == 296);
static_assert(offsetof(GpuPhotonStats, photons) == 216);
static_assert(offsetof(GpuPhotonStats, steps) == 232);
static_assert(offsetof(GpuPhotonStats, deposits) == 248);
static_assert(offsetof(GpuPhotonStats, invariant) == 264);
static_assert(offsetof(GpuPhotonStats, surfaces) == 280);

// One ray of the wavefront pass (shaders/wavefront_trace.comp), traced from
// its point of the light's emission square to where it ends.
struct GpuWavefrontCorner {
    glm::vec4 ends;      // xy: coordinates in its face of the emission domain, [0, 1]²; zw: receiver map coordinates
                         // where received, or where it crossed the receiver's plane past the square
    glm::vec4 power;     // rgb: power arriving, per unit of the light's power density there; w: history (uint bits)
    glm::vec4 absorbed;  // rgb: power absorbed on the way, same unit; w: fate | (receiver + 1) << 4 (uint bits)
    glm::vec4 source;    // rgb: power the ray starts its wavefront with: emitted, or reflected into its branch
    glm::vec4 exit;      // xyz: the last point in the grid the ray reached; w: 1 if it reached the grid
};
static_assert(sizeof(GpuWavefrontCorner) == 80);

// A triangle of one face of a light's emission domain whose corners are traced rays.
struct GpuWavefrontPatch {
    GpuWavefrontCorner corners[3];
    glm::uvec4 info;  // x: emitter, y: refinement depth, z: face of the emission domain; w unused
};
static_assert(sizeof(GpuWavefrontPatch) == 256);
static_assert(offsetof(GpuWavefrontPatch, info) == 240);

// The wavefront pass's counters (std430, scalar members as in GLSL).
struct GpuWavefrontCounters {
    std::uint32_t children;  // patches written to the next level (may pass its capacity: those are not written)
    std::uint32_t finished;  // patches deposited
    std::uint32_t splits;    // patches split in four
    std::uint32_t atLimit;   // patches deposited that wanted to split: at the depth or count limit
    std::uint32_t rays;      // corner rays traced
    std::uint32_t tubes;     // tube axes traced (fluence in the grid)
    std::uint32_t unused[2];
};
static_assert(sizeof(GpuWavefrontCounters) == 32);

// The lattice's survey pass (shaders/lattice_scattering.comp, pass 3).
struct GpuLatticeSurvey {
    std::uint32_t channelsDiffer;  // 1 where the channels' media or sources differ
    std::uint32_t thickVoxels;     // cells beyond the depth limit (render/stages/LatticeScattering.h)
    std::uint32_t deepestDepth;    // float bits: the largest optical depth across a voxel among them
    std::uint32_t coarseVoxels;    // scattering cells coarser than the lattice's validated resolution
    std::uint32_t coarsestDepth;   // float bits: the largest reduced optical depth along a voxel's longest edge
    std::uint32_t unused;
};
static_assert(sizeof(GpuLatticeSurvey) == 24);

// A photon suspended at the driver's loop cap, to be resumed by the next
// dispatch (shaders/common/suspended_photons.glsl).
struct GpuSuspendedPhoton {
    glm::vec4 x;              // xyz: position; w: the roulette's cutoff
    glm::vec4 xLost;          // xyz: Kahan compensation of x
    glm::vec4 v;              // xyz: v, |v| = n
    glm::vec4 power;          // rgb: power carried
    glm::uvec4 counters;      // photon, receiver bounces, roulette draws, steps
    glm::uvec4 surfaces;      // recorded vertices, sharp-surface events, inside mask, sharp δn offset (float bits)
};
static_assert(sizeof(GpuSuspendedPhoton) == 96);

// How many photons a dispatch suspended (may pass the buffer's capacity:
// those past it are cut off instead).
// One emitting cell of a glowing volume (render/stages/VolumeGlow.h), in
// cell order.
struct GpuGlowCell {
    glm::vec4 colour;  // rgb: ε per channel over the cell's Σε; w: the inclusive cumulative share of all cells' Σε
    glm::uvec4 cell;   // x: linear cell index
};
static_assert(sizeof(GpuGlowCell) == 32);

struct GpuSuspendedCount {
    std::uint32_t count;
    std::uint32_t unused[3];
};
static_assert(sizeof(GpuSuspendedCount) == 16);

// A sharp surface (shaders/common/sharp_surfaces.glsl), in scene order: a
// sphere, a box, or a mesh or water surface given by its triangles.
struct GpuSharpSurface {
    glm::vec4 shapeA;  // xyz: sphere centre or box min (m); w: kind (SharpSurfaceKind)
    glm::vec4 shapeB;  // x: sphere radius (m); or xyz box max (m); w: a mesh's root node (FieldSet::surfaceNodes)
    glm::vec4 optics;  // x: n_object − n_ref; y: 1 if Fresnel reflection is on; zw unused
};
static_assert(sizeof(GpuSharpSurface) == 48);

// A water body as image space walks its height field (uniform WaterBodies,
// std140; shaders/common/water_height_fields.glsl).
struct GpuWaterHeightField {
    glm::vec4 low;    // xyz: the basin's minimum corner (m); w unused
    glm::vec4 high;   // xyz: its maximum corner (m); w unused
    glm::ivec4 grid;  // x, y: nodes along x and z; z: its first node's texel in WaterNodeGrids; w: its sharp surface
};
static_assert(sizeof(GpuWaterHeightField) == 48);


// uniform CameraBlock (std140): a pinhole or orthographic camera and the environment.
enum EnvironmentKind : unsigned { kUniformEnvironment = 0, kSkyEnvironment = 1, kHdrEnvironment = 2 };

struct GpuCamera {
    glm::vec4 position;    // xyz metres; w = half the image's height: tan(vertical fov / 2) (perspective), metres (orthographic)
    glm::vec4 forward;     // unit; w = width / height
    glm::vec4 right;       // unit
    glm::vec4 up;          // unit
    glm::uvec4 image;      // x: width, y: height, z: EnvironmentKind, w: Projection
    glm::vec4 radiance;    // uniform: rgb radiance W/(m²·sr); hdr: x intensity, y rotation about +y (rad)
    glm::vec4 zenith;      // sky: rgb
    glm::vec4 horizon;     // sky: rgb
    glm::vec4 groundA;     // sky: rgb of one checker colour
    glm::vec4 groundB;     // sky: rgb of the other
    glm::vec4 ground;      // sky: x ground height (m), y checker size (m)
};
static_assert(sizeof(GpuCamera) == 176);
static_assert(offsetof(GpuCamera, image) == 64);
static_assert(offsetof(GpuCamera, ground) == 160);

}  // namespace eikon::layout
