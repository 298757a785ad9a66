// Per-voxel octree level and step cap ([Sun08] §4.2 and §5.3): from
// the coarsest level down, the first node around the voxel whose index range
// is below ε gives the level with no cap; one whose range is below ε′ gives
// the level with the finite cap. Unlike [Sun08], ε and ε′ are fractions of
// the whole field's index range (read off the pyramid's top), so one setting
// serves glass (Δn ≈ 0.5) and hot air (Δn ≈ 1e-4) alike; an absolute ε
// fit for glass would call a whole mirage uniform. Voxels that find neither step by Δs_min —
// where [Sun08] stepped to the voxel's face, up to √3 voxels: in the
// steepest part of an interface that doubled the caustic's error against
// uniform half-voxel steps.
//
// Unlike [Sun08], a node must also hold extinction nearly constant: its κ
// range times its edge must stay below an optical-depth tolerance, because a
// step attenuates by exp(−κ(start)·Δs). Without this bound a step from clear
// air jumps over an absorbing slab: a measured Beer–Lambert error of +45% to
// +550% for κ = 1 to 5 /m, against 0.01% with it.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/octree_levels.glsl"

layout(binding = kPyramidTexture) uniform sampler3D pyramid;  // (min δn, max δn, min κ, max κ) per node, common/octree_levels.glsl
// (level, step cap in m, 1 if the node holds no extinction — hence no
// scattering, so a camera ray may cross it in one step — 0)
layout(rgba32f, binding = kStepImage) writeonly uniform image3D step_structure;

uniform float epsilon;
uniform float epsilon_prime;
uniform float index_scale;  // largest dispersion scale: ranges are of n = n_ref + s·δn
uniform float capped_step;  // metres
uniform float min_step;     // metres, Δs_min
uniform float node_edge;    // metres, level 0
uniform float optical_depth_tolerance;

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    ivec3 cells = imageSize(step_structure);
    if (any(greaterThanEqual(cell, cells))) return;
    vec3 result = vec3(0.0f, min_step, 0.0f);
    int levels = octree_levels(cells);
    ivec3 offset = octree_level_offset(cells, levels - 1);  // of `level` below, from the top down
    vec4 whole = texelFetch(pyramid, offset, 0);
    float field_range = index_scale * (whole.y - whole.x);
    for (int level = levels - 1; level >= 0; --level) {
        vec4 range = texelFetch(pyramid, offset + (cell >> level), 0);
        offset = level > 1 ? offset - ivec3(0, 0, octree_level_size(cells, level - 1).z) : ivec3(0);
        if ((range.w - range.z) * node_edge * exp2(float(level)) >= optical_depth_tolerance) continue;
        float variation = index_scale * (range.y - range.x);
        float empty = range.w <= 0.0f ? 1.0f : 0.0f;
        if (variation <= epsilon * field_range) {
            result = vec3(float(level), 1e30f, empty);
            break;
        }
        if (variation <= epsilon_prime * field_range) {
            result = vec3(float(level), capped_step, empty);
            break;
        }
    }
    imageStore(step_structure, cell, vec4(result, 0.0f));
}
