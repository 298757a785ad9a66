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
// lost. Where two receivers face each other, a cell drawn on both is not
// shadowed by either. Both are drawn by the raster pipeline: the triangles
// by caustic_polygons.vert, the splats as points by caustic_splats.vert.
//
// Program options: EIKON_PASS (0: one invocation per grid cell and sheet,
// listing the triangles and splats to draw; 1: one per receiver texel,
// adding the drawn atlas to the tallies); EIKON_CELL_RECEIVERS (pass 0:
// the scene's receivers, up to four).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"

#if EIKON_PASS == 0
#include "common/caustic_vertices.glsl"

layout(std430, binding = kCausticTriangles) writeonly buffer CausticTriangles {
    vec4 caustic_triangles[];  // per triangle: (uv a, uv b), (uv c, receiver, 0), (W per receiver texel rgb, 0)
};
layout(std430, binding = kCausticDraw) buffer CausticDraw {
    uvec4 caustic_draw;  // glDrawArraysIndirect's (count, instances, first, base instance)
};
layout(std430, binding = kCausticSplats) writeonly buffer CausticSplats {
    vec4 caustic_splats[];  // per splat: (map uv, receiver, 0), (W rgb, 0)
};
layout(std430, binding = kCausticSplatDraw) buffer CausticSplatDraw {
    uvec4 caustic_splat_draw;  // glDrawArraysIndirect's (count, instances, first, base instance)
};

uniform ivec2 layer_size;

// The most receivers one cell is drawn on: the scene's, up to four (program
// option EIKON_CELL_RECEIVERS); and the most splats a cell makes.
const int kCellReceivers = EIKON_CELL_RECEIVERS;
const int kSplatSlots = max(4, 2 * kCellReceivers);

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

// Corner k of a cell (0 at its first texel, counter-clockwise): its light texel.
uint corner_texel(uint first, int k) {
    return first + uint(k >> 1) * uint(layer_size.x) + uint(k == 1 || k == 2 ? 1 : 0);
}

