// The GPU contract as OpenGL reports it: every uniform block, shader storage
// block, sampler and image of every production program (in the #define
// variants that change which of them exist) sits at the binding point or
// unit bridge/layout/GpuLayouts.h names for it, every block has the size of
// its C++ struct, every member of a block of a GPU struct sits at its C++
// member's offset with the type its list gives, every member of the list
// is there, and no two resources of one program share a binding. A
// resource whose name the tables below do not know fails the test: a new
// block, sampler or image needs its row here.
#include "bridge/layout/GpuLayouts.h"
#include "gl/EmbeddedShaders.h"
#include "gl/GlContext.h"
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"
#include "tests/integration/ContractMembers.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/ProgramResources.h"

#include <gtest/gtest.h>

#include <glm/ext/vector_double4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace eikon {
namespace {

using test::activeResources;
using test::activeVariables;
using test::glTypeOf;
using test::resourceName;
using test::resourceProperty;
using test::typeBytes;

// A block's layout: the bytes before its runtime-sized array (all of it when
// it has none) and that array's element stride (0: none; kFloatOrDouble: a
// float or a double by the program's variant, as the fluid solver's linear
// algebra and reductions choose their precision per pass).
constexpr std::size_t kFloatOrDouble = ~std::size_t{0};
struct BlockRow {
    unsigned binding;
    std::size_t fixedBytes;
    std::size_t elementBytes;
};

const std::map<std::string, BlockRow>& uniformBlocks() {
    static const std::map<std::string, BlockRow> rows = {
        {"GridBlock", {layout::kGridBlock, sizeof(layout::GpuGrid), 0}},
        {"CameraBlock", {layout::kCameraBlock, sizeof(layout::GpuCamera), 0}},
        {"Receivers", {layout::kReceivers, layout::kMaxReceivers * sizeof(layout::GpuReceiver), 0}},
        {"SharpSurfaces", {layout::kSharpSurfaces, layout::kMaxSharpObjects * sizeof(layout::GpuSharpSurface), 0}},
        {"ImageSpaceSurfaces", {layout::kImageSpaceSurfaces, layout::kMaxSharpObjects * sizeof(glm::vec4), 0}},
        {"WaterBodies", {layout::kWaterBodies, layout::kMaxSharpObjects * sizeof(layout::GpuWaterHeightField), 0}},
    };
    return rows;
}

const std::map<std::string, BlockRow>& storageBlocks() {
    static const std::map<std::string, BlockRow> rows = {
        {"Emitters", {layout::kEmitters, 0, sizeof(layout::GpuEmitter)}},
        {"ReceiverMaps", {layout::kReceiverMaps, 0, sizeof(float)}},
        {"Fluence", {layout::kFluence, 0, sizeof(float)}},
        {"PhotonStats", {layout::kPhotonStats, sizeof(layout::GpuPhotonStats), 0}},
        {"HdrImage", {layout::kHdrImage, 0, sizeof(glm::vec4)}},
        {"LdrImage", {layout::kLdrImage, 0, sizeof(std::uint32_t)}},
        {"PhotonPaths", {layout::kPhotonPaths, 0, sizeof(glm::vec4)}},
        {"ReceiverTallies", {layout::kReceiverTallies, 0, sizeof(std::uint32_t)}},
        {"FluenceDirection", {layout::kFluenceDirection, 0, sizeof(float)}},
        {"RawFluence", {layout::kRawFluence, 0, sizeof(float)}},
        {"RawFluenceDirection", {layout::kRawFluenceDirection, 0, sizeof(float)}},
        {"ViewExit", {layout::kViewExit, 0, sizeof(glm::vec4)}},
        {"DiagnosticRays", {layout::kDiagnosticRays, 0, sizeof(glm::vec4)}},
        {"DiagnosticLanding", {layout::kDiagnosticLanding, 0, sizeof(glm::vec4)}},
        {"DiagnosticReference", {layout::kDiagnosticReference, 0, sizeof(std::uint32_t)}},
        {"DiagnosticScreen", {layout::kDiagnosticScreen, 0, sizeof(std::uint32_t)}},
        {"PhotonPathPower", {layout::kPhotonPathPower, 0, sizeof(glm::vec4)}},
        {"SurfaceNodes", {layout::kSurfaceNodes, 0, sizeof(glm::vec4)}},
        {"WaterNodeGrids", {layout::kWaterNodeGrids, 0, sizeof(glm::vec4)}},
        {"WaterSlabs", {layout::kWaterSlabs, 0, sizeof(glm::uvec4)}},
        {"SurfaceTriangles", {layout::kSurfaceTriangles, 0, sizeof(glm::vec4)}},
        {"Patches", {layout::kWavefrontPatches, 0, sizeof(layout::GpuWavefrontPatch)}},
        {"Children", {layout::kWavefrontChildren, 0, sizeof(layout::GpuWavefrontPatch)}},
        {"Counters", {layout::kWavefrontCounters, sizeof(layout::GpuWavefrontCounters), 0}},
        {"GlowCells", {layout::kGlowCells, 0, sizeof(layout::GpuGlowCell)}},
        {"SuspendedIn", {layout::kSuspendedIn, 0, sizeof(layout::GpuSuspendedPhoton)}},
        {"SuspendedOut", {layout::kSuspendedOut, 0, sizeof(layout::GpuSuspendedPhoton)}},
        {"SuspendedCount", {layout::kSuspendedCount, sizeof(layout::GpuSuspendedCount), 0}},
        {"LatticeIn", {layout::kLatticeIn, 0, sizeof(float)}},
        {"LatticeOut", {layout::kLatticeOut, 0, sizeof(float)}},
        {"LatticeProbes", {layout::kLatticeProbes, 0, sizeof(float)}},
        {"MultipleFluence", {layout::kMultipleFluence, 0, sizeof(float)}},
        {"LatticeTallies", {layout::kLatticeTallies, 0, sizeof(glm::vec4)}},
        {"RawScattered", {layout::kRawScattered, 0, sizeof(float)}},
        {"ScatteredPower", {layout::kScatteredPower, 0, sizeof(float)}},
        {"LatticeSurvey", {layout::kLatticeSurvey, sizeof(layout::GpuLatticeSurvey), 0}},
        {"LatticeInterfaces", {layout::kLatticeInterfaces, 0, sizeof(glm::uvec4)}},
        {"LatticeBirth", {layout::kLatticeBirth, 0, sizeof(float)}},
        {"LatticePhase", {layout::kLatticePhase, 0, sizeof(float)}},
        // Image space (render/stages/ImageSpace*, CausticPolygons).
        {"SurfacePixels", {layout::kSurfacePixels, 0, sizeof(std::uint32_t)}},
        {"SurfacePixelCount", {layout::kSurfacePixelCount, sizeof(glm::uvec4), 0}},
        {"CausticVertices", {layout::kCausticVertices, 0, sizeof(glm::vec4)}},
        {"CausticTriangles", {layout::kCausticTriangles, 0, sizeof(glm::vec4)}},
        {"CausticDraw", {layout::kCausticDraw, sizeof(glm::uvec4), 0}},
        {"CausticDeposits", {layout::kCausticDeposits, 0, sizeof(glm::vec4)}},
        {"CausticDepositCount", {layout::kCausticDepositCount, sizeof(glm::uvec4), 0}},
        {"CausticCellGroups", {layout::kCausticCellGroups, sizeof(glm::uvec4), 0}},
        // The fluid solver's passes (sim/gpu, shaders/sim).
        {"VelocityX", {layout::kSolverVelocityX, 0, sizeof(float)}},
        {"VelocityY", {layout::kSolverVelocityY, 0, sizeof(float)}},
        {"VelocityZ", {layout::kSolverVelocityZ, 0, sizeof(float)}},
        {"Field", {layout::kSolverField, 0, sizeof(float)}},
        {"Concentration", {layout::kSolverField, 0, sizeof(float)}},
        {"Source", {layout::kSolverSource, 0, sizeof(float)}},
        {"TemperatureExcess", {layout::kSolverSource, 0, sizeof(float)}},
        {"OperandA", {layout::kSolverSource, 0, kFloatOrDouble}},
        {"Target", {layout::kSolverTarget, 0, sizeof(float)}},
        {"Velocity", {layout::kSolverTarget, 0, sizeof(float)}},
        {"OperandB", {layout::kSolverTarget, 0, kFloatOrDouble}},
        {"BoundsLow", {layout::kSolverBoundsLow, 0, sizeof(float)}},
        {"BoundsHigh", {layout::kSolverBoundsHigh, 0, sizeof(float)}},
        {"Cells", {layout::kSolverCells, 0, sizeof(std::uint32_t)}},
        {"VectorX", {layout::kSolverVectorX, 0, kFloatOrDouble}},
        {"VectorB", {layout::kSolverVectorB, 0, kFloatOrDouble}},
        {"VectorR", {layout::kSolverVectorR, 0, kFloatOrDouble}},
        {"VectorP", {layout::kSolverVectorP, 0, kFloatOrDouble}},
        {"VectorQ", {layout::kSolverVectorQ, 0, kFloatOrDouble}},
        {"Partials", {layout::kSolverPartials, 0, sizeof(double)}},
        {"FirstBad", {layout::kSolverPartials, 0, sizeof(std::uint32_t)}},
        {"Results", {layout::kSolverResults, 0, sizeof(double)}},
        {"Backward", {layout::kSolverBackward, 0, sizeof(glm::vec4)}},
        {"Forward", {layout::kSolverForward, 0, sizeof(glm::vec4)}},
        {"Coarse", {layout::kSolverCoarse, 0, sizeof(float)}},
        {"Fine", {layout::kSolverFine, 0, sizeof(float)}},
        {"Held", {layout::kSolverSourceCells, 0, sizeof(glm::uvec2)}},
        {"OpticsTemperature", {layout::kOpticsTemperature, 0, sizeof(float)}},
        {"OpticsConcentration", {layout::kOpticsConcentration, 0, sizeof(float)}},
        {"OpticsDye", {layout::kOpticsDye, 0, sizeof(float)}},
        {"OpticsDeltaIndex", {layout::kOpticsDeltaIndex, 0, sizeof(float)}},
        {"OpticsExtinction", {layout::kOpticsExtinction, 0, sizeof(float)}},
        {"OpticsScattering", {layout::kOpticsScattering, 0, sizeof(float)}},
        {"OpticsAnisotropy", {layout::kOpticsAnisotropy, 0, sizeof(float)}},
        {"WaterHeight", {layout::kWaterHeight, 0, sizeof(double)}},
        {"WaterNextHeight", {layout::kWaterNextHeight, 0, sizeof(double)}},
        {"WaterVelocity", {layout::kWaterVelocity, 0, sizeof(double)}},
        {"WaterDrop", {layout::kWaterDrop, 0, sizeof(double)}},
        {"WaterVertices", {layout::kWaterVertices, 0, sizeof(glm::dvec4)}},
        {"WaterTriangles", {layout::kWaterTriangles, 0, sizeof(glm::ivec4)}},
        {"WaterSlots", {layout::kWaterSlots, 0, sizeof(int)}},
        {"WaterCornerStart", {layout::kWaterCornerStart, 0, sizeof(int)}},
        {"WaterCorners", {layout::kWaterCorners, 0, sizeof(int)}},
        {"WaterFaceNormals", {layout::kWaterFaceNormals, 0, sizeof(glm::dvec4)}},
        {"WaterFaceAngles", {layout::kWaterFaceAngles, 0, sizeof(glm::dvec4)}},
        {"WaterNodes", {layout::kWaterNodes, 0, sizeof(glm::ivec4)}},
        {"WaterLevelNodes", {layout::kWaterLevelNodes, 0, sizeof(int)}},
        {"WaterSurfaceNodes", {layout::kWaterSurfaceNodes, 0, sizeof(glm::vec4)}},
        {"WaterSurfaceTriangles", {layout::kWaterSurfaceTriangles, 0, sizeof(glm::vec4)}},
        {"WaterBaseExtinction", {layout::kWaterBaseExtinction, 0, sizeof(float)}},
        {"WaterBaseScattering", {layout::kWaterBaseScattering, 0, sizeof(float)}},
        {"WaterBaseAnisotropy", {layout::kWaterBaseAnisotropy, 0, sizeof(float)}},
    };
    return rows;
}

// The blocks that hold a GPU struct of bridge/layout/GpuLayouts.h.
const std::map<std::string, test::StructuredBlock>& structuredBlocks() {
    static const std::map<std::string, test::StructuredBlock> rows = {
        {"GridBlock", {"GpuGrid", ""}},
        {"CameraBlock", {"GpuCamera", ""}},
        {"Receivers", {"GpuReceiver", "receivers"}},
        {"SharpSurfaces", {"GpuSharpSurface", "sharp_surfaces"}},
        {"WaterBodies", {"GpuWaterHeightField", "water_bodies"}},
        {"Emitters", {"GpuEmitter", "emitters"}},
        {"PhotonStats", {"GpuPhotonStats", ""}},
        {"Patches", {"GpuWavefrontPatch", "patches"}},
        {"Children", {"GpuWavefrontPatch", "children"}},
        {"Counters", {"GpuWavefrontCounters", ""}},
        {"LatticeSurvey", {"GpuLatticeSurvey", ""}},
        {"GlowCells", {"GpuGlowCell", "glow_cells"}},
        {"SuspendedIn", {"GpuSuspendedPhoton", "suspended_in"}},
        {"SuspendedOut", {"GpuSuspendedPhoton", "suspended_out"}},
        {"SuspendedCount", {"GpuSuspendedCount", ""}},
    };
    return rows;
}

// GLSL sampler name → texture unit.
const std::map<std::string, unsigned>& samplers() {
    static const std::map<std::string, unsigned> rows = {
        {"index_texture", layout::kIndexTexture},           {"source_texture", layout::kIndexTexture},
        {"pyramid", layout::kPyramidTexture},               {"gradient_texture", layout::kGradientTexture},
        {"extinction_texture", layout::kExtinctionTexture}, {"scattering_texture", layout::kScatteringTexture},
        {"step_structure", layout::kStepTexture},           {"environment_texture", layout::kEnvironmentTexture},
        {"anisotropy_texture", layout::kAnisotropyTexture}, {"emission_texture", layout::kEmissionTexture},
        {"near_layer", layout::kNearLayerTexture},          {"far_layer", layout::kFarLayerTexture},
        {"caustic_atlas", layout::kCausticAtlasTexture},    {"receiver_map_texels", layout::kReceiverMapTexture},
        {"caustic_vertex_texels", layout::kCausticVertexTexture},
        {"surface_triangle_texels", layout::kSurfaceTriangleTexture},
        {"surface_node_texels", layout::kSurfaceNodeTexture},
        {"receiver_tally_texels", layout::kReceiverTallyTexture},
        {"hdr_radiance", layout::kHdrImageTexture},
        {"water_node_texels", layout::kWaterNodeTexture},
        {"pattern_texture", layout::kBackgroundPatternTexture},
    };
    return rows;
}

// GLSL image name → image unit.
const std::map<std::string, unsigned>& images() {
    static const std::map<std::string, unsigned> rows = {
        {"target_image", layout::kSmoothedIndexImage}, {"gradient_image", layout::kGradientImage},
        {"finer_level", layout::kFinerLevelImage},     {"this_level", layout::kPyramidLevelImage},
        {"step_structure", layout::kStepImage},
    };
    return rows;
}

struct Variant {
    std::string shader;  // a compute shader, or a raster program's vertex shader
    gl::ShaderDefines defines;
    std::string fragment = {};  // a raster program's fragment shader

