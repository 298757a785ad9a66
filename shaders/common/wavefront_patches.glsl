// The wavefront pass's patches ([Ihrke07] §4.2.2–4.2.3; the method in
// shaders/wavefront_trace.comp): seeding a chunk of a light's emission
// domain, tracing the corners of new patches, and refining a level — each
// patch splits in four or finishes, depositing its power. One invocation (or
// one native loop iteration) a patch or a ray; the host drives the levels.
// Shared by GLSL and C++ (render/stages/NativeWavefrontTrace.cpp); the
// includer declares the uniforms of wavefront_trace.comp, Corner, Patch, the
// buffers `patches` and `children`, and the counters count_traced_ray,
// count_finished_patch, count_split_patch and count_limited_patch. What
// stores fluence (EIKON_STORE_FLUENCE) is GLSL only: the native pass keeps no
// fluence.

// A patch corner: the ray of point u, depositing nothing.
Corner trace_corner(uint emitter_index, uint face, vec2 u) {
    count_traced_ray();
    return trace_ray(emitter_index, face, u, vec3(0.0f));
}

uint corner_history(Corner corner) { return floatBitsToUint(corner.power.w); }
uint corner_fate_code(Corner corner) { return floatBitsToUint(corner.absorbed.w); }
int corner_fate(Corner corner) { return int(corner_fate_code(corner) & 15u); }
int corner_receiver(Corner corner) { return int(corner_fate_code(corner) >> 4) - 1; }

// The receiver whose plane all the patch's corners reached with one history
// — on its square (received) or past its edge (escaped after crossing the
// plane there) — or −1: the patch's footprint is then a triangle in that
// plane, cut by the square's edges.
int footprint_receiver(Patch p) {
    int r = corner_receiver(p.corners[0]);
    if (r < 0) return -1;
    for (int k = 0; k < 3; ++k) {
        int fate = corner_fate(p.corners[k]);
        if (corner_receiver(p.corners[k]) != r || (fate != kReceived && fate != kEscaped) ||
            corner_history(p.corners[k]) != corner_history(p.corners[0]))
            return -1;
    }
    return r;
}

bool corners_agree(Patch p) {
    return corner_history(p.corners[0]) == corner_history(p.corners[1]) &&
           corner_history(p.corners[1]) == corner_history(p.corners[2]) &&
           corner_fate_code(p.corners[0]) == corner_fate_code(p.corners[1]) &&
           corner_fate_code(p.corners[1]) == corner_fate_code(p.corners[2]);
}

bool reaches_grid(Patch p) { return p.corners[0].exit.w + p.corners[1].exit.w + p.corners[2].exit.w > 0.0f; }

#if EIKON_STORE_FLUENCE > 0
// The fluence of a finished patch's tube, narrower than split_voxels where it
// crosses the grid: its power Φ carried along its axis, the ray of its
// centroid, as the photons' track-length estimator carries a photon's
// (common/fluence_deposits.glsl). A branch's tube starts at its reflection;
// one whose corners all missed the grid, or none of which began the branch,
// deposits nothing.
void deposit_tube(Patch p, vec3 power, vec3 sourced) {
    if (!reaches_grid(p) || !any(greaterThan(sourced, vec3(0.0f)))) return;
    atomicAdd(tube_rays, 1u);
    trace_ray(p.info.x, p.info.z, (xy_of(p.corners[0].ends) + xy_of(p.corners[1].ends) + xy_of(p.corners[2].ends)) / 3.0f,
              power);
    uint before = atomicAdd(deposit_tallies[0], deposits);
    if (before + deposits < before) atomicAdd(deposit_tallies[1], 1u);
}
#endif

// A patch that is done: its power Φ (patch_power), a third to each corner's
// ledger — its source, absorbed, unfollowed reflections — and what arrives:
// on a receiver's plane, by footprint (the part on the square received, the
// rest escaped); with corners that agree elsewhere, to their common fate;
// else each corner's third to its own fate, at its own texel if received;
// and, where the pass stores fluence, its tube's (deposit_tube).
void finish_patch(Patch p) {
    Emitter emitter = emitters[p.info.x];
    vec3 third =
        patch_power(emitter, p.info.z, xy_of(p.corners[0].ends), xy_of(p.corners[1].ends), xy_of(p.corners[2].ends)) / 3.0f;
    vec3 sourced = vec3(0.0f);
    vec3 absorbed = vec3(0.0f);
    vec3 unfollowed = vec3(0.0f);
    vec3 arriving = vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
        Corner corner = p.corners[k];
        sourced += third * xyz_of(corner.source);
        absorbed += third * xyz_of(corner.absorbed);
        unfollowed += third * max(xyz_of(corner.source) - xyz_of(corner.power) - xyz_of(corner.absorbed), vec3(0.0f));
        arriving += third * xyz_of(corner.power);
    }
    add_stat(branch < 0 ? kEmitted : kReflected, sourced);
    add_stat(kAbsorbed, absorbed);
    add_stat(kUnfollowed, unfollowed);
    int r = footprint_receiver(p);
    if (r >= 0) {
        float on = deposit_footprint(r, zw_of(p.corners[0].ends), zw_of(p.corners[1].ends), zw_of(p.corners[2].ends),
                                     arriving);
        add_stat(kReceived, on * arriving);
        add_stat(kEscaped, (1.0f - on) * arriving);
    } else if (corners_agree(p)) {
        add_stat(corner_fate(p.corners[0]), arriving);
    } else {
        for (int k = 0; k < 3; ++k) {
            Corner corner = p.corners[k];
            int fate = corner_fate(corner);
            add_stat(fate, third * xyz_of(corner.power));
            if (fate == kReceived)
                deposit_in_texel(corner_receiver(corner), texel_of(corner_receiver(corner), zw_of(corner.ends)),
                                 third * xyz_of(corner.power));
        }
    }
    count_finished_patch();
