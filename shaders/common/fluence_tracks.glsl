// The two ways a light pass fills the fluence tallies (common/fluence_deposits.glsl
// says which pass takes which): by the track length in each voxel a photon's
// segment crosses, and by smooth cloud weights along a wavefront tube's axis.
// Shared by GLSL and C++: the includer declares add_fluence, add_scattered
// and EIKON_STORE_FLUENCE; needs common/grid_box.glsl, common/loop_budget.glsl
// and common/attenuation.glsl.

// The power-weighted length (W·m) of a piece `piece` long that starts
// `travelled` along a segment entered with `power` at extinction κ: the
// power there times the length it spends decaying across the piece.
vec3 piece_track(vec3 power, vec3 kappa, float travelled, float piece) {
    return power * beer_lambert_transmittance(kappa, travelled) * attenuated_track_length(kappa, piece);
}

// Track-length estimator over the segment a → b: a 3D DDA visits every voxel
// the segment crosses and adds the power-weighted length spent in it, with
// Beer–Lambert decay along the way at the segment's extinction κ.
void deposit_segment(vec3 a, vec3 b, vec3 power, vec3 kappa, vec3 sigma_s) {
#if EIKON_STORE_FLUENCE > 0
    vec3 delta = b - a;
    float length_ = length(delta);
    if (length_ <= 0.0f) return;
    vec3 direction = delta / length_;
    vec3 p = (a - xyz_of(grid.bounds_min)) / xyz_of(grid.voxel_size);
    vec3 q = (b - xyz_of(grid.bounds_min)) / xyz_of(grid.voxel_size);
    vec3 span = q - p;
    ivec3 cell = clamp(ivec3(floor(p)), ivec3(0), ivec3(grid.resolution) - 1);
    ivec3 stride = ivec3(sign(span));
    vec3 inverse = 1.0f / abs(span);
    vec3 next_face = vec3(cell) + step(vec3(0.0f), span);  // the face ahead on each axis
    vec3 t_max = mix((next_face - p) / span, vec3(1e30f), equal(span, vec3(0.0f)));
    vec3 t_delta = mix(inverse, vec3(1e30f), equal(span, vec3(0.0f)));
    float t = 0.0f;
    int guard = 3 * (int(abs(span.x)) + int(abs(span.y)) + int(abs(span.z))) + 6;
    spend_loops(uint(guard));
    for (int i = 0; i < guard; ++i) {
        float t_next = min(1.0f, min(t_max.x, min(t_max.y, t_max.z)));
        float piece = (t_next - t) * length_;
        if (piece > 0.0f) {
            vec3 track = piece_track(power, kappa, t * length_, piece);
            add_fluence(cell, track, direction);
            add_scattered(cell, track, sigma_s);
        }
        if (t_next >= 1.0f) break;
        t = t_next;
        if (t_max.x <= t_max.y && t_max.x <= t_max.z) {
            cell.x += stride.x;
            t_max.x += t_delta.x;
        } else if (t_max.y <= t_max.z) {
            cell.y += stride.y;
            t_max.y += t_delta.y;
        } else {
            cell.z += stride.z;
            t_max.z += t_delta.z;
        }
        if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(grid.resolution)))) break;
    }
#endif
}

// Cloud estimator over the segment a → b of a tube's axis carrying `power`:
// the segment is cut into pieces of at most half a voxel, and each piece's
// power-weighted length goes to the 27 cells about its midpoint by the
// quadratic B-spline weights between cell centres ("triangular-shaped
// cloud"; cells past the grid's faces fold onto the face cells, so nothing
// is lost). The weights sum to one: the track length, and so the energy in
// the grid, is the photons'; what changes is that a thin tube's light
// spreads over the cells its width could reach rather than landing in the
// one its axis crosses. The spline, not the trilinear tent: the tubes' axes
// sample the cross-section on the patches' lattice, and the ripple that
// sampling leaves falls with the kernel's spectrum, sinc³ against sinc² —
// about 1% with the tent at the default split_voxels, 0.1% with the spline.
// The power scattered goes to the cell the piece is in, as for photons.
void deposit_tube_segment(vec3 a, vec3 b, vec3 power, vec3 kappa, vec3 sigma_s) {
#if EIKON_STORE_FLUENCE > 0
    vec3 delta = b - a;
    float length_ = length(delta);
    if (length_ <= 0.0f) return;
    vec3 direction = delta / length_;
    vec3 p = (a - xyz_of(grid.bounds_min)) / xyz_of(grid.voxel_size);
    vec3 span = (b - a) / xyz_of(grid.voxel_size);
    int pieces = max(1, int(ceil(2.0f * max(abs(span.x), max(abs(span.y), abs(span.z))))));
    spend_loops(uint(27 * pieces));
    float piece = length_ / float(pieces);
    for (int i = 0; i < pieces; ++i) {
        vec3 track = piece_track(power, kappa, float(i) * piece, piece);
        vec3 middle = p + (float(i) + 0.5f) / float(pieces) * span;
        add_scattered(clamp(ivec3(floor(middle)), ivec3(0), ivec3(grid.resolution) - 1), track, sigma_s);
        vec3 nearest = floor(middle);  // the cell whose centre is nearest
        vec3 d = middle - nearest - 0.5f;  // from that centre, in [−1/2, 1/2]
        vec3 below = 0.5f * (0.5f - d) * (0.5f - d);
        vec3 centre = 0.75f - d * d;
        vec3 above = 0.5f * (0.5f + d) * (0.5f + d);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    ivec3 offset = ivec3(dx, dy, dz);
                    vec3 weights = mix(mix(below, centre, vec3(greaterThanEqual(offset, ivec3(0)))), above,
                                       vec3(greaterThan(offset, ivec3(0))));
                    ivec3 cell = clamp(ivec3(nearest) + offset, ivec3(0), ivec3(grid.resolution) - 1);
                    add_fluence(cell, track * (weights.x * weights.y * weights.z), direction);
                }
    }
#endif
}
