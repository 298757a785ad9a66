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
//
// Written once for both backends: the compute shader octree_label.comp and
// the native loop (render/stages/NativeStepStructure.cpp) call it. The
// includer gives
//     vec4 pyramid_range(ivec3 texel)  // (min δn, max δn, min κ, max κ), common/octree_levels.glsl's placement
// after common/octree_levels.glsl and common/octree_label_rule.glsl.

// (level, step cap in metres or 1e30 for none, 1 where the node holds no
// extinction — hence no scattering, so a camera ray may cross it in one step).
vec3 octree_label(ivec3 cell, ivec3 cells, OctreeLabelRule rule) {
    vec3 result = vec3(0.0f, rule.min_step, 0.0f);
    int levels = octree_levels(cells);
    ivec3 offset = octree_level_offset(cells, levels - 1);  // of `level` below, from the top down
    vec4 whole = pyramid_range(offset);
    float field_range = rule.index_scale * (whole.y - whole.x);
    for (int level = levels - 1; level >= 0; --level) {
        vec4 range = pyramid_range(offset + (cell >> level));
        offset = level > 1 ? offset - ivec3(0, 0, octree_level_size(cells, level - 1).z) : ivec3(0);
        if ((range.w - range.z) * rule.node_edge * exp2(float(level)) >= rule.optical_depth_tolerance) continue;
        float variation = rule.index_scale * (range.y - range.x);
        float empty = range.w <= 0.0f ? 1.0f : 0.0f;
        if (variation <= rule.epsilon * field_range) {
            result = vec3(float(level), 1e30f, empty);
            break;
        }
        if (variation <= rule.epsilon_prime * field_range) {
            result = vec3(float(level), rule.capped_step, empty);
            break;
        }
    }
    return result;
}
