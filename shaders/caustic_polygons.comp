// Caustic polygons (render/stages/CausticPolygons.h): the photons of a
// light's caustic map (common/caustic_vertices.glsl) sample a smooth map from
// the light's texel grid to the receivers, so the power between four
// neighbouring photons lands spread over the quadrilateral between their
// landings ([Wyman06] §3.2.1, Fig. 5: caustic polygons joining adjacent
// photons of the light-space buffer, after Watt's beam tracing). Each cell carries
// a quarter of each corner's power, split between its two triangles; a
// triangle covering a quarter of a receiver texel or more is drawn
// (caustic_polygons.vert/.frag) with its irradiance, power over landing
// area; a smaller one lands at its centroid as a bilinear splat (the whole
// cell at once where both are small). A cell
// whose corners do not all land on one receiver, through one surface, is no
// smooth map (the paper culls such polygons or draws them anyway): each
// corner that lands splats its quarter where it lands, so no power is lost.
//
// Program options: EIKON_PASS (0: one invocation per grid cell and sheet,
// listing the triangles to draw; 1: one per receiver texel, adding the
// drawn triangles' atlas to the tallies).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/wide_units.glsl"
#include "common/caustic_deposits.glsl"

#if EIKON_PASS == 0
#include "common/caustic_vertices.glsl"

layout(std430, binding = kCausticTriangles) writeonly buffer CausticTriangles {
    vec4 caustic_triangles[];  // per triangle: (uv a, uv b), (uv c, receiver, 0), (W per receiver texel rgb, 0)
};
layout(std430, binding = kCausticDraw) buffer CausticDraw {
    uvec4 caustic_draw;  // glDrawArraysIndirect's (count, instances, first, base instance)
};

uniform ivec2 layer_size;

// Triangles landing on less of a receiver texel than this are splatted: the
// raster pipeline samples coverage at texel centres, which a swarm of tiny
// triangles at a caustic's focus can all miss (the default scene's peak
// then falls to 0.6 of the reference), while drawing every larger one keeps
// a uniform beam flat (CausticPolygons.CarryAUniformBeamThroughASlabUniformly).
const float kSmallestDrawnTexels = 0.25f;

shared uint group_triangles;  // this work group's triangles to draw
shared uint group_first;      // where they go in the list

void main() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    int sheet = int(gl_GlobalInvocationID.z);
    bool inside_grid = all(lessThan(cell, layer_size - 1));
    CausticVertex corner[4];
    bool smooth_map = inside_grid;
    if (inside_grid) {
        const ivec2 offsets[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
        for (int k = 0; k < 4; ++k) {
            ivec2 t = cell + offsets[k];
            corner[k] = read_caustic_vertex(uint(t.y * layer_size.x + t.x), sheet);
        }
        for (int k = 0; k < 4; ++k)
            smooth_map = smooth_map && corner[k].receiver >= 0 && corner[k].receiver == corner[0].receiver &&
                         corner[k].surface == corner[0].surface;
        if (!smooth_map)
            for (int k = 0; k < 4; ++k)
                if (corner[k].receiver >= 0) splat_at(corner[k].receiver, corner[k].map_uv, 0.25f * corner[k].watts);
    }
    // The two triangles (corners 0 1 2 and 0 2 3), each with half the cell's power.
    int r = smooth_map ? corner[0].receiver : 0;
    vec3 half_watts = smooth_map ? 0.125f * (corner[0].watts + corner[1].watts + corner[2].watts + corner[3].watts)
                                 : vec3(0.0f);
    bool drawn[2] = bool[2](false, false);
    float texels[2] = float[2](0.0f, 0.0f);
    for (int t = 0; t < 2 && smooth_map; ++t) {
        vec2 ab = corner[t + 1].map_uv - corner[0].map_uv, ac = corner[t + 2].map_uv - corner[0].map_uv;
        texels[t] = 0.5f * abs(ab.x * ac.y - ab.y * ac.x) * float(receivers[r].map.y * receivers[r].map.y);
        drawn[t] = texels[t] >= kSmallestDrawnTexels;
    }
    if (smooth_map && !drawn[0] && !drawn[1]) {  // the whole cell within about a texel: one splat
        splat_at(r, 0.25f * (corner[0].map_uv + corner[1].map_uv + corner[2].map_uv + corner[3].map_uv), 2.0f * half_watts);
    } else {
        for (int t = 0; t < 2 && smooth_map; ++t)
            if (!drawn[t]) splat_at(r, (corner[0].map_uv + corner[t + 1].map_uv + corner[t + 2].map_uv) / 3.0f, half_watts);
    }
    // One atomic on the list's count per work group (llvmpipe serialises them).
    if (gl_LocalInvocationIndex == 0u) group_triangles = 0u;
    barrier();
    uint local_slot[2] = uint[2](0u, 0u);
    for (int t = 0; t < 2; ++t)
        if (drawn[t]) local_slot[t] = atomicAdd(group_triangles, 1u);
    barrier();
    if (gl_LocalInvocationIndex == 0u && group_triangles > 0u) group_first = atomicAdd(caustic_draw.x, 3u * group_triangles) / 3u;
    barrier();
    for (int t = 0; t < 2; ++t) {
        if (!drawn[t]) continue;
        uint slot = 3u * (group_first + local_slot[t]);
        caustic_triangles[slot] = vec4(corner[0].map_uv, corner[t + 1].map_uv);
        caustic_triangles[slot + 1u] = vec4(corner[t + 2].map_uv, float(r), 0.0f);
        caustic_triangles[slot + 2u] = vec4(half_watts / texels[t], 0.0f);
    }
}
#else
#include "common/caustic_atlas.glsl"

layout(binding = kCausticAtlasTexture) uniform sampler2D caustic_atlas;

uniform uint texel_count;  // receiver texels in all

void main() {
    int r;
    ivec2 texel;
    if (!receiver_texel_of(gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x + gl_GlobalInvocationID.x,
                           texel_count, r, texel))
        return;
    deposit_texel(r, texel, texelFetch(caustic_atlas, texel + ivec2(0, atlas_row(r)), 0).rgb);
}
#endif
