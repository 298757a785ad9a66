// The scene's water bodies as height fields for image space (read by
// shaders/common/water_height_fields.glsl): per body, the node grid of its
// surface — each node's y and corner normal — and the slab between its
// lowest and highest node, gathered each frame on the GPU from the
// triangles the field buffers carry (shaders/water_height_fields.comp).
// A ray inside the water then finds where it leaves by walking the few
// cells of that slab it crosses, exactly on the surface's triangles,
// instead of marching through a viewpoint's layers.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/FieldTextures.h"

#include <cstdint>
#include <vector>

namespace eikon::render {

class WaterHeightFields {
public:
    explicit WaterHeightFields(const Scene& scene);

    // The program options of passes that follow rays through the sharp
    // surfaces (shaders/common/refractor_paths.glsl): EIKON_WATER_BODIES,
    // how many; EIKON_LAYER_SURFACES, 1 where other sharp surfaces are;
    // EIKON_SHARP_SURFACES, how many sharp surfaces in all.
    static gl::ShaderDefines programOptions(const Scene& scene);
    // Whether a sharp surface other than water is there, whose exits are
    // searched in a viewpoint's layers (the programs then read its
    // view_projection).
    static bool hasLayerSurfaces(const Scene& scene);
    // The water body of each sharp surface in scene order, or −1.
    static std::vector<int> waterOfSurface(const Scene& scene);
    // The sharp surface number of each water body, in body order.
    static std::vector<int> surfaceOfWater(const Scene& scene);

    bool empty() const { return bodies_ == 0; }
    // Gathers the grids from `fields`' surface triangles, where they changed since.
    void update(const FieldTextures& fields);
    // The bodies (kWaterBodies) and their grids (kWaterNodeTexture).
    void bind() const;

private:
    int bodies_ = 0;
    std::vector<int> waterOfOrdinal_;  // a mesh's ordinal among the sharp meshes → its water body, or −1
    gl::Buffer block_, nodes_, slabs_;
    gl::BufferTexture nodeTexels_;
    gl::Program gatherProgram_, cellProgram_, slabProgram_;  // water_height_fields.comp's passes 0, 1, 2
    std::uint64_t version_ = 0;
    bool gathered_ = false;
};

}  // namespace eikon::render
