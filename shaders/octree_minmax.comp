// Min/max pyramid ([Sun08] §4.2), like a mipmap whose texels hold
// (min δn, max δn, min κ, max κ) with κ the largest extinction channel,
// over the grid's own nodes: level k of ⌈cells/2^k⌉ along each axis, all
// levels in one texture (common/octree_levels.glsl), which this pass reads
// (finer_level) and writes (this_level) through two image units.
// Level 0 takes each voxel's 3×3×3 neighbourhood, the cells trilinear
// interpolation mixes anywhere inside it; level k > 0 reduces the 2×2×2
// children of level k − 1 that exist (a last node along an odd side has one
// child along it). An emitting voxel counts as holding extinction (a
// vanishing 1e-30 /m at least), so that no camera ray crosses its glow in one
// jump (octree_label: such a node is not empty).
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

vec4 merged(vec4 a, vec4 b) {
    return vec4(min(a.x, b.x), max(a.y, b.y), min(a.z, b.z), max(a.w, b.w));
}

void main() {
    ivec3 node = ivec3(gl_GlobalInvocationID);
    ivec3 cells = textureSize(index_texture, 0);
    if (any(greaterThanEqual(node, octree_level_size(cells, level)))) return;
    vec4 range = vec4(1e30f, -1e30f, 1e30f, -1e30f);
    if (level == 0) {
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    ivec3 cell = clamp(node + ivec3(dx, dy, dz), ivec3(0), cells - 1);
                    float index = texelFetch(index_texture, cell, 0).r;
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
                    range = merged(range, vec4(index, index, kappa, kappa));
                }
    } else {
        ivec3 finer = octree_level_size(cells, level - 1);
        ivec3 finer_offset = octree_level_offset(cells, level - 1);
        for (int child = 0; child < 8; ++child) {
            ivec3 c = 2 * node + ivec3(child & 1, (child >> 1) & 1, (child >> 2) & 1);
            if (any(greaterThanEqual(c, finer))) continue;
            range = merged(range, imageLoad(finer_level, finer_offset + c));
        }
    }
    imageStore(this_level, octree_level_offset(cells, level) + node, range);
}