#if EIKON_STORE_FLUENCE > 0
    deposit_tube(p, 3.0f * third, sourced);
#endif
}

// A footprint's corners, in texel coordinates of a receiver.
struct Footprint {
    vec2 ends[3];
};

// The footprint, in texel coordinates of receiver r, that the patch's
// emission rays would have there if they flew straight: the scale of a patch
// whose real footprint is torn, and the measure of the power a texel there
// would get unobstructed. False when a straight ray would miss the plane.
bool straight_footprint(Patch p, int r, OUT(Footprint) straight) {
    Emitter emitter = emitters[p.info.x];
    Receiver receiver = receivers[r];
    for (int k = 0; k < 3; ++k) {
        vec3 x;
        vec3 d;
        emission_ray(emitter, p.info.z, xy_of(p.corners[k].ends), x, d);
        float t = receiver_ray_parameter(x, d, xyz_of(receiver.origin), xyz_of(receiver.normal));
        if (t < 0.0f) return false;
        straight.ends[k] = receiver_map_coordinates(x + t * d, xyz_of(receiver.origin), xyz_of(receiver.axis_u),
                                                    xyz_of(receiver.axis_v), receiver.origin.w) *
                           float(receiver.map.y);
    }
    return true;
}

float longest_edge(vec2 a, vec2 b, vec2 c) { return max(distance(a, b), max(distance(b, c), distance(c, a))); }

// The spot profile's mean over the patch (1 for other lights): its corners
// carry what reaches them of a unit ray, the patch's power the profile.
float profile_of(Patch p) {
    return patch_profile(emitters[p.info.x], p.info.z, xy_of(p.corners[0].ends), xy_of(p.corners[1].ends),
                         xy_of(p.corners[2].ends));
}

// Whether a patch carries at least min_power of what a texel gets where its
// straight footprint lies (its corners' power over the straight footprint's
// area in texels): splitting a fainter one cannot move much light.
bool carries_power(Patch p, Footprint straight) {
    vec3 arriving = xyz_of(p.corners[0].power) + xyz_of(p.corners[1].power) + xyz_of(p.corners[2].power);
    float share = max(arriving.r, max(arriving.g, arriving.b)) / 3.0f * profile_of(p);
    return share * 0.5f * abs(twice_signed_area(straight.ends[0], straight.ends[1], straight.ends[2])) >= min_power;
}

// Whether a patch must split for a receiver: while it is larger than
// split_texels there and carries power (carries_power) — the light a grazing ray
// refracts into a wide, faint halo would otherwise split without end, and
// what such a patch misplaces is at most its own power.
// - A footprint in a receiver's plane (footprint_receiver) is measured
//   there, where it overlaps the square; one across the square's edge, where
//   the power is shared by area as if even over the patch, down to
//   tear_texels.
// - Corners that disagree (a shadow edge, a tear of the wavefront at a
//   silhouette or where total internal reflection sets in) are measured by
//   their straight footprint on the receiver a corner reached, down to
//   tear_texels; none reached one, or some fly away from its plane (a tear
//   at its horizon, where light grazes it): the patch stops, as do corners
//   that agree elsewhere.
bool wants_receiver_split(Patch p) {
    Footprint straight;
    int r = footprint_receiver(p);
    if (r < 0) {
        if (corners_agree(p)) return false;
        for (int k = 2; k >= 0; --k)
            if (corner_fate(p.corners[k]) == kReceived) r = corner_receiver(p.corners[k]);
        if (r < 0 || !straight_footprint(p, r, straight)) return false;
        return longest_edge(straight.ends[0], straight.ends[1], straight.ends[2]) > tear_texels &&
               carries_power(p, straight);
    }
    float resolution = float(receivers[r].map.y);
    vec2 a = zw_of(p.corners[0].ends) * resolution;
    vec2 b = zw_of(p.corners[1].ends) * resolution;
    vec2 c = zw_of(p.corners[2].ends) * resolution;
    if (any(greaterThan(min(a, min(b, c)), vec2(resolution))) || any(lessThan(max(a, max(b, c)), vec2(0.0f))))
        return false;  // wholly beside the square
    bool straddles = on_square(zw_of(p.corners[0].ends)) != on_square(zw_of(p.corners[1].ends)) ||
                     on_square(zw_of(p.corners[1].ends)) != on_square(zw_of(p.corners[2].ends));
    if (longest_edge(a, b, c) <= (straddles ? tear_texels : split_texels)) return false;
    return !straight_footprint(p, r, straight) || carries_power(p, straight);
}

