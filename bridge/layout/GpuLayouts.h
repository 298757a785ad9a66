// Every GPU buffer layout eikon uses, in one place (after [Filament]'s
// UibStructs.h). Each struct is an X-macro member list that expands into the
// C++ struct, a static_assert per member that it sits where the std140 or
// std430 rules put its GLSL declaration (GlslPacking.h), and, in the
// embedded shader set, the GLSL macro of the list's name that the shaders
// write as the body of their block or struct: neither side is written
// twice.
//
// The binding points, texture and image units and power-tally indices are
// listed once each, below, as X-macro lists of (name, value). A list expands
// here into its C++ enum and, in the embedded shader set
// (cmake/EmbedShaders.cmake), into the table the shader library declares
// ahead of every program as `const int NAME = VALUE;`, so GLSL writes
// layout(binding = kEmitters) and never a number.
// tests/integration/test_gpu_contract.cpp reads every block, sampler and
// image of every production program back from OpenGL and checks it against
// these names, the structs' sizes and each member's offset and type.
#pragma once

#include "bridge/layout/GlslPacking.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <type_traits>

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

// The structs of the blocks. Each is a member list, X(C++ type, C++ name,
// GLSL type, GLSL name, GLSL array length or 0), that EIKON_LAYOUT_STRUCT
// (GlslPacking.h) makes into the C++ struct with its per-member checks and
// the shader library into the GLSL macro of the list's name, which shaders
// write as the body of their block or struct:
//   layout(std140, binding = kGridBlock) uniform GridBlock { EIKON_GPU_GRID } grid;

// uniform GridBlock (std140): the world box of the field grid.
#define EIKON_GPU_GRID(X)                                                                        \
    X(glm::vec4, boundsMin, vec4, bounds_min, 0)   /* xyz metres; w = n_ref */                   \
    X(glm::vec4, boundsMax, vec4, bounds_max, 0)   /* xyz metres; w unused */                    \
    X(glm::vec4, voxelSize, vec4, voxel_size, 0)   /* xyz metres; w = voxel volume in m³ */      \
    X(glm::ivec4, resolution, ivec4, resolution, 0) /* xyz cells; w unused */
EIKON_LAYOUT_STRUCT(GpuGrid, EIKON_GPU_GRID, kStd140)

// One light's emission (buffer Emitters { Emitter emitters[]; }), prepared on
// the CPU so that the photons of all lights carry exactly the power each
// light sends toward the traced region.
#define EIKON_GPU_EMITTER(X)                                                                                          \
    X(glm::vec4, origin, vec4, origin, 0)             /* point, spot: position; directional: centre of the emitting disk. w: kind (0 cone, 1 disk, 2 glowing volume) */ \
    X(glm::vec4, axis, vec4, axis, 0)                 /* unit central direction. w: cone: versine 1 − cos of its half-angle (2: the sphere); disk: radius (m) */ \
    X(glm::vec4, tangent, vec4, tangent, 0)           /* unit, ⟂ axis */                                                  \
    X(glm::vec4, bitangent, vec4, bitangent, 0)       /* unit, ⟂ axis and tangent */                                      \
    X(glm::vec4, photonPower, vec4, photon_power, 0)  /* rgb W carried by each photon where the spot profile is 1 (glowing volume: × its cell's colour); w unused */ \
    X(glm::vec4, spot, vec4, spot, 0)                 /* xyz: unit spot axis; w: versine 1 − cos of the spot's outer half-angle (−1: no profile) */ \
    X(glm::vec4, spotEdge, vec4, spot_edge, 0)        /* x: versine of the spot's inner half-angle (full intensity inside) */ \
    X(glm::uvec4, photons, uvec4, photons, 0)         /* x: first photon index, y: photon count, z: strata along u1, w: strata along u2 */
EIKON_LAYOUT_STRUCT(GpuEmitter, EIKON_GPU_EMITTER, kStd430)

// An opaque diffuse square receiver and where its map lives in ReceiverMaps
// (uniform Receivers { Receiver receivers[kMaxReceivers]; }).
#define EIKON_GPU_RECEIVER(X)                                                                            \
    X(glm::vec4, origin, vec4, origin, 0)  /* centre on the plane; w: edge size (m) */                   \
    X(glm::vec4, normal, vec4, normal, 0)  /* unit, lit side; w: texel area (m²) */                      \
    X(glm::vec4, axisU, vec4, axis_u, 0)   /* unit tangent; w unused */                                  \
    X(glm::vec4, axisV, vec4, axis_v, 0)   /* unit tangent; w unused */                                  \
    X(glm::vec4, albedo, vec4, albedo, 0)  /* rgb in [0,1]; w unused */                                  \
    X(glm::uvec4, map, uvec4, map, 0)      /* x: first texel in ReceiverMaps, y: texels per edge, z: 1 if photons bounce */
