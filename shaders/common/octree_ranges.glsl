// One node of the min/max pyramid ([Sun08] §4.2), like a mipmap whose
// texels hold (min δn, max δn, min κ, max κ), κ the largest extinction
// channel: level 0 takes each voxel's 3×3×3 neighbourhood, the cells
// trilinear interpolation mixes anywhere inside it; level k > 0 reduces the
// 2×2×2 children of level k − 1 that exist (a last node along an odd side
// has one child along it). Written once for both backends: the compute
// shader octree_minmax.comp and the native loop
// (render/stages/NativeStepStructure.cpp) call it; the pyramid's placement
// is common/octree_levels.glsl's. The includer gives
//     float range_index(ivec3 cell)       // smoothed δn, cell inside the grid
//     float range_extinction(ivec3 cell)  // largest κ channel there (0 without extinction;
//                                         // at least 1e-30 where the voxel glows)
//     vec4 finer_range(ivec3 texel)       // the pyramid texel of a node of the level below

vec4 merged_range(vec4 a, vec4 b) {
    return vec4(min(a.x, b.x), max(a.y, b.y), min(a.z, b.z), max(a.w, b.w));
}

vec4 leaf_range(ivec3 node, ivec3 cells) {
    vec4 range = vec4(1e30f, -1e30f, 1e30f, -1e30f);
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                ivec3 cell = clamp(node + ivec3(dx, dy, dz), ivec3(0), cells - 1);
                float index = range_index(cell);
                float kappa = range_extinction(cell);
                range = merged_range(range, vec4(index, index, kappa, kappa));
            }
    return range;
}

vec4 node_range(ivec3 node, ivec3 cells, int level) {
    if (level == 0) return leaf_range(node, cells);
    vec4 range = vec4(1e30f, -1e30f, 1e30f, -1e30f);
    ivec3 finer = octree_level_size(cells, level - 1);
    ivec3 finer_offset = octree_level_offset(cells, level - 1);
    for (int child = 0; child < 8; ++child) {
        ivec3 c = 2 * node + ivec3(child & 1, (child >> 1) & 1, (child >> 2) & 1);
        if (any(greaterThanEqual(c, finer))) continue;
        range = merged_range(range, finer_range(finer_offset + c));
    }
    return range;
}