float longest_edge(vec3 a, vec3 b, vec3 c) { return max(distance(a, b), max(distance(b, c), distance(c, a))); }

#if EIKON_STORE_FLUENCE > 0
// Whether a patch must split for the fluence in the grid: while its tube is
// wider than split_voxels there and it carries at least min_power of what a
// voxel's cross-section gets unobstructed. The width, in voxels, is that of
// the triangle of its corners where they enter the grid and where they last
// leave it, when they agree (one history, one fate); when they disagree (a
// silhouette, a shadow edge), that of its emission rays flown straight as far
// as the farthest corner got in the grid, so that a torn patch splits only
// down to the tube width, not without end. A patch none of whose corners
// reached the grid does not split for it.
bool wants_grid_split(Patch p) {
    if (!reaches_grid(p)) return false;
    Emitter emitter = emitters[p.info.x];
    vec3 x[3];
    vec3 d[3];
    float farthest = 0.0f;
    bool all_inside = true;
    for (int k = 0; k < 3; ++k) {
        emission_ray(emitter, p.info.z, xy_of(p.corners[k].ends), x[k], d[k]);
        if (p.corners[k].exit.w > 0.0f) farthest = max(farthest, distance(x[k], xyz_of(p.corners[k].exit)));
        else all_inside = false;
    }
    vec3 voxel = xyz_of(grid.voxel_size);
    vec3 straight[3];
    for (int k = 0; k < 3; ++k) straight[k] = (x[k] + farthest * d[k]) / voxel;
    float width = longest_edge(straight[0], straight[1], straight[2]);
    if (all_inside && corners_agree(p)) {
        vec3 entry[3];
        for (int k = 0; k < 3; ++k) entry[k] = (x[k] + max(grid_ray_interval(x[k], d[k]).x, 0.0f) * d[k]) / voxel;
        width = max(longest_edge(entry[0], entry[1], entry[2]),
                    longest_edge(xyz_of(p.corners[0].exit) / voxel, xyz_of(p.corners[1].exit) / voxel,
                                 xyz_of(p.corners[2].exit) / voxel));
    }
    if (width <= split_voxels) return false;
    vec3 sourced = xyz_of(p.corners[0].source) + xyz_of(p.corners[1].source) + xyz_of(p.corners[2].source);
    float share = max(sourced.r, max(sourced.g, sourced.b)) / 3.0f * profile_of(p);
    return share * 0.5f * length(cross(straight[1] - straight[0], straight[2] - straight[0])) >= min_power;
}
#endif

// Whether a branch's patch must split where its corners start the branch
// with different power: across the silhouette of the surface it reflects at,
// where grazing Fresnel reflectance climbs steeply to 1 and then drops to
// nothing beyond the rim, so that the corners' linear interpolation of it
// misses the rim's reflection (−19% of the default scene's reflected power
// at grid_cells 64, −40% of what it reflects onto the floor). It splits
// while that difference times the patch's share of a start patch's power
// (4^−depth) is at least reflection_split — down to max_depth. The main
// wavefront's rim is resolved by its footprint where its light reaches a
// receiver (its unfollowed reflection moves 0.04% from grid_cells 64 to 256
// on the default scene).
bool wants_source_split(Patch p) {
    if (branch < 0) return false;
    float least = 3.0e38f;
    float most = 0.0f;
    for (int k = 0; k < 3; ++k) {
        vec3 s = xyz_of(p.corners[k].source);
        float strongest = max(s.r, max(s.g, s.b));
        least = min(least, strongest);
        most = max(most, strongest);
    }
    return (most - least) * exp2(-2.0f * float(p.info.y)) >= reflection_split;
}

bool wants_split(Patch p) {
    if (wants_source_split(p)) return true;
#if EIKON_STORE_FLUENCE > 0
    if (wants_grid_split(p)) return true;
#endif
    return wants_receiver_split(p);
}

