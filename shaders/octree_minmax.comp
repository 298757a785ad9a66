// Min/max pyramid ([Sun08] §4.2) over the grid's own nodes, one level per
// dispatch (common/octree_ranges.glsl), all levels in one texture
// (common/octree_levels.glsl), which this pass reads (finer_level) and
// writes (this_level) through two image units. An emitting voxel counts as
// holding extinction (a vanishing 1e-30 /m at least), so that no camera ray
// crosses its glow in one jump (octree_label: such a node is not empty).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/octree_levels.glsl"

#ifndef EIKON_HAS_EXTINCTION
#define EIKON_HAS_EXTINCTION 0
#endif
#ifndef EIKON_HAS_EMISSION
#define EIKON_HAS_EMISSION 0
#endif

layout(binding = kIndexTexture) uniform sampler3D index_texture;  // r: smoothed δn (level 0 input)
#if EIKON_HAS_EXTINCTION
layout(binding = kExtinctionTexture) uniform sampler3D extinction_texture;  // rgb: κ (level 0 input)
#endif
#if EIKON_HAS_EMISSION
layout(binding = kEmissionTexture) uniform sampler3D emission_texture;  // rgb: ε (level 0 input)
#endif
layout(rgba32f, binding = kFinerLevelImage) readonly uniform image3D finer_level;  // the pyramid: level k − 1 (k > 0)
layout(rgba32f, binding = kPyramidLevelImage) writeonly uniform image3D this_level;  // the pyramid: level k

uniform int level;

float range_index(ivec3 cell) { return texelFetch(index_texture, cell, 0).r; }

float range_extinction(ivec3 cell) {
#if EIKON_HAS_EXTINCTION
    vec3 kappa3 = texelFetch(extinction_texture, cell, 0).rgb;
    float kappa = max(kappa3.r, max(kappa3.g, kappa3.b));
#else
    float kappa = 0.0f;
#endif
#if EIKON_HAS_EMISSION
    vec3 glow = texelFetch(emission_texture, cell, 0).rgb;
    if (max(glow.r, max(glow.g, glow.b)) > 0.0f) kappa = max(kappa, 1e-30f);
#endif
    return kappa;
}

vec4 finer_range(ivec3 texel) { return imageLoad(finer_level, texel); }

#include "common/octree_ranges.glsl"

void main() {
    ivec3 node = ivec3(gl_GlobalInvocationID);
    ivec3 cells = textureSize(index_texture, 0);
    if (any(greaterThanEqual(node, octree_level_size(cells, level)))) return;
    imageStore(this_level, octree_level_offset(cells, level) + node, node_range(node, cells, level));
}
