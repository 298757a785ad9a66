// Per-voxel octree level and step cap (common/octree_labels.glsl) from the
// min/max pyramid (octree_minmax.comp).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/octree_levels.glsl"

layout(binding = kPyramidTexture) uniform sampler3D pyramid;  // (min δn, max δn, min κ, max κ) per node, common/octree_levels.glsl
// (level, step cap in m, 1 if the node holds no extinction — hence no
// scattering, so a camera ray may cross it in one step — 0)
layout(rgba32f, binding = kStepImage) writeonly uniform image3D step_structure;

vec4 pyramid_range(ivec3 texel) { return texelFetch(pyramid, texel, 0); }

#include "common/octree_label_rule.glsl"
#include "common/octree_labels.glsl"

uniform OctreeLabelRule rule;

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    ivec3 cells = imageSize(step_structure);
    if (any(greaterThanEqual(cell, cells))) return;
    imageStore(step_structure, cell, vec4(octree_label(cell, cells, rule), 0.0f));
}