// A child patch whose corners are the parent's corners or, still to be
// traced (mode 1), edge midpoints of the emission square.
Corner untraced_corner(vec2 u) {
    Corner corner;
    corner.ends = vec4(u, 0.0f, 0.0f);
    corner.power = vec4(0.0f);
    corner.absorbed = vec4(0.0f);
    corner.source = vec4(0.0f);
    corner.exit = vec4(0.0f);
    return corner;
}

void write_child(uint slot, uvec4 info, Corner a, Corner b, Corner c) {
    children[slot].corners[0] = a;
    children[slot].corners[1] = b;
    children[slot].corners[2] = c;
    children[slot].info = info;
}

// The four children of p at slot…slot + 3: its corners and its three edge
// midpoints m01, m12, m20 — as (c0, m01, m20), (m01, c1, m12),
// (m20, m12, c2), (m01, m12, m20) — the midpoints traced by mode 1.
void split_patch(Patch p, uint slot) {
    Corner m01 = untraced_corner(0.5f * (xy_of(p.corners[0].ends) + xy_of(p.corners[1].ends)));
    Corner m12 = untraced_corner(0.5f * (xy_of(p.corners[1].ends) + xy_of(p.corners[2].ends)));
    Corner m20 = untraced_corner(0.5f * (xy_of(p.corners[2].ends) + xy_of(p.corners[0].ends)));
    uvec4 info = uvec4(p.info.x, p.info.y + 1u, p.info.z, 0u);
    write_child(slot + 0u, info, p.corners[0], m01, m20);
    write_child(slot + 1u, info, m01, p.corners[1], m12);
    write_child(slot + 2u, info, m20, m12, p.corners[2]);
    write_child(slot + 3u, info, m01, m12, m20);
    count_split_patch();
}

// Mode 2's end for patch p of the level, whose wants_split is `splitting`:
// its four children at slot…slot + 3 of Children where they fit (slot is
// `capacity` where none were claimed: it does not split or is at max_depth),
// else it finishes — counted as at the limit where it wanted to split.
void settle_patch(Patch p, bool splitting, uint slot) {
    if (slot + 4u <= capacity) {
        split_patch(p, slot);
        return;
    }
    if (splitting) count_limited_patch();
    finish_patch(p);
}

// Whether a patch that wants to split claims slots for its children.
bool claims_children(Patch p, bool splitting) { return splitting && p.info.y < max_depth; }

// Mode 0: seed patch `index` of this chunk, half of cell first_cell + index / 2
// of the emission domain's faces of grid_cells² cells, its corners to be traced.
void seed(uint index) {
    uint cell = first_cell + index / 2u;
    uint face = cell / (grid_cells * grid_cells);
    uint in_face = cell % (grid_cells * grid_cells);
    vec2 low = vec2(float(in_face % grid_cells), float(in_face / grid_cells)) / float(grid_cells);
    float size = 1.0f / float(grid_cells);
    vec2 other = (index % 2u == 0u) ? low + vec2(size, 0.0f) : low + vec2(0.0f, size);
    write_child(index, uvec4(seed_emitter, 0u, face, 0u), untraced_corner(low), untraced_corner(other),
                untraced_corner(low + vec2(size)));
}

// Mode 1: ray `job` of the children. After seeding, corner job % 3 of patch
// job / 3; after a split, midpoint job % 3 (m01, m12, m20) of the four
// children at 4·(job / 3), written to each child that has it.
void trace_job(uint job) {
    uint which = job % 3u;
    uint first = job / 3u;
    if (seeded_jobs != 0u) {
        children[first].corners[which] =
            trace_corner(children[first].info.x, children[first].info.z, xy_of(children[first].corners[which].ends));
        return;
    }
    uint slot = 4u * first;
    if (which == 0u) {  // m01: child 0 corner 1, child 1 corner 0, child 3 corner 0
        Corner m = trace_corner(children[slot].info.x, children[slot].info.z, xy_of(children[slot].corners[1].ends));
        children[slot].corners[1] = m;
        children[slot + 1u].corners[0] = m;
        children[slot + 3u].corners[0] = m;
    } else if (which == 1u) {  // m12: child 1 corner 2, child 2 corner 1, child 3 corner 1
        Corner m = trace_corner(children[slot].info.x, children[slot].info.z, xy_of(children[slot + 1u].corners[2].ends));
        children[slot + 1u].corners[2] = m;
        children[slot + 2u].corners[1] = m;
        children[slot + 3u].corners[1] = m;
    } else {  // m20: child 0 corner 2, child 2 corner 0, child 3 corner 2
        Corner m = trace_corner(children[slot].info.x, children[slot].info.z, xy_of(children[slot].corners[2].ends));
        children[slot].corners[2] = m;
        children[slot + 2u].corners[0] = m;
        children[slot + 3u].corners[2] = m;
    }
}
