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
// lost. Nor is a cell whose photons met or left the surface on facets more
// than a crease apart (bridge/mesh/Creases.h), where it lands beyond a few
// texels: drawn, it would spread across the gap under a bar's edge. Where
// two receivers face each other, a cell drawn on both is not shadowed by
// either.
//
// A triangle is added where it covers a texel centre, as the raster
// pipeline samples it. Most are small: a CPU rasterizer's cost is per
// primitive (pool_caustics' 56 000 triangles, most within two texels,
// took a fifth of its frame), so those whose box holds at most
// kDepositWindow centres along each axis, and the splats, are listed for
// pass 2, which tests the few centres in integers and adds the power to
// the tallies by atomics; the larger ones are drawn into an atlas of the
// receivers' maps by caustic_polygons.vert, which pass 1 adds in.
//
// Program options: EIKON_PASS (0: one invocation per grid cell and sheet,
// listing the triangles to draw and the deposits; 1: one per receiver
// texel, adding the drawn atlas to the tallies; 2: one per deposit);
// EIKON_CELL_RECEIVERS (pass 0: the scene's receivers, up to four).
#if EIKON_PASS == 2
layout(local_size_x = 64) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

// The texel centres along each axis a deposited triangle's box holds at most.
const int kDepositWindow = 3;

#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"

#if EIKON_PASS == 0
#include "common/caustic_vertices.glsl"
#include "common/listed_work_groups.glsl"

layout(std430, binding = kCausticTriangles) writeonly buffer CausticTriangles {
    vec4 caustic_triangles[];  // per triangle: (uv a, uv b), (uv c, receiver, 0), (W per receiver texel rgb, 0)
};
layout(std430, binding = kCausticDraw) buffer CausticDraw {
    uvec4 caustic_draw;  // glDrawArraysIndirect's (count, instances, first, base instance)
};
layout(std430, binding = kCausticDeposits) writeonly buffer CausticDeposits {
    vec4 caustic_deposits[];  // per deposit, as a triangle's; a splat: (map uv, 0, 0), (0, 0, receiver, 1), (W rgb, 0)
};
layout(std430, binding = kCausticDepositCount) buffer CausticDepositCount {
    uvec4 caustic_deposit_count;  // x: work groups of pass 2 (y = z = 1); w: deposits listed
};

uniform ivec2 layer_size;
uniform float crease_cosine;  // bridge/mesh/Creases.h, set once

// Whether a triangle's bounding box holds at most kDepositWindow texel
// centres of receiver r along each axis: pass 2 deposits it (in floats:
// a flight that grazes the plane lands where an integer would overflow).
bool within_deposit_window(vec2 a, vec2 b, vec2 c, int r) {
    float edge = float(receivers[receiver_slot(r)].map.y);
    vec2 low = min(a, min(b, c)) * edge, high = max(a, max(b, c)) * edge;
    return all(lessThan(floor(high - 0.5f) - ceil(low - 0.5f), vec2(kDepositWindow)));
}

// Whether a triangle's bounding box meets its receiver's square: one that
// does not covers no texel centre of it, and is neither drawn nor deposited.
bool meets_square(vec2 a, vec2 b, vec2 c) {
    return all(lessThan(min(a, min(b, c)), vec2(1.0f))) && all(greaterThan(max(a, max(b, c)), vec2(0.0f)));
}

// The most receivers one cell is drawn on: the scene's, up to four (program
// option EIKON_CELL_RECEIVERS); and the most splats a cell makes.
const int kCellReceivers = EIKON_CELL_RECEIVERS;
const int kSplatSlots = max(4, 2 * kCellReceivers);

// Triangles landing on less of a receiver texel than this are splatted: a
// triangle adds its power at the texel centres it covers, which a swarm of tiny
// triangles at a caustic's focus can all miss (the default scene's peak
// then falls to 0.6 of the reference), while drawing every larger one keeps
// a uniform beam flat (CausticPolygons.CarryAUniformBeamThroughASlabUniformly).
const float kSmallestDrawnTexels = 0.25f;