EIKON_LAYOUT_STRUCT(GpuReceiver, EIKON_GPU_RECEIVER, kStd140)

// Energy balance and error figures of one photon pass (buffer PhotonStats),
// accumulated with atomics (the tallies: PowerTally above).
// Powers are tallied in 64-bit fixed point (two 32-bit words with carry) in
// units of the largest per-photon power / 2^24 per channel: float atomics
// adding a million equal values drift by a percent, these stay exact to the
// per-photon rounding and are independent of summation order.
constexpr double kPowerUnitsPerPhoton = 16777216.0;  // 2^24
// The wavefront pass tallies in units of the brightest light's power / 2^50.
constexpr double kPowerUnitsPerWavefront = 1125899906842624.0;  // 2^50

// GLSL declares every member as a scalar array, so std430 packs them with
// 4-byte alignment, as GLM's unaligned vectors are here.
#define EIKON_GPU_PHOTON_STATS(X)                                                                                            \
    X(std::type_identity_t<std::uint32_t[kTallyCount][3][2]>, power, uint, power_tallies, 2 * 3 * kTallyCount) /* [tally][channel][low, high word] */ \
    X(glm::uvec4, photons, uint, photon_tallies, 4)      /* photon counts: x escaped, y received, z cut off, w blocked */          \
    X(glm::uvec4, steps, uint, step_tallies, 4)          /* x: low 32 bits of the step count, y: high bits; z: max |v|−n invariant error (float bits) */ \
    X(glm::uvec4, deposits, uint, deposit_tallies, 4)    /* x: low 32 bits of the voxel deposits, y: high bits */                 \
    X(glm::uvec4, invariant, uint, invariant_tallies, 4) /* x low, y high word: Σ over steps of the relative invariant error in 2^-32 units */ \
    X(glm::uvec4, surfaces, uint, surface_tallies, 4)    /* events at sharp surfaces: x reflected (Fresnel or total internal reflection), y transmitted */
EIKON_LAYOUT_STRUCT(GpuPhotonStats, EIKON_GPU_PHOTON_STATS, kStd430)

// One ray of the wavefront pass (shaders/wavefront_trace.comp, its Corner),
// traced from its point of the light's emission square to where it ends.
#define EIKON_GPU_WAVEFRONT_CORNER(X)                                                                                 \
    X(glm::vec4, ends, vec4, ends, 0)         /* xy: coordinates in its face of the emission domain, [0, 1]²; zw: receiver map coordinates where received, or where it crossed the receiver's plane past the square */ \
    X(glm::vec4, power, vec4, power, 0)       /* rgb: power arriving, per unit of the light's power density there; w: history (uint bits) */ \
    X(glm::vec4, absorbed, vec4, absorbed, 0) /* rgb: power absorbed on the way, same unit; w: fate | (receiver + 1) << 4 (uint bits) */ \
    X(glm::vec4, source, vec4, source, 0)     /* rgb: power the ray starts its wavefront with: emitted, or reflected into its branch */ \
    X(glm::vec4, exit, vec4, exit, 0)         /* xyz: the last point in the grid the ray reached; w: 1 if it reached the grid */
EIKON_LAYOUT_STRUCT(GpuWavefrontCorner, EIKON_GPU_WAVEFRONT_CORNER, kStd430)
namespace glsl {
using Corner = GpuWavefrontCorner;
}  // namespace glsl

// A triangle of one face of a light's emission domain whose corners are
// traced rays (buffers Patches and Children, of Patch).
#define EIKON_GPU_WAVEFRONT_PATCH(X)                                                                 \
    X(std::type_identity_t<GpuWavefrontCorner[3]>, corners, Corner, corners, 3)                      \
    X(glm::uvec4, info, uvec4, info, 0) /* x: emitter, y: refinement depth, z: face of the emission domain; w unused */
EIKON_LAYOUT_STRUCT(GpuWavefrontPatch, EIKON_GPU_WAVEFRONT_PATCH, kStd430)

