#include "render/stages/WaterHeightFields.h"

#include "bridge/grid/FieldSet.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <string>

namespace eikon::render {

namespace {

bool isWaterBody(const ObjectDesc& object) { return object.isSharp() && object.kind == ObjectDesc::Kind::Water; }

// Work groups per body that share its cells out in pass 1 of water_height_fields.comp.
constexpr GLuint kCellGroups = 16;

}  // namespace

std::vector<int> WaterHeightFields::waterOfSurface(const Scene& scene) {
    std::vector<int> water;
    int bodies = 0;
    for (const ObjectDesc& object : scene.objects)
        if (object.isSharp()) water.push_back(isWaterBody(object) ? bodies++ : -1);
    return water;
}

std::vector<int> WaterHeightFields::surfaceOfWater(const Scene& scene) {
    const std::vector<int> water = waterOfSurface(scene);
    std::vector<int> surfaces;
    for (std::size_t surface = 0; surface < water.size(); ++surface)
        if (water[surface] >= 0) surfaces.push_back(static_cast<int>(surface));
    return surfaces;
}

bool WaterHeightFields::hasLayerSurfaces(const Scene& scene) {
    return std::any_of(scene.objects.begin(), scene.objects.end(),
                       [](const ObjectDesc& object) { return object.isSharp() && !isWaterBody(object); });
}

gl::ShaderDefines WaterHeightFields::programOptions(const Scene& scene) {
    const auto bodies = std::count_if(scene.objects.begin(), scene.objects.end(), isWaterBody);
    return {{"EIKON_WATER_BODIES", std::to_string(bodies)},
            {"EIKON_LAYER_SURFACES", hasLayerSurfaces(scene) ? "1" : "0"},
            {"EIKON_SHARP_SURFACES", std::to_string(waterOfSurface(scene).size())}};
}

WaterHeightFields::WaterHeightFields(const Scene& scene) {
    std::vector<layout::GpuWaterHeightField> bodies;
    const std::vector<int> surfaceOfBody = surfaceOfWater(scene);
    int texels = 0;
    for (const ObjectDesc& object : scene.objects) {
        if (!object.hasTriangleSurface()) continue;
        if (!isWaterBody(object)) {
            waterOfOrdinal_.push_back(-1);
            continue;
        }
        waterOfOrdinal_.push_back(static_cast<int>(bodies.size()));
        const WaterDesc& water = object.water;
        ++texels;  // its slab
        bodies.push_back({glm::vec4(glm::vec3(water.basinMin), 0.0f), glm::vec4(glm::vec3(water.basinMax), 0.0f),
                          glm::ivec4(water.cells.x, water.cells.y, texels, surfaceOfBody.at(bodies.size()))});
        texels += water.cells.x * water.cells.y;
    }
    bodies_ = static_cast<int>(bodies.size());
    if (bodies.empty()) return;
    waterOfOrdinal_.resize(layout::kMaxSharpObjects, -1);
    bodies.resize(layout::kMaxSharpObjects, layout::GpuWaterHeightField{});
    block_ = gl::Buffer(bodies.size() * sizeof(layout::GpuWaterHeightField), bodies.data(), GL_DYNAMIC_STORAGE_BIT,
                        {"objects", "the water bodies"});
    nodes_ = gl::Buffer(static_cast<std::size_t>(texels) * sizeof(glm::vec4), {"objects[].cells", "the water's node grids"});
    nodeTexels_ = gl::BufferTexture(nodes_, GL_RGBA32F, {"objects[].cells", "the water's node grids"});
    slabs_ = gl::Buffer(static_cast<std::size_t>(bodies_) * sizeof(glm::uvec4), {"objects", "the water's slabs"});
    gatherProgram_ = gl::compileComputeProgram("water_height_fields.comp", {{"EIKON_PASS", "0"}});
    cellProgram_ = gl::compileComputeProgram("water_height_fields.comp", {{"EIKON_PASS", "1"}});
    slabProgram_ = gl::compileComputeProgram("water_height_fields.comp", {{"EIKON_PASS", "2"}});
}

void WaterHeightFields::update(const FieldTextures& fields) {
    if (empty() || (gathered_ && fields.surfaceVersion() == version_)) return;
    gathered_ = true;
    version_ = fields.surfaceVersion();
    // The slabs start empty: lowest at the ordered bits' top, highest and steepest at their bottom.
    const std::vector<glm::uvec4> emptySlabs(static_cast<std::size_t>(bodies_), glm::uvec4(0xffffffffu, 0u, 0u, 0u));
    slabs_.upload(emptySlabs.data(), emptySlabs.size() * sizeof(glm::uvec4));
    block_.bindUniform(layout::kWaterBodies);
    nodes_.bindStorage(layout::kWaterNodeGrids);
    slabs_.bindStorage(layout::kWaterSlabs);
    fields.surfaceTriangleTexels().bindSampler(layout::kSurfaceTriangleTexture);
    const auto triangles = static_cast<int>(surfaceTrianglesIn(fields.surfaceTriangles().bytes()));
    gatherProgram_.use();
    glUniform1i(gatherProgram_.uniform("triangle_count"), triangles);
    glUniform1iv(gatherProgram_.uniform("water_of_ordinal"), layout::kMaxSharpObjects, waterOfOrdinal_.data());
    gatherProgram_.dispatchCovering(static_cast<std::size_t>(triangles));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the cells read the nodes as texels
    nodeTexels_.bindSampler(layout::kWaterNodeTexture);
    cellProgram_.use();
    cellProgram_.dispatchGroups(kCellGroups, static_cast<GLuint>(bodies_));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    slabProgram_.use();
    glUniform1i(slabProgram_.uniform("body_count"), bodies_);
    slabProgram_.dispatchCovering(static_cast<std::size_t>(bodies_));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkpoint("water height fields");
}

void WaterHeightFields::bind() const {
    if (empty()) return;
    block_.bindUniform(layout::kWaterBodies);
    nodeTexels_.bindSampler(layout::kWaterNodeTexture);
}

}  // namespace eikon::render
