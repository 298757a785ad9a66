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

// A cell's corner: where its photon landed, if on receiver r through surface s.
bool lands_with(CausticVertex v, int r, int s) { return v.receiver == r && v.surface == s; }

// The area of the triangle between three landings, in texels of receiver r.
float texels_between(vec2 a, vec2 b, vec2 c, int r) {
    vec2 ab = b - a, ac = c - a;
    float edge = float(receivers[r].map.y);
    return 0.5f * abs(ab.x * ac.y - ab.y * ac.x) * edge * edge;
}

// A CPU rasterizer runs every call site of a shader under a mask, whether
// its lanes take it or not, so the cell's splats and triangles are listed
// first and then deposited from one call site each.
void main() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    int sheet = int(gl_GlobalInvocationID.z);
    if (any(greaterThanEqual(cell, layer_size - 1))) return;
    uint first = uint(cell.y * layer_size.x + cell.x);
    CausticVertex corner[4] = CausticVertex[4](
        read_caustic_vertex(first, sheet), read_caustic_vertex(first + 1u, sheet),
        read_caustic_vertex(first + uint(layer_size.x) + 1u, sheet), read_caustic_vertex(first + uint(layer_size.x), sheet));
    int r = corner[0].receiver;
    bool smooth_map = r >= 0;
    for (int k = 1; k < 4; ++k) smooth_map = smooth_map && lands_with(corner[k], r, corner[0].surface);
    // The two triangles (corners 0 1 2 and 0 2 3), each with half the cell's power.
    vec3 half_watts = 0.125f * (corner[0].watts + corner[1].watts + corner[2].watts + corner[3].watts);
    float texels[2] = float[2](0.0f, 0.0f);
    bool drawn[2] = bool[2](false, false);
    for (int t = 0; t < 2 && smooth_map; ++t) {
        texels[t] = texels_between(corner[0].map_uv, corner[t + 1].map_uv, corner[t + 2].map_uv, r);
        drawn[t] = texels[t] >= kSmallestDrawnTexels;
    }
    // The splats: a corner's quarter each (no smooth map), the whole cell
    // within about a texel at once, or a small triangle at its centroid.
    int splats = 0;
    int splat_receiver[4];
    vec2 splat_uv[4];
    vec3 splat_watts[4];
    if (!smooth_map) {
        for (int k = 0; k < 4; ++k)
            if (corner[k].receiver >= 0) {
                splat_receiver[splats] = corner[k].receiver;
                splat_uv[splats] = corner[k].map_uv;
                splat_watts[splats++] = 0.25f * corner[k].watts;
            }
    } else if (!drawn[0] && !drawn[1]) {
        splat_receiver[0] = r;
        splat_uv[0] = 0.25f * (corner[0].map_uv + corner[1].map_uv + corner[2].map_uv + corner[3].map_uv);
        splat_watts[0] = 2.0f * half_watts;
        splats = 1;
    } else {
        for (int t = 0; t < 2; ++t)
            if (!drawn[t]) {
                splat_receiver[splats] = r;
                splat_uv[splats] = (corner[0].map_uv + corner[t + 1].map_uv + corner[t + 2].map_uv) / 3.0f;
                splat_watts[splats++] = half_watts;
            }
    }
    for (int k = 0; k < splats; ++k) splat_at(splat_receiver[k], splat_uv[k], splat_watts[k]);
    for (int t = 0; t < 2; ++t) {
        if (!drawn[t]) continue;
        // One atomic per triangle: llvmpipe runs a work group's barriers so
        // slowly that counting per group first cost more than the whole pass.
        uint slot = 3u * (atomicAdd(caustic_draw.x, 3u) / 3u);
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