// Every array below is indexed by constants only (loops of constant bounds,
// unrolled): a CPU rasterizer keeps such arrays in registers, where an index
// that differs between lanes sends each access through memory lane by lane.
// So the corners are read rotated to put a silhouette's missing corner last,
// and the receivers a cell lands on are ranked by selects.
void main() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    int sheet = int(gl_GlobalInvocationID.z);
    if (any(greaterThanEqual(cell, layer_size - 1))) return;
    uint first = uint(cell.y * layer_size.x + cell.x);
    // The corners whose light texel shows a surface, all the same one for a
    // smooth map; a cell on a refractor's silhouette keeps the triangle of
    // its three that do, corners 0, 1, 2 once the missing one is turned to 3.
    int shown = 0, missing = 0;
    for (int k = 0; k < 4; ++k) {
        bool on_surface = caustic_vertex_surface(corner_texel(first, k), sheet) >= 0;
        shown += on_surface ? 1 : 0;
        missing = on_surface ? missing : k;
    }
    int turn = shown == 4 ? 0 : missing + 1;
    CausticVertex corner[4];
    for (int k = 0; k < 4; ++k) corner[k] = read_caustic_vertex(corner_texel(first, (k + turn) & 3), sheet);
    bool one_surface = true;
    int surface = -1;
    for (int k = 0; k < 4; ++k) {
        one_surface = one_surface && (corner[k].surface < 0 || surface < 0 || corner[k].surface == surface);
        surface = corner[k].surface >= 0 ? corner[k].surface : surface;
    }
    // The receivers the cell's photons land on, each once: corner k's is
    // target rank[k] (−1: it lands on none), target q's receiver target[q].
    int targets = 0;
    int rank[4];
    int target[kCellReceivers];
    for (int q = 0; q < kCellReceivers; ++q) target[q] = -1;
    for (int k = 0; k < 4; ++k) {
        int own = -1;
        for (int j = 0; j < k; ++j) own = own < 0 && rank[j] >= 0 && corner[j].receiver == corner[k].receiver ? rank[j] : own;
        bool opens = corner[k].receiver >= 0 && own < 0;
        for (int q = 0; q < kCellReceivers; ++q) target[q] = opens && q == targets ? corner[k].receiver : target[q];
        rank[k] = opens ? targets : own;
        targets += opens ? 1 : 0;
    }
    // Every flight met with every such receiver's plane.
    vec2 uvs[kCellReceivers][4];  // [target][corner]
    bool reached = true;
    for (int q = 0; q < kCellReceivers; ++q) {
        ReceiverPlane plane = receiver_plane(max(target[q], 0));
        for (int k = 0; k < 4; ++k) {
            bool meets = flight_on_plane(corner[k], plane, uvs[q][k]);
            reached = (q >= targets || meets || corner[k].surface < 0) && reached;
        }
    }
    bool smooth_map = one_surface && shown >= 3 && targets > 0 && reached;
    // Its triangles: corners 0 1 2 and 0 2 3 with half the cell's power
    // each, or on a silhouette 0 1 2 with the three corners' quarters.
    vec3 all_watts = corner[0].watts + corner[1].watts + corner[2].watts + corner[3].watts;
    vec3 triangle_watts = shown == 4 ? 0.125f * all_watts : 0.25f * all_watts;  // a missing corner carries none
    // The splats: with no smooth map, a corner's quarter each where it lands
    // (slot k); with one, the triangles too small to draw (slots 2q, 2q + 1).
    bool splat_on[kSplatSlots];
    int splat_receiver[kSplatSlots];
    vec2 splat_uv[kSplatSlots];
    vec3 splat_watts[kSplatSlots];
    for (int j = 0; j < kSplatSlots; ++j) {
        splat_on[j] = false;
        splat_receiver[j] = 0;
        splat_uv[j] = vec2(0.0f);
        splat_watts[j] = vec3(0.0f);
    }
    for (int k = 0; k < 4; ++k) {
        vec2 own_uv = vec2(0.0f);
        for (int q = 0; q < kCellReceivers; ++q) own_uv = rank[k] == q ? uvs[q][k] : own_uv;
        splat_on[k] = !smooth_map && rank[k] >= 0;
        splat_receiver[k] = corner[k].receiver;
        splat_uv[k] = own_uv;
        splat_watts[k] = 0.25f * corner[k].watts;
    }
    bool drawn[kCellReceivers][2];
    vec3 drawn_watts[kCellReceivers][2];  // W per receiver texel
    for (int q = 0; q < kCellReceivers; ++q) {
        bool on = smooth_map && q < targets;
        int r = max(target[q], 0);
        float texels[2] = float[2](texels_between(uvs[q][0], uvs[q][1], uvs[q][2], r),
                                   texels_between(uvs[q][0], uvs[q][2], uvs[q][3], r));
        bool whole_cell = shown == 4 && texels[0] < kSmallestDrawnTexels && texels[1] < kSmallestDrawnTexels;
        // Too small to draw: at its middle (the whole cell's at once), where that lies on the square.
        vec2 middle[2] = vec2[2](whole_cell ? 0.25f * (uvs[q][0] + uvs[q][1] + uvs[q][2] + uvs[q][3])
                                            : (uvs[q][0] + uvs[q][1] + uvs[q][2]) / 3.0f,
                                 (uvs[q][0] + uvs[q][2] + uvs[q][3]) / 3.0f);
        for (int t = 0; t < 2; ++t) {
            bool exists = on && (t == 0 || (shown == 4 && !whole_cell));
            drawn[q][t] = exists && !whole_cell && texels[t] >= kSmallestDrawnTexels;
            drawn_watts[q][t] = triangle_watts / max(texels[t], 1e-30f);
            int slot = 2 * q + t;
            if (!exists) continue;
            splat_on[slot] = !drawn[q][t] && on_square(middle[t]);
            splat_receiver[slot] = r;
            splat_uv[slot] = middle[t];
            splat_watts[slot] = (whole_cell ? 2.0f : 1.0f) * triangle_watts;
        }
    }
    // One atomic per cell for its triangles and one for its splats: llvmpipe
    // runs a work group's barriers so slowly that counting per group first
    // cost more than the pass.
    int triangle_count = 0;
    for (int q = 0; q < kCellReceivers; ++q)
        for (int t = 0; t < 2; ++t) triangle_count += drawn[q][t] ? 1 : 0;
    uint triangle_slot = triangle_count > 0 ? atomicAdd(caustic_draw.x, 3u * uint(triangle_count)) : 0u;
    for (int q = 0; q < kCellReceivers; ++q)
        for (int t = 0; t < 2; ++t) {
            if (!drawn[q][t]) continue;
            caustic_triangles[triangle_slot] = vec4(uvs[q][0], uvs[q][t + 1]);
            caustic_triangles[triangle_slot + 1u] = vec4(uvs[q][t + 2], float(target[q]), 0.0f);
            caustic_triangles[triangle_slot + 2u] = vec4(drawn_watts[q][t], 0.0f);
            triangle_slot += 3u;
        }
    // The splats are drawn as points rather than added here by atomics: a
    // CPU rasterizer ran a splat's dozens of atomics under a mask for every
    // cell of a work group that had one (half the pass on the default scene).
    int splat_count = 0;
    for (int j = 0; j < kSplatSlots; ++j) splat_count += splat_on[j] ? 1 : 0;
    uint splat_slot = splat_count > 0 ? atomicAdd(caustic_splat_draw.x, uint(splat_count)) : 0u;
    for (int j = 0; j < kSplatSlots; ++j) {
        if (!splat_on[j]) continue;
        caustic_splats[2u * splat_slot] = vec4(splat_uv[j], float(splat_receiver[j]), 0.0f);
        caustic_splats[2u * splat_slot + 1u] = vec4(splat_watts[j], 0.0f);
        ++splat_slot;
    }
}
#else
#include "common/wide_units.glsl"
#include "common/caustic_deposits.glsl"
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