// The wavefront pass's counters (buffer Counters).
#define EIKON_GPU_WAVEFRONT_COUNTERS(X)                                                                                   \
    X(std::uint32_t, children, uint, child_count, 0)     /* patches written to the next level (may pass its capacity: those are not written) */ \
    X(std::uint32_t, finished, uint, finished_patches, 0) /* patches deposited */                                           \
    X(std::uint32_t, splits, uint, split_patches, 0)     /* patches split in four */                                        \
    X(std::uint32_t, atLimit, uint, limited_patches, 0)  /* patches deposited that wanted to split: at the depth or count limit */ \
    X(std::uint32_t, rays, uint, traced_rays, 0)         /* corner rays traced */                                           \
    X(std::uint32_t, tubes, uint, tube_rays, 0)          /* tube axes traced (fluence in the grid) */                       \
    X(std::type_identity_t<std::uint32_t[2]>, unused, uint, unused_counters, 2)
EIKON_LAYOUT_STRUCT(GpuWavefrontCounters, EIKON_GPU_WAVEFRONT_COUNTERS, kStd430)

// The lattice's survey pass (buffer LatticeSurvey; shaders/lattice_scattering.comp, pass 3).
#define EIKON_GPU_LATTICE_SURVEY(X)                                                                                  \
    X(std::uint32_t, channelsDiffer, uint, channels_differ, 0) /* 1 where the channels' media or sources differ */     \
    X(std::uint32_t, thickVoxels, uint, thick_voxels, 0)       /* cells beyond the depth limit (render/stages/LatticeScattering.h) */ \
    X(std::uint32_t, deepestDepth, uint, deepest_depth, 0)     /* float bits: the largest optical depth across a voxel among them */ \
    X(std::uint32_t, coarseVoxels, uint, coarse_voxels, 0)     /* scattering cells coarser than the lattice's validated resolution */ \
    X(std::uint32_t, coarsestDepth, uint, coarsest_depth, 0)   /* float bits: the largest reduced optical depth along a voxel's longest edge */ \
    X(std::uint32_t, unused, uint, survey_unused, 0)
EIKON_LAYOUT_STRUCT(GpuLatticeSurvey, EIKON_GPU_LATTICE_SURVEY, kStd430)

// A photon suspended at the driver's loop cap, to be resumed by the next
// dispatch (buffers SuspendedIn and SuspendedOut, of SuspendedPhoton;
// shaders/common/suspended_photons.glsl).
#define EIKON_GPU_SUSPENDED_PHOTON(X)                                                          \
    X(glm::vec4, x, vec4, x, 0)                 /* xyz: position; w: the roulette's cutoff */  \
    X(glm::vec4, xLost, vec4, x_lost, 0)        /* xyz: Kahan compensation of x */             \
    X(glm::vec4, v, vec4, v, 0)                 /* xyz: v, |v| = n */                          \
    X(glm::vec4, power, vec4, power, 0)         /* rgb: power carried */                       \
    X(glm::uvec4, counters, uvec4, counters, 0) /* photon, receiver bounces, roulette draws, steps */ \
    X(glm::uvec4, surfaces, uvec4, surfaces, 0) /* recorded vertices, sharp-surface events, inside mask, sharp δn offset (float bits) */
EIKON_LAYOUT_STRUCT(GpuSuspendedPhoton, EIKON_GPU_SUSPENDED_PHOTON, kStd430)

// How many photons a dispatch suspended (buffer SuspendedCount; may pass
// the buffer's capacity: those past it are cut off instead).
#define EIKON_GPU_SUSPENDED_COUNT(X)             \
    X(std::uint32_t, count, uint, suspended_count, 0) \
    X(std::type_identity_t<std::uint32_t[3]>, unused, uint, suspended_unused, 3)
EIKON_LAYOUT_STRUCT(GpuSuspendedCount, EIKON_GPU_SUSPENDED_COUNT, kStd430)

// One emitting cell of a glowing volume (render/stages/VolumeGlow.h), in
// cell order (buffer GlowCells { GlowCell glow_cells[]; }).
#define EIKON_GPU_GLOW_CELL(X)                                                                                         \
    X(glm::vec4, colour, vec4, colour, 0) /* rgb: ε per channel over the cell's Σε; w: the inclusive cumulative share of all cells' Σε */ \
    X(glm::uvec4, cell, uvec4, cell, 0)   /* x: linear cell index */
EIKON_LAYOUT_STRUCT(GpuGlowCell, EIKON_GPU_GLOW_CELL, kStd430)

// A sharp surface (shaders/common/sharp_surface_list.glsl), in scene order: a
// sphere, a box, or a mesh or water surface given by its triangles (uniform
// SharpSurfaces { SharpSurface sharp_surfaces[kMaxSharpObjects]; }).
#define EIKON_GPU_SHARP_SURFACE(X)                                                                          \
    X(glm::vec4, shapeA, vec4, shape_a, 0) /* xyz: sphere centre or box min (m); w: kind (SharpSurfaceKind) */ \
    X(glm::vec4, shapeB, vec4, shape_b, 0) /* x: sphere radius (m); or xyz box max (m); w: a mesh's root node (FieldSet::surfaceNodes) */ \
    X(glm::vec4, optics, vec4, optics, 0)  /* x: n_object − n_ref; y: 1 if Fresnel reflection is on; zw unused */
