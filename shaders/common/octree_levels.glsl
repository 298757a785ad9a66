// The octree of [Sun08] §4.2 over a grid of `cells` voxels, unpadded: level
// k has ⌈cells/2^k⌉ nodes along each axis, node n spanning the voxels
// [n·2^k, (n + 1)·2^k) (so a node sits where it would in an octree padded to
// a cube of 2^k, and common/step_size.glsl's node geometry holds), up to the
// level whose one node spans every axis. Its min/max pyramid is one texture:
// level 0 at the origin, the levels k ≥ 1 beside it along x, stacked along
// z — about 1.5 times the grid's cells, where a cube of 2^k around a
// 16×96×200 grid held 55 times as many. Shared by GLSL (octree_minmax.comp,
// octree_label.comp) and C++ (cpp_shim.h; StepStructureStage, MemoryEstimate).

int octree_levels(ivec3 cells) {
    int largest = max(cells.x, max(cells.y, cells.z));
    int levels = 1;
    while ((1 << (levels - 1)) < largest) ++levels;
    return levels;
}

ivec3 octree_level_size(ivec3 cells, int level) {
    return (cells + ivec3((1 << level) - 1)) >> level;
}

// Where level `level`'s nodes begin in the pyramid texture.
ivec3 octree_level_offset(ivec3 cells, int level) {
    if (level == 0) return ivec3(0);
    int z = 0;
    for (int k = 1; k < level; ++k) z += octree_level_size(cells, k).z;
    return ivec3(cells.x, 0, z);
}

ivec3 octree_pyramid_size(ivec3 cells) {
    int levels = octree_levels(cells);
    if (levels == 1) return cells;
    int depth = octree_level_offset(cells, levels - 1).z + octree_level_size(cells, levels - 1).z;
    return ivec3(cells.x + octree_level_size(cells, 1).x, cells.y, max(cells.z, depth));
}
