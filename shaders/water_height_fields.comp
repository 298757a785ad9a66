// The water bodies' node grids for image space (render/stages/
// WaterHeightFields.h; read by common/water_height_fields.glsl), gathered
// from the sharp surfaces' triangles as the field buffers carry them this
// frame (bridge/grid/FieldSet.h), so that the grids hold the very corners
// and corner normals the tracers and the raster pipeline read.
//   EIKON_PASS 0, per triangle: a water body's surface triangle (all
//     three corners above its basin's bottom; the walls' and the bottom's
//     reach down to it) writes each corner's (normal, y) to its node. A
//     node's triangles agree on its normal: they are the surface's, within
//     the crease angle of one another.
//   EIKON_PASS 1, kCellGroups work groups per body, each invocation over a
//     share of its cells: the lowest and highest node and the steepest
//     slope (|∇y| of a triangle's plane) among them, into its body's slab
//     by three atomics (one per triangle cost llvmpipe, which runs
//     atomics a lane at a time, two thirds of the gather).
//   EIKON_PASS 2, per body: the slab's lowest and highest y and the
//     steepest slope, into the texel before its nodes.
layout(local_size_x = 64) in;

layout(std430, binding = kWaterNodeGrids) buffer WaterNodeGrids { vec4 water_nodes[]; };
// Per body, ordered bits of (lowest y, highest y, steepest slope, unused).
layout(std430, binding = kWaterSlabs) buffer WaterSlabs { uvec4 water_slabs[]; };

#include "common/water_height_fields.glsl"

// Float bits in an order that unsigned comparison keeps.
uint ordered_bits(float f) {
    uint bits = floatBitsToUint(f);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

float float_of_ordered_bits(uint bits) {
    return uintBitsToFloat((bits & 0x80000000u) != 0u ? bits & 0x7fffffffu : ~bits);
}

#if EIKON_PASS == 0
layout(binding = kSurfaceTriangleTexture) uniform samplerBuffer surface_triangle_texels;
uniform int triangle_count;
uniform int water_of_ordinal[kMaxSharpObjects];  // a mesh's ordinal in w → its water body, or −1

void main() {
    int triangle = int(gl_GlobalInvocationID.x);
    if (triangle >= triangle_count) return;
    vec4 first = texelFetch(surface_triangle_texels, 6 * triangle);
    int water = water_of_ordinal[int(first.w + 0.5f)];
    if (water < 0) return;
    WaterBody body = water_bodies[water];
    vec3 corners[3] = vec3[3](first.xyz, texelFetch(surface_triangle_texels, 6 * triangle + 1).xyz,
                              texelFetch(surface_triangle_texels, 6 * triangle + 2).xyz);
    for (int c = 0; c < 3; ++c)
        if (!(corners[c].y > body.low.y)) return;  // a wall's or the bottom's
    vec2 spacing = water_spacing(body);
    for (int c = 0; c < 3; ++c) {
        ivec2 node = clamp(ivec2(round((corners[c].xz - body.low.xz) / spacing)), ivec2(0), body.grid.xy - 1);
        vec3 normal = texelFetch(surface_triangle_texels, 6 * triangle + 3 + c).xyz;
        water_nodes[body.grid.z + node.y * body.grid.x + node.x] = vec4(normal, corners[c].y);
    }
}
#elif EIKON_PASS == 1
void main() {
    int water = int(gl_WorkGroupID.y);
    WaterBody body = water_bodies[water];
    int cells = (body.grid.x - 1) * (body.grid.y - 1);
    int invocations = int(gl_NumWorkGroups.x * gl_WorkGroupSize.x);
    vec2 spacing = water_spacing(body);
    float lowest = 1e30f, highest = -1e30f, steepest = 0.0f;
    for (int c = int(gl_GlobalInvocationID.x); c < cells; c += invocations) {
        ivec2 cell = ivec2(c % (body.grid.x - 1), c / (body.grid.x - 1));
        WaterCell surface = water_cell(body, cell);
        vec4 h = surface.heights;
        lowest = min(lowest, min(min(h.x, h.y), min(h.z, h.w)));
        highest = max(highest, max(max(h.x, h.y), max(h.z, h.w)));
        steepest = max(steepest, length(surface.upper_slope / spacing));
        steepest = max(steepest, length(surface.lower_slope / spacing));
    }
    if (lowest > highest) return;  // no cells of its own
    atomicMin(water_slabs[water].x, ordered_bits(lowest));
    atomicMax(water_slabs[water].y, ordered_bits(highest));
    atomicMax(water_slabs[water].z, ordered_bits(steepest));
}
#else
uniform int body_count;

void main() {
    int water = int(gl_GlobalInvocationID.x);
    if (water >= body_count) return;
    uvec4 slab = water_slabs[water];
    water_nodes[water_bodies[water].grid.z - 1] =
        vec4(float_of_ordered_bits(slab.x), float_of_ordered_bits(slab.y), float_of_ordered_bits(slab.z), 0.0f);
}
#endif