EIKON_LAYOUT_STRUCT(GpuSharpSurface, EIKON_GPU_SHARP_SURFACE, kStd140)

// A water body as image space walks its height field (uniform WaterBodies
// { WaterBody water_bodies[kMaxSharpObjects]; }; shaders/common/water_height_fields.glsl).
#define EIKON_GPU_WATER_HEIGHT_FIELD(X)                                                                 \
    X(glm::vec4, low, vec4, low, 0)     /* xyz: the basin's minimum corner (m); w unused */             \
    X(glm::vec4, high, vec4, high, 0)   /* xyz: its maximum corner (m); w unused */                     \
    X(glm::ivec4, grid, ivec4, grid, 0) /* x, y: nodes along x and z; z: its first node's texel in WaterNodeGrids; w: its sharp surface */
EIKON_LAYOUT_STRUCT(GpuWaterHeightField, EIKON_GPU_WATER_HEIGHT_FIELD, kStd140)

// uniform CameraBlock (std140): a pinhole or orthographic camera and the environment.
enum EnvironmentKind : unsigned { kUniformEnvironment = 0, kSkyEnvironment = 1, kHdrEnvironment = 2 };

#define EIKON_GPU_CAMERA(X)                                                                                    \
    X(glm::vec4, position, vec4, position, 0) /* xyz metres; w = half the image's height: tan(vertical fov / 2) (perspective), metres (orthographic) */ \
    X(glm::vec4, forward, vec4, forward, 0)   /* unit; w = width / height */                                   \
    X(glm::vec4, right, vec4, right, 0)       /* unit */                                                       \
    X(glm::vec4, up, vec4, up, 0)             /* unit */                                                       \
    X(glm::uvec4, image, uvec4, image, 0)     /* x: width, y: height, z: EnvironmentKind, w: Projection */     \
    X(glm::vec4, radiance, vec4, radiance, 0) /* uniform: rgb radiance W/(m²·sr); hdr: x intensity, y rotation about +y (rad) */ \
    X(glm::vec4, zenith, vec4, zenith, 0)     /* sky: rgb */                                                   \
    X(glm::vec4, horizon, vec4, horizon, 0)   /* sky: rgb */                                                   \
    X(glm::vec4, groundA, vec4, ground_a, 0)  /* sky: rgb of one checker colour */                             \
    X(glm::vec4, groundB, vec4, ground_b, 0)  /* sky: rgb of the other */                                      \
    X(glm::vec4, ground, vec4, ground, 0)     /* sky: x ground height (m), y checker size (m) */
EIKON_LAYOUT_STRUCT(GpuCamera, EIKON_GPU_CAMERA, kStd140)

}  // namespace eikon::layout

// Every struct above, (C++ name, member list), nested structs before the
// structs that hold them: the shader library declares each list's GLSL
// macro ahead of every program.
#define EIKON_LAYOUT_STRUCTS(S)                                  \
    S(GpuGrid, EIKON_GPU_GRID)                                   \
    S(GpuEmitter, EIKON_GPU_EMITTER)                             \
    S(GpuReceiver, EIKON_GPU_RECEIVER)                           \
    S(GpuPhotonStats, EIKON_GPU_PHOTON_STATS)                    \
    S(GpuWavefrontCorner, EIKON_GPU_WAVEFRONT_CORNER)            \
    S(GpuWavefrontPatch, EIKON_GPU_WAVEFRONT_PATCH)              \
    S(GpuWavefrontCounters, EIKON_GPU_WAVEFRONT_COUNTERS)        \
    S(GpuLatticeSurvey, EIKON_GPU_LATTICE_SURVEY)                \
    S(GpuSuspendedPhoton, EIKON_GPU_SUSPENDED_PHOTON)            \
    S(GpuSuspendedCount, EIKON_GPU_SUSPENDED_COUNT)              \
    S(GpuGlowCell, EIKON_GPU_GLOW_CELL)                          \
    S(GpuSharpSurface, EIKON_GPU_SHARP_SURFACE)                  \
    S(GpuWaterHeightField, EIKON_GPU_WATER_HEIGHT_FIELD)         \
    S(GpuCamera, EIKON_GPU_CAMERA)