// The area of the triangle between three map points, in texels of receiver r.
float texels_between(vec2 a, vec2 b, vec2 c, int r) {
    vec2 ab = b - a, ac = c - a;
    float edge = float(receivers[receiver_slot(r)].map.y);
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
    // Photons that met, or left, the surface on facets more than a crease
    // apart (bridge/mesh/Creases.h) part at its edge: the map from the light
    // to the receivers breaks there, and the cell between them is drawn
    // across whatever lies between their landings. Each corner is compared
    // with corner 0, which shows the surface wherever three or more do.
    bool creased = false;
    for (int k = 1; k < 4; ++k) {
        bool same_patch = dot(corner[0].entry_normal, corner[k].entry_normal) >= crease_cosine &&
                          dot(corner[0].exit_normal, corner[k].exit_normal) >= crease_cosine;
        creased = creased || (corner[0].surface >= 0 && corner[k].surface >= 0 && !same_patch);
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
        ReceiverPlane plane = receiver_plane(receiver_slot(max(target[q], 0)));
        for (int k = 0; k < 4; ++k) {
            bool meets = flight_on_plane(corner[k], plane, uvs[q][k]);
            reached = (q >= targets || meets || corner[k].surface < 0) && reached;
        }
    }
    // Its triangles within the deposit window on every receiver.
    bool within[kCellReceivers][2];
    bool compact = true;
    for (int q = 0; q < kCellReceivers; ++q)
        for (int t = 0; t < 2; ++t) {
            within[q][t] = within_deposit_window(uvs[q][0], uvs[q][t + 1], uvs[q][t + 2], max(target[q], 0));
            compact = compact && (q >= targets || within[q][t]);
        }
    // A creased cell is drawn where it lands within a few texels, which
    // misplaces its power by no more than splats at its corners would (and
    // keeps a seam smooth); a larger one (a bar's edge spreads such cells
    // over the floor, 5.4 million texels of triangles) is splatted.
    bool smooth_map = one_surface && (!creased || compact) && shown >= 3 && targets > 0 && reached;
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
            drawn[q][t] = exists && !whole_cell && texels[t] >= kSmallestDrawnTexels &&
                          meets_square(uvs[q][0], uvs[q][t + 1], uvs[q][t + 2]);
            drawn_watts[q][t] = triangle_watts / max(texels[t], 1e-30f);
            int slot = 2 * q + t;
            if (!exists) continue;
            splat_on[slot] = !drawn[q][t] && on_square(middle[t]);
            splat_receiver[slot] = r;
            splat_uv[slot] = middle[t];
            splat_watts[slot] = (whole_cell ? 2.0f : 1.0f) * triangle_watts;
        }
    }
    // One atomic per cell for its drawn triangles and one for its deposits:
    // llvmpipe runs a work group's barriers so slowly that counting per
    // group first cost more than the pass.
    bool deposited[kCellReceivers][2];
    int triangle_count = 0, deposit_count = 0;
    for (int q = 0; q < kCellReceivers; ++q)
        for (int t = 0; t < 2; ++t) {
            deposited[q][t] = drawn[q][t] && within[q][t];
            triangle_count += drawn[q][t] && !deposited[q][t] ? 1 : 0;
            deposit_count += deposited[q][t] ? 1 : 0;
        }
    for (int j = 0; j < kSplatSlots; ++j) deposit_count += splat_on[j] ? 1 : 0;
    uint triangle_slot = triangle_count > 0 ? atomicAdd(caustic_draw.x, 3u * uint(triangle_count)) : 0u;
    uint deposit_slot = deposit_count > 0 ? atomicAdd(caustic_deposit_count.w, uint(deposit_count)) : 0u;
    uint groups = work_groups_started(deposit_slot, uint(deposit_count), 64u);  // pass 2's work group: 64
    if (groups > 0u) atomicAdd(caustic_deposit_count.x, groups);
    for (int q = 0; q < kCellReceivers; ++q)
        for (int t = 0; t < 2; ++t) {
            if (!drawn[q][t]) continue;
            vec4 corners_ab = vec4(uvs[q][0], uvs[q][t + 1]);
            vec4 corner_c = vec4(uvs[q][t + 2], float(target[q]), 0.0f);
            vec4 watts = vec4(drawn_watts[q][t], 0.0f);
            if (deposited[q][t]) {
                caustic_deposits[3u * deposit_slot] = corners_ab;
                caustic_deposits[3u * deposit_slot + 1u] = corner_c;
                caustic_deposits[3u * deposit_slot + 2u] = watts;
                ++deposit_slot;
            } else {
                caustic_triangles[triangle_slot] = corners_ab;
                caustic_triangles[triangle_slot + 1u] = corner_c;
                caustic_triangles[triangle_slot + 2u] = watts;
                triangle_slot += 3u;
            }
        }
    for (int j = 0; j < kSplatSlots; ++j) {
        if (!splat_on[j]) continue;
        caustic_deposits[3u * deposit_slot] = vec4(splat_uv[j], 0.0f, 0.0f);
        caustic_deposits[3u * deposit_slot + 1u] = vec4(0.0f, 0.0f, float(splat_receiver[j]), 1.0f);
        caustic_deposits[3u * deposit_slot + 2u] = vec4(splat_watts[j], 0.0f);
        ++deposit_slot;
    }
}
#else
#include "common/wide_units.glsl"
#include "common/caustic_deposits.glsl"
#if EIKON_PASS == 2
layout(std430, binding = kCausticDeposits) readonly buffer CausticDeposits { vec4 caustic_deposits[]; };
layout(std430, binding = kCausticDepositCount) readonly buffer CausticDepositCount { uvec4 caustic_deposit_count; };