    std::string label() const {
        std::string text = fragment.empty() ? shader : shader + " + " + fragment;
        for (const auto& [key, value] : defines) text += " " + key + "=" + value;
        return text;
    }
};

// Every program the stages compile, with no options (the fewest resources),
// with every option that adds one, and the photon pass as `eikon bench`
// runs it bare.
std::vector<Variant> productionVariants() {
    return {
        {"smooth_index.comp", {}},
        {"prepare_gradient.comp", {}},
        {"octree_minmax.comp", {{"EIKON_HAS_EXTINCTION", "0"}}},
        {"octree_minmax.comp", {{"EIKON_HAS_EXTINCTION", "1"}, {"EIKON_HAS_EMISSION", "1"}}},
        {"octree_label.comp", {}},
        {"receiver_filter.comp", {{"EIKON_FILTER_RADIUS", "1"}}},
        {"receiver_filter.comp", {{"EIKON_FILTER_RADIUS", "-1"}}},
        {"fluence_smooth.comp", {}},
        {"fluence_smooth.comp", {{"EIKON_FIXED_FLUENCE", "1"}, {"EIKON_LATTICE_SOURCE", "1"}}},
        {"tonemap.comp", {}},
        {"photon_trace.comp", {{"EIKON_RECEIVERS", "1"}}},
        {"photon_trace.comp",
         {{"EIKON_RECEIVERS", "4"},
          {"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_OCTREE_STEPS", "1"},
          {"EIKON_DISPERSION", "1"},
          {"EIKON_STORE_FLUENCE", "1"},
          {"EIKON_LATTICE_SOURCE", "1"},
          {"EIKON_BOUNCE", "1"},
          {"EIKON_SHARP_SURFACES", "2"},
          {"EIKON_VOLUME_GLOW", "1"},
          {"EIKON_RECORD_PATHS", "8"}}},
        {"photon_trace.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_BARE_MARCH", "1"}}},
        {"photon_trace.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_LOOP_BUDGET", "4096"}}},
        {"wavefront_trace.comp", {{"EIKON_RECEIVERS", "1"}}},
        {"wavefront_trace.comp",
         {{"EIKON_RECEIVERS", "4"},
          {"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_OCTREE_STEPS", "1"},
          {"EIKON_SHARP_SURFACES", "2"},
          {"EIKON_STORE_FLUENCE", "1"},
          {"EIKON_FIXED_FLUENCE", "1"},
          {"EIKON_LATTICE_SOURCE", "1"}}},
        {"view_rays.comp", {{"EIKON_RECEIVERS", "1"}}},
        {"view_rays.comp",
         {{"EIKON_RECEIVERS", "4"},
          {"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_HAS_ANISOTROPY", "1"},
          {"EIKON_HAS_EMISSION", "1"},
          {"EIKON_STEP_STRUCTURE", "1"},
          {"EIKON_ENVIRONMENT", std::to_string(layout::kHdrEnvironment)},
          {"EIKON_SHARP_SURFACES", "2"},
          {"EIKON_MULTIPLE_SCATTERING", "1"},
          {"EIKON_RECORD_EXIT", "1"}}},
        // The diagnostics, one instrument each (render/stages/DiagnosticStage).
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "0"}}},
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "1"}, {"EIKON_HAS_EXTINCTION", "1"}}},
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "2"}}},
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "3"}}},
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "4"}, {"EIKON_HAS_EXTINCTION", "1"}}},
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "5"}}},
        {"diagnostic_rays.comp", {{"EIKON_INSTRUMENT", "5"}, {"EIKON_BOS_IMAGE", "1"}, {"EIKON_INTEGRATOR", "2"}}},
        {"shadowgraph_screen.comp", {{"EIKON_SCREEN_PASS", "0"}, {"EIKON_HAS_EXTINCTION", "1"}}},
        {"shadowgraph_screen.comp", {{"EIKON_SCREEN_PASS", "1"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"}, {"EIKON_HAS_SCATTERING", "1"}, {"EIKON_LATTICE_PASS", "0"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_LATTICE_DIRECTIONS", "14"},
          {"EIKON_LATTICE_PASS", "1"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"}, {"EIKON_HAS_SCATTERING", "1"}, {"EIKON_LATTICE_PASS", "3"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_LATTICE_INTERFACES", "1"},
          {"EIKON_LATTICE_PASS", "4"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_LATTICE_INTERFACES", "1"},
          {"EIKON_LATTICE_PASS", "0"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_HAS_ANISOTROPY", "1"},
          {"EIKON_LATTICE_DIRECTIONS", "18"},
          {"EIKON_LATTICE_PASS", "2"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_HAS_ANISOTROPY", "1"},
          {"EIKON_LATTICE_DIRECTED", "1"},
          {"EIKON_LATTICE_PASS", "0"}}},
        {"lattice_scattering.comp",
         {{"EIKON_HAS_EXTINCTION", "1"},
          {"EIKON_HAS_SCATTERING", "1"},
          {"EIKON_HAS_ANISOTROPY", "1"},
          {"EIKON_LATTICE_DIRECTED", "1"},
          {"EIKON_LATTICE_PASS", "5"}}},
        // Image space's compute passes (render/stages/ImageSpace*, CausticPolygons).
        {"image_space_caustics.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "0"}}},
        {"image_space_caustics.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "1"}}},
        {"image_space_view.comp",
         {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "0"}, {"EIKON_ENVIRONMENT", std::to_string(layout::kHdrEnvironment)}}},
        {"image_space_view.comp",
         {{"EIKON_RECEIVERS", "4"},
          {"EIKON_PASS", "1"},
          {"EIKON_ENVIRONMENT", std::to_string(layout::kHdrEnvironment)},
          {"EIKON_RECORD_EXIT", "1"},
          {"EIKON_WATER_BODIES", "1"},
          {"EIKON_LAYER_SURFACES", "1"}}},
        {"image_space_view.comp",
         {{"EIKON_RECEIVERS", "2"},
          {"EIKON_PASS", "2"},
          {"EIKON_ENVIRONMENT", std::to_string(layout::kSkyEnvironment)},
          {"EIKON_RECORD_EXIT", "1"},
          {"EIKON_WATER_BODIES", "2"},
          {"EIKON_LAYER_SURFACES", "0"}}},
        {"image_space_caustics.comp",
         {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "1"}, {"EIKON_WATER_BODIES", "2"}, {"EIKON_LAYER_SURFACES", "0"}}},
        {"water_height_fields.comp", {{"EIKON_PASS", "0"}}},
        {"water_height_fields.comp", {{"EIKON_PASS", "1"}}},
        {"water_height_fields.comp", {{"EIKON_PASS", "2"}}},
        {"caustic_polygons.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "0"}, {"EIKON_CELL_RECEIVERS", "4"}}},
        {"caustic_polygons.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "1"}}},
        {"caustic_polygons.comp", {{"EIKON_RECEIVERS", "1"}, {"EIKON_PASS", "2"}}},
        // Image space's raster programs (render/stages/SurfaceLayers, CausticPolygons).
        {"surface_layers.vert",
         {{"EIKON_EXACT_SHAPES", "1"}, {"EIKON_PEEL", "1"}, {"EIKON_NEAR_TEST", "1"}},
         "surface_layers.frag"},
        {"surface_layers.vert",
         {{"EIKON_EXACT_SHAPES", "0"}, {"EIKON_PEEL", "0"}, {"EIKON_NEAR_TEST", "0"}},
         "surface_layers.frag"},
        {"surface_layers.vert",
         {{"EIKON_EXACT_SHAPES", "2"}, {"EIKON_PEEL", "1"}, {"EIKON_NEAR_TEST", "0"}},
         "surface_layers.frag"},
        {"caustic_polygons.vert", {{"EIKON_RECEIVERS", "2"}}, "caustic_polygons.frag"},
        // The fluid solver's passes, each variant sim/gpu compiles.
        {"sim/apply_sources.comp", {}},
        {"sim/buoyancy.comp", {}},
        {"sim/velocity_boundaries.comp", {}},
        {"sim/find_nonfinite.comp", {{"FIND", "1"}}},
        {"sim/find_nonfinite.comp", {}},
        {"sim/reduce.comp", {{"OPERATION", "REDUCE_DOT"}, {"ELEMENT", "double"}, {"PASS", "0"}}},
        {"sim/reduce.comp", {{"OPERATION", "REDUCE_MAX_ABS"}, {"ELEMENT", "float"}, {"PASS", "1"}}},
        {"sim/advection_trace.comp", {}},
        {"sim/advection_predict.comp", {}},
        {"sim/advection_correct.comp", {}},
        {"sim/mass_correction.comp", {{"STAGE", "STAGE_RECORD"}, {"PASS", "0"}}},
        {"sim/mass_correction.comp", {{"STAGE", "STAGE_MEASURE"}, {"PASS", "1"}}},
        {"sim/mass_correction.comp", {{"STAGE", "STAGE_RESTORE"}, {"PASS", "0"}}},
        {"sim/stencil_apply.comp", {{"OPERATION", "OPERATION_APPLY"}, {"REAL", "double"}}},
        {"sim/stencil_apply.comp", {{"OPERATION", "OPERATION_RESIDUAL"}, {"REAL", "float"}}},
        {"sim/stencil_apply.comp", {{"OPERATION", "OPERATION_INVERSE_DIAGONAL"}, {"REAL", "double"}}},
        {"sim/stencil_relax.comp", {{"RELAX", "RELAX_SMOOTH"}, {"REAL", "float"}}},
        {"sim/stencil_relax.comp", {{"RELAX", "RELAX_GAUSS_SEIDEL"}, {"REAL", "double"}}},
        {"sim/stencil_relax.comp", {{"RELAX", "RELAX_COARSEST"}, {"REAL", "float"}}},
        {"sim/cg_update.comp", {{"UPDATE", "UPDATE_STEP"}}},
        {"sim/cg_update.comp", {{"UPDATE", "UPDATE_DIRECTION"}}},
        {"sim/cg_update.comp", {{"UPDATE", "UPDATE_REMOVE_MEAN"}}},
        {"sim/multigrid_transfer.comp", {{"TRANSFER", "TRANSFER_RESTRICT"}}},
        {"sim/multigrid_transfer.comp", {{"TRANSFER", "TRANSFER_PROLONG"}}},
        {"sim/vector_convert.comp", {{"CONVERT", "CONVERT_NARROW"}}},
        {"sim/vector_convert.comp", {{"CONVERT", "CONVERT_WIDEN"}}},
        {"sim/vector_convert.comp", {{"CONVERT", "CONVERT_ADD"}}},
        {"sim/pressure_divergence.comp", {}},
        {"sim/pressure_gradient.comp", {}},
        {"sim/diffusion_rhs.comp", {}},
        {"sim/optical_mapping.comp",
         {{"EIKON_LIQUID", "1"}, {"EIKON_LORENTZ_LORENZ", "1"}, {"EIKON_HAS_EXTINCTION", "1"}, {"EIKON_HAS_SCATTERING", "1"}}},
        {"sim/optical_mapping.comp",
         {{"EIKON_LIQUID", "0"}, {"EIKON_LORENTZ_LORENZ", "0"}, {"EIKON_HAS_EXTINCTION", "0"}, {"EIKON_HAS_SCATTERING", "0"}}},
        {"sim/water_step.comp", {{"EIKON_PASS", "0"}, {"EIKON_MAX_WATER_MOVERS", "8"}}},
        {"sim/water_step.comp", {{"EIKON_PASS", "1"}, {"EIKON_MAX_WATER_MOVERS", "8"}}},
        {"sim/water_surface.comp", {{"EIKON_PASS", "0"}}},
        {"sim/water_surface.comp", {{"EIKON_PASS", "1"}}},
        {"sim/water_surface.comp", {{"EIKON_PASS", "2"}}},
        {"sim/water_coverage.comp",
         {{"EIKON_HAS_EXTINCTION", "1"}, {"EIKON_HAS_SCATTERING", "1"}, {"EIKON_HAS_ANISOTROPY", "1"}}},
        {"sim/water_coverage.comp",
         {{"EIKON_HAS_EXTINCTION", "0"}, {"EIKON_HAS_SCATTERING", "0"}, {"EIKON_HAS_ANISOTROPY", "0"}}},
    };
}

// A block's layout from its members' offsets and strides: GL_BUFFER_DATA_SIZE
// would do for most, but Mesa rounds it up to 16 bytes.
BlockRow measuredLayout(GLuint program, GLenum blockInterface, GLuint block) {
    const GLenum memberInterface = blockInterface == GL_SHADER_STORAGE_BLOCK ? GL_BUFFER_VARIABLE : GL_UNIFORM;
    BlockRow layout{static_cast<unsigned>(resourceProperty(program, blockInterface, block, GL_BUFFER_BINDING)), 0, 0};
    for (const GLint member : activeVariables(program, blockInterface, block)) {
        auto property = [&](GLenum name) {
            return resourceProperty(program, memberInterface, static_cast<GLuint>(member), name);
        };
        // A runtime-sized array has size 0: an array of structs at the top
        // level, one of a basic type (for Mesa) in the member itself.
        if (memberInterface == GL_BUFFER_VARIABLE && property(GL_TOP_LEVEL_ARRAY_SIZE) == 0) {
            layout.elementBytes = static_cast<std::size_t>(property(GL_TOP_LEVEL_ARRAY_STRIDE));
            continue;
        }
        if (memberInterface == GL_BUFFER_VARIABLE && property(GL_ARRAY_SIZE) == 0) {
            layout.elementBytes = static_cast<std::size_t>(property(GL_ARRAY_STRIDE));
            continue;
        }
        const auto elements = static_cast<std::size_t>(std::max(property(GL_ARRAY_SIZE), 1));
        const std::size_t end = static_cast<std::size_t>(property(GL_OFFSET)) +
                                (elements - 1) * static_cast<std::size_t>(property(GL_ARRAY_STRIDE)) +
                                typeBytes(static_cast<GLenum>(property(GL_TYPE)));
        layout.fixedBytes = std::max(layout.fixedBytes, end);
    }
    return layout;
}

// What one program declares, checked against the tables; `seen` collects
// the rows met, so rows no program uses can be told apart.
class ContractCheck {
public:
    explicit ContractCheck(std::set<std::string>& seen) : seen_(seen) {}

    void blocks(const gl::Program& program, const std::string& label, GLenum interface) {
        const auto& rows = interface == GL_UNIFORM_BLOCK ? uniformBlocks() : storageBlocks();
        const char* kind = interface == GL_UNIFORM_BLOCK ? "uniform block" : "shader storage block";
        std::map<GLint, std::string> byBinding;
        for (GLuint i = 0; i < activeResources(program.id(), interface); ++i) {
            const std::string name = resourceName(program.id(), interface, i);
            const BlockRow measured = measuredLayout(program.id(), interface, i);
            noteBinding(byBinding, static_cast<GLint>(measured.binding), name, label, kind);
            const auto row = rows.find(name);
            if (row == rows.end()) {
                ADD_FAILURE() << label << ": " << kind << " " << name << " is not in the contract tables";
                continue;
            }
            seen_.insert(std::string(kind) + " " + name);
            const BlockRow& expected = row->second;
            EXPECT_EQ(measured.binding, expected.binding) << label << ": " << kind << " " << name << " is bound at "
                                                          << measured.binding << ", bridge/layout/GpuLayouts.h says "
                                                          << expected.binding;
            EXPECT_EQ(measured.fixedBytes, expected.fixedBytes)
                << label << ": " << kind << " " << name << " has " << measured.fixedBytes
                << " bytes before any runtime-sized array, its C++ mirror " << expected.fixedBytes;
            const auto structured = structuredBlocks().find(name);
            if (structured != structuredBlocks().end())
                members(program, label, interface, i, name, structured->second);
            if (expected.elementBytes == kFloatOrDouble) {
                EXPECT_TRUE(measured.elementBytes == sizeof(float) || measured.elementBytes == sizeof(double))
                    << label << ": " << kind << " " << name << " has an element stride of " << measured.elementBytes
                    << " bytes, not a float's or a double's";
            } else {
                EXPECT_EQ(measured.elementBytes, expected.elementBytes)
                    << label << ": " << kind << " " << name << " has an element stride of " << measured.elementBytes
                    << " bytes, its C++ mirror " << expected.elementBytes;
            }
        }
    }

    // Every member of a block of a GPU struct against the C++ struct and its
    // list: offset, type, array length and stride; and every member of the
    // list declared.
    void members(const gl::Program& program, const std::string& label, GLenum interface, GLuint block,
                 const std::string& blockName, const test::StructuredBlock& rows) {
        const GLenum memberInterface = interface == GL_SHADER_STORAGE_BLOCK ? GL_BUFFER_VARIABLE : GL_UNIFORM;
        std::set<std::string> seen;
        for (const GLint index : activeVariables(program.id(), interface, block)) {
            auto property = [&](GLenum name) {
                return resourceProperty(program.id(), memberInterface, static_cast<GLuint>(index), name);
            };
            std::string path = resourceName(program.id(), memberInterface, static_cast<GLuint>(index));
            if (path.rfind(blockName + ".", 0) == 0) path.erase(0, blockName.size() + 1);
            const auto resolved = test::resolveMember(rows, path, seen);
            if (!resolved) {
                ADD_FAILURE() << label << ": " << blockName << " member " << path << " is in no list of "
                              << rows.structName << " (bridge/layout/GpuLayouts.h)";
                continue;
            }
            const test::ContractMember& expected = *resolved->member;
            EXPECT_EQ(static_cast<std::size_t>(property(GL_OFFSET)), resolved->offset)
                << label << ": " << blockName << " member " << path << " is at byte " << property(GL_OFFSET)
                << ", its C++ member (" << rows.structName << ") at " << resolved->offset;
            EXPECT_EQ(static_cast<GLenum>(property(GL_TYPE)), glTypeOf(expected.glslType))
                << label << ": " << blockName << " member " << path << " is not a " << expected.glslType;
            if (expected.count > 0 && test::nestedStructName(expected.glslType).empty()) {
                EXPECT_EQ(static_cast<std::size_t>(property(GL_ARRAY_SIZE)), expected.count)
                    << label << ": " << blockName << " member " << path << " has another array length";
                EXPECT_EQ(static_cast<std::size_t>(property(GL_ARRAY_STRIDE)), expected.stride)
                    << label << ": " << blockName << " member " << path << " has another array stride";
            }
        }
        for (const auto& [structName, contract] : test::contractStructs()) {
            const bool reached = std::any_of(seen.begin(), seen.end(), [&](const std::string& member) {
                return member.rfind(structName + ".", 0) == 0;
            });
            if (!reached && structName != rows.structName) continue;
            for (const auto& [member, row] : contract.members)
                EXPECT_TRUE(seen.count(structName + "." + member))
                    << label << ": " << blockName << " lacks " << structName << "'s member " << member;
        }
    }

    void opaqueUniforms(const gl::Program& program, const std::string& label) {
        std::map<GLint, std::string> samplerUnits, imageUnits;
        for (GLuint i = 0; i < activeResources(program.id(), GL_UNIFORM); ++i) {
            const auto type = static_cast<GLenum>(resourceProperty(program.id(), GL_UNIFORM, i, GL_TYPE));
            const bool sampler = isSampler(type), image = isImage(type);
            if (!sampler && !image) continue;
            const std::string name = resourceName(program.id(), GL_UNIFORM, i);
            GLint unit = -1;
            glGetUniformiv(program.id(), resourceProperty(program.id(), GL_UNIFORM, i, GL_LOCATION), &unit);
            const char* kind = sampler ? "sampler" : "image";
            noteBinding(sampler ? samplerUnits : imageUnits, unit, name, label, kind);
            const auto& rows = sampler ? samplers() : images();
            const auto row = rows.find(name);
            if (row == rows.end()) {
                ADD_FAILURE() << label << ": " << kind << " " << name << " is not in the contract tables";
                continue;
            }
            seen_.insert(std::string(kind) + " " + name);
            EXPECT_EQ(static_cast<unsigned>(unit), row->second)
                << label << ": " << kind << " " << name << " is at unit " << unit
                << ", bridge/layout/GpuLayouts.h says " << row->second;
        }
    }

private:
    static bool isSampler(GLenum type) {
        static const std::set<GLenum> types = {GL_SAMPLER_1D, GL_SAMPLER_2D, GL_SAMPLER_3D, GL_SAMPLER_CUBE,
                                               GL_SAMPLER_2D_ARRAY, GL_SAMPLER_BUFFER, GL_UNSIGNED_INT_SAMPLER_BUFFER,
                                               GL_INT_SAMPLER_2D,
                                               GL_INT_SAMPLER_3D, GL_UNSIGNED_INT_SAMPLER_2D,
                                               GL_UNSIGNED_INT_SAMPLER_3D};
        return types.count(type) > 0;
    }

    static bool isImage(GLenum type) {
        static const std::set<GLenum> types = {GL_IMAGE_1D, GL_IMAGE_2D, GL_IMAGE_3D, GL_IMAGE_CUBE,
                                               GL_IMAGE_2D_ARRAY, GL_IMAGE_BUFFER, GL_INT_IMAGE_2D,
                                               GL_INT_IMAGE_3D, GL_UNSIGNED_INT_IMAGE_2D,
                                               GL_UNSIGNED_INT_IMAGE_3D};
        return types.count(type) > 0;
    }

    // Two resources of one kind at one binding would read each other's data.
    static void noteBinding(std::map<GLint, std::string>& byBinding, GLint binding, const std::string& name,
                            const std::string& label, const char* kind) {
        const auto [existing, fresh] = byBinding.emplace(binding, name);
        EXPECT_TRUE(fresh) << label << ": " << kind << "s " << existing->second << " and " << name
                           << " share binding " << binding;
    }

    std::set<std::string>& seen_;
};

// Every row of the tables, as ContractCheck notes the ones it meets.
std::set<std::string> tableRows() {
    std::set<std::string> rows;
    for (const auto& [name, row] : uniformBlocks()) rows.insert("uniform block " + name);
    for (const auto& [name, row] : storageBlocks()) rows.insert("shader storage block " + name);
    for (const auto& [name, unit] : samplers()) rows.insert("sampler " + name);
    for (const auto& [name, unit] : images()) rows.insert("image " + name);
    return rows;
}

TEST(GpuContract, EveryProgramBindsWhatGpuLayoutsNames) {
    test::glContext();
    std::set<std::string> seen;
    ContractCheck check(seen);
    for (const Variant& variant : productionVariants()) {
        const gl::Program program =
            variant.fragment.empty() ? gl::compileComputeProgram(variant.shader, variant.defines)
                                     : gl::compileRasterProgram(variant.shader, variant.fragment, variant.defines);
        check.blocks(program, variant.label(), GL_UNIFORM_BLOCK);
        check.blocks(program, variant.label(), GL_SHADER_STORAGE_BLOCK);
        check.opaqueUniforms(program, variant.label());
    }
    // A row no program uses is a stale contract (or a variant missing above).
    for (const std::string& row : tableRows()) EXPECT_TRUE(seen.count(row)) << row << " is used by no program";
}

// What the names are for: a number in a shader would not follow the enum.
TEST(GpuContract, ShadersBindByNameNeverByNumber) {
    static const std::regex numbered(R"(binding\s*=\s*\d)");
    for (const auto& [name, text] : gl::embeddedShaders())
        EXPECT_FALSE(std::regex_search(text.begin(), text.end(), numbered)) << name << " binds by number";
}

TEST(GpuContract, MisspeltUniformIsAnErrorNamingProgramAndUniform) {
    test::glContext();
    const gl::Program program = gl::compileComputeProgram("tonemap.comp");
    EXPECT_GE(program.uniform("exposure_scale"), 0);
    try {
        program.uniform("exposure_scael");
        FAIL() << "a misspelt uniform was accepted";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("tonemap.comp"), std::string::npos) << message;
        EXPECT_NE(message.find("exposure_scael"), std::string::npos) << message;
    }
}

// The generated constants and the prelude come before the shader's own
// text, and an include sits inside it: messages must still name its line.
TEST(GpuContract, CompilerMessagesNameTheShadersOwnLine) {
    test::glContext();
    const char* source =
        "layout(local_size_x = 1) in;\n"
        "#include \"common/random.glsl\"\n"
        "void main() { undeclared_name = 1; }\n";
    try {
        gl::compileComputeProgramFromSource("line_check.comp", source);
        FAIL() << "a broken shader compiled";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("line_check.comp:3"), std::string::npos) << message;
    }
}

// llvmpipe caps the loop iterations of each SIMD vector of invocations,
// all loops together (gl/GlContext.h); the budget a lane may spend
// is 65 535 over its lane count, and no cap elsewhere.
TEST(GpuContract, LoopBudgetKeepsUnderTheDriversCap) {
    EXPECT_EQ(gl::loopBudgetForRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"), 65535u / 8u);
    EXPECT_EQ(gl::loopBudgetForRenderer("llvmpipe (LLVM 15.0.6, 512 bits)"), 65535u / 16u);
    EXPECT_EQ(gl::loopBudgetForRenderer("llvmpipe"), 65535u / 16u) << "unknown width: the widest";
    EXPECT_EQ(gl::loopBudgetForRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"), 0u);
    // Every invocation runs nested loops of 160 000 iterations in all (far
    // past any cap), spending from the budget, and stops where it runs out:
    // its count is then exactly the budget, or all of it where there is no
    // cap, and the mark written after the loops shows it got there.
    test::glContext();
    const unsigned budget = gl::currentLoopBudget();
    const char* source =
        "layout(local_size_x = 64) in;\n"
        "#include \"common/loop_budget.glsl\"\n"
        "layout(std430, binding = 0) buffer Counts { uvec2 counts[]; };\n"
        "void main() {\n"
        "    uint count = 0u;\n"
        "    for (uint outer = 0u; outer < 400u && loops_left(); ++outer)\n"
        "        for (uint inner = 0u; inner < 400u; ++inner) {\n"
        "            spend_loops(1u);\n"
        "            if (!loops_left()) break;\n"
        "            ++count;\n"
        "        }\n"
        "    counts[gl_GlobalInvocationID.x] = uvec2(count, 12345u);\n"
        "}\n";
    const gl::Program program = gl::compileComputeProgramFromSource(
        "loop_budget_check.comp", source, {{"EIKON_LOOP_BUDGET", std::to_string(budget)}});
    constexpr std::size_t kInvocations = 256;
    gl::Buffer counts(kInvocations * sizeof(glm::uvec2));
    counts.bindStorage(0);
    program.dispatchCovering(kInvocations);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::uvec2> result(kInvocations);
    counts.download(result.data(), result.size() * sizeof(glm::uvec2));
    // The budget is spent once more by the iteration that finds it gone.
    const unsigned expected = budget > 0 ? budget - 1 : 160000u;
    for (const glm::uvec2& r : result) {
        ASSERT_EQ(r.y, 12345u) << "the invocation reached its end";
        ASSERT_EQ(r.x, expected);
    }
}

}  // namespace
}  // namespace eikon
