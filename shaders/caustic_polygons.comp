// Caustic polygons (render/stages/CausticPolygons.h): the photons of a
// light's caustic map (common/caustic_vertices.glsl) sample a smooth map from
// the light's texel grid to the receivers, so the power between four
// neighbouring photons lands spread over the quadrilateral between their
// landings ([Wyman06] §3.2.1, Fig. 5: caustic polygons joining adjacent
// photons of the light-space buffer, after Watt's beam tracing). Each cell
// carries a quarter of each corner's power, split between its two
// triangles. Where its four photons left through one surface, the cell is
// drawn on each receiver one of them lands on: all four flights are met
// with that receiver's plane, and the triangles, clipped to its square
// (caustic_polygons.vert), carry their irradiance, power over landing area,
// so a cell across two receivers' seam or a square's edge lands on each in
// proportion. A triangle on less than a quarter of a texel is splatted at
// its centroid instead (the whole cell at once where both are), when that
// lies on the square. On a refractor's silhouette, where one corner's texel
// shows no surface, the triangle of the other three carries their
// quarters. A cell whose photons left through different surfaces, or with
// two or more corners on no surface, or whose flight cannot reach a plane,
// is no smooth map (the paper culls such polygons or draws them anyway):
// each corner that lands splats its quarter where it lands, so no power is
// lost. Where two
// receivers face each other, a cell drawn on both is not shadowed by
// either.
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

// The area of the triangle between three map points, in texels of receiver r.
float texels_between(vec2 a, vec2 b, vec2 c, int r) {
    vec2 ab = b - a, ac = c - a;
    float edge = float(receivers[r].map.y);
    return 0.5f * abs(ab.x * ac.y - ab.y * ac.x) * edge * edge;
}

bool on_square(vec2 map_uv) { return all(greaterThanEqual(map_uv, vec2(0.0f))) && all(lessThan(map_uv, vec2(1.0f))); }

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
    // The corners whose light texel shows a surface, all the same one for a
    // smooth map; a cell on a refractor's silhouette keeps the triangle of
    // its three that do (corners k + 1, k + 2, k + 3 around the missing k).
    int shown = 0, missing = 0;
    bool one_surface = true;
    int surface = -1;
    for (int k = 0; k < 4; ++k) {
        if (corner[k].surface < 0) {
            missing = k;
            continue;
        }
        one_surface = one_surface && (surface < 0 || corner[k].surface == surface);
        surface = corner[k].surface;
        ++shown;
    }
    // The receivers the cell's photons land on, each once (corner k's: target[own[k]]).
    int targets = 0;
    int target[4];
    int own[4];
    for (int k = 0; k < 4; ++k) {
        own[k] = -1;
        for (int q = 0; q < targets; ++q)
            if (target[q] == corner[k].receiver) own[k] = q;
        if (corner[k].receiver >= 0 && own[k] < 0) {
            own[k] = targets;
            target[targets++] = corner[k].receiver;
        }
    }
    // Every flight met with every such receiver's plane (one call site: a
    // CPU rasterizer runs each under a mask, taken or not).
    vec2 uvs[4][4];  // [target][corner]
    bool reached = true;
    for (int q = 0; q < targets; ++q) {
        ReceiverPlane plane = receiver_plane(target[q]);
        for (int k = 0; k < 4; ++k)
            reached = (flight_on_plane(corner[k], plane, uvs[q][k]) || corner[k].surface < 0) && reached;
    }
    bool smooth_map = one_surface && shown >= 3 && targets > 0 && reached;
    // Its triangles: corners 0 1 2 and 0 2 3 with half the cell's power
    // each, or on a silhouette the three shown with their quarters.
    int triangles = shown == 4 ? 2 : 1;
    ivec3 triangle[2] = ivec3[2](shown == 4 ? ivec3(0, 1, 2) : (ivec3(1, 2, 3) + missing) % 4, ivec3(0, 2, 3));
    vec3 all_watts = corner[0].watts + corner[1].watts + corner[2].watts + corner[3].watts;
    vec3 triangle_watts = shown == 4 ? 0.125f * all_watts : 0.25f * all_watts;  // a missing corner carries none
    // The splats, deposited from one call site after the triangles.
    int splats = 0;
    int splat_receiver[8];  // up to two per receiver
    vec2 splat_uv[8];
    vec3 splat_watts[8];
    for (int k = 0; k < 4 && !smooth_map; ++k) {  // no smooth map: a corner's quarter each, where it lands
        if (own[k] < 0) continue;
        splat_receiver[splats] = corner[k].receiver;
        splat_uv[splats] = uvs[own[k]][k];
        splat_watts[splats++] = 0.25f * corner[k].watts;
    }
    for (int q = 0; q < (smooth_map ? targets : 0); ++q) {
        int r = target[q];
        float texels[2];
        for (int t = 0; t < triangles; ++t)
            texels[t] = texels_between(uvs[q][triangle[t].x], uvs[q][triangle[t].y], uvs[q][triangle[t].z], r);
        bool whole_cell = triangles == 2 && texels[0] < kSmallestDrawnTexels && texels[1] < kSmallestDrawnTexels;
        for (int t = 0; t < (whole_cell ? 1 : triangles); ++t) {
            vec2 a = uvs[q][triangle[t].x], b = uvs[q][triangle[t].y], c = uvs[q][triangle[t].z];
            if (!whole_cell && texels[t] >= kSmallestDrawnTexels) {
                // One atomic per triangle: llvmpipe runs a work group's barriers
                // so slowly that counting per group first cost more than the pass.
                uint slot = 3u * (atomicAdd(caustic_draw.x, 3u) / 3u);
                caustic_triangles[slot] = vec4(a, b);
                caustic_triangles[slot + 1u] = vec4(c, float(r), 0.0f);
                caustic_triangles[slot + 2u] = vec4(triangle_watts / texels[t], 0.0f);
                continue;
            }
            // Too small to draw: at its middle (the whole cell's at once), where that lies on the square.
            vec2 middle = whole_cell ? 0.25f * (uvs[q][0] + uvs[q][1] + uvs[q][2] + uvs[q][3]) : (a + b + c) / 3.0f;
            if (on_square(middle)) {
                splat_receiver[splats] = r;
                splat_uv[splats] = middle;
                splat_watts[splats++] = (whole_cell ? 2.0f : 1.0f) * triangle_watts;
            }
        }
    }
    for (int k = 0; k < splats; ++k) splat_at(splat_receiver[k], splat_uv[k], splat_watts[k]);
}
#else
#include "common/caustic_atlas.glsl"

layout(binding = kCausticAtlasTexture) uniform sampler2D caustic_atlas;

uniform uint texel_count;  // receiver texels in all

void main() {
    int r;
    ivec2 texel;
    if (!receiver_texel_of_invocation(texel_count, r, texel)) return;
    deposit_texel(r, texel, texelFetch(caustic_atlas, texel + ivec2(0, atlas_row(r)), 0).rgb);
}
#endif