// Twice the signed area of the triangle (a, b, c), in fixed point.
int fixed_cross(ivec2 a, ivec2 b, ivec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// The texel centres of the kDepositWindow² window from texel `first` that
// the triangle with corners a, b, c (in texels) covers: bit y·window + x.
// As the raster pipeline samples them: the corners snapped to 1/256 of a
// texel, so that the edge tests are exact in integers, and a centre on an
// edge belongs to the one of its two triangles on whose side of it the
// edge runs up (or left, when level): a uniform beam's cells neither lose
// nor double the centres on their shared edges.
uint centres_covered(vec2 a, vec2 b, vec2 c, ivec2 first) {
    ivec2 centre_fixed = first * 256 + 128;
    ivec2 corner[3] = ivec2[3](ivec2(round(a * 256.0f)) - centre_fixed, ivec2(round(b * 256.0f)) - centre_fixed,
                               ivec2(round(c * 256.0f)) - centre_fixed);
    int area = fixed_cross(corner[0], corner[1], corner[2]);
    // Counter-clockwise: a fold of the caustic turns triangles over.
    ivec2 second = area < 0 ? corner[2] : corner[1], third = area < 0 ? corner[1] : corner[2];
    corner[1] = second;
    corner[2] = third;
    uint covered = 0u;
    for (int k = 0; k < kDepositWindow * kDepositWindow; ++k) {
        ivec2 centre = ivec2(k % kDepositWindow, k / kDepositWindow) * 256;
        bool inside = area != 0;
        for (int e = 0; e < 3; ++e) {
            ivec2 from = corner[e], to = corner[(e + 1) % 3];
            int side = fixed_cross(from, to, centre);
            bool owns_edge = to.y > from.y || (to.y == from.y && to.x < from.x);
            inside = inside && (side > 0 || (side == 0 && owns_edge));
        }
        covered |= inside ? 1u << uint(k) : 0u;
    }
    return covered;
}

void main() {
    uint deposit = gl_GlobalInvocationID.x;
    if (deposit >= caustic_deposit_count.w) return;
    vec4 ab = caustic_deposits[3u * deposit], c = caustic_deposits[3u * deposit + 1u];
    vec3 watts = caustic_deposits[3u * deposit + 2u].rgb;
    bool splat = c.w > 0.5f;
    int r = int(round(c.z));
    int resolution = int(receivers[receiver_slot(r)].map.y);
    vec2 a = ab.xy * float(resolution), b = ab.zw * float(resolution), c_ = c.xy * float(resolution);
    // A splat's four texels around it, a triangle's window from the first centre its box holds.
    BilinearSplat around = bilinear_splat(ab.xy, resolution);
    ivec2 first = splat ? around.base : ivec2(ceil(min(a, min(b, c_)) - 0.5f));
    uint covered = splat ? (around.on_map > 0.0f ? 3u | (3u << uint(kDepositWindow)) : 0u) : centres_covered(a, b, c_, first);
    // One deposit in a loop: a CPU rasterizer runs every call site under a mask.
    for (; covered != 0u; covered &= covered - 1u) {
        int k = findLSB(covered);
        ivec2 offset = ivec2(k % kDepositWindow, k / kDepositWindow);
        deposit_texel(r, first + offset, (splat ? bilinear_splat_share(around, offset) : 1.0f) * watts);
    }
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
#endif
