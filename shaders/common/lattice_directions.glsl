// The direction sets of the lattice that carries multiply scattered light
// ([Bernabei12] §III-C, eqs. 4–5). A link moves a photon density to the
// neighbour at offset c_d in one lattice step. Directions are numbered once
// for all lattices: d in [0, 6) the principal axes ±x, ±y, ±z (even d
// positive); [6, 18) the face diagonals, plane by plane (xy, yz, zx), each
// with the sign pairs (+,+), (−,+), (+,−), (−,−); [18, 26) the body
// diagonals, bit b of d − 18 set where axis b is negative. A lattice of
// `directions` links uses a subset (lattice_link):
// - 6: the principal directions, as the paper;
// - 18: axes and face diagonals ([Geist04]'s 18 links, here without the
//   rest particle);
// - 14: axes and body diagonals.
//
// Weights w_d are the share of isotropically scattered power each link
// takes. Every lattice here integrates ⟨μ²⟩ = 1/3, the diffusion limit's
// moment, so all diffuse alike in the bulk; they differ where transport is
// not yet diffusive — next to a boundary and within a mean free path of
// where light is born:
// - 6 links: 1/6 each.
// - 18 links: 1/30 per axis, 1/15 per face diagonal, the only split that
//   also integrates the fourth moments (⟨μ⁴⟩ = 1/5, ⟨μx²μy²⟩ = 1/15).
// - 14 links: (3 − √3)/24 per axis, (1 + √3)/32 per body diagonal, the
//   split whose half-range flux Σ_{μ>0} w μ is 1/4, the continuum's
//   (Marshak's condition): an isotropic density leaves through a face at the
//   continuum's rate φ/4 (18 links: 0.222 φ; 6 links: φ/6), and no link runs
//   parallel to a face (18 links: 40% of the weight; 6 links: 2/3), where
//   light near the face cannot leave before it scatters again.
// Shared by GLSL and C++ (cpp_shim.h).

// The global direction of link `slot` of a lattice of `directions` links.
int lattice_link(int slot, int directions) { return (directions == 14 && slot >= 6) ? slot + 12 : slot; }

// The link slot of global direction d in a lattice of `directions` links
// (the inverse of lattice_link).
int lattice_slot(int d, int directions) { return (directions == 14 && d >= 18) ? d - 12 : d; }

ivec3 lattice_offset(int d) {
    if (d < 6) {
        ivec3 offset = ivec3(0);
        int axis = d / 2;
        int sign_ = (d % 2 == 0) ? 1 : -1;
        if (axis == 0) offset.x = sign_;
        if (axis == 1) offset.y = sign_;
        if (axis == 2) offset.z = sign_;
        return offset;
    }
    if (d >= 18) {
        int bits = d - 18;
        return ivec3((bits & 1) != 0 ? -1 : 1, (bits & 2) != 0 ? -1 : 1, (bits & 4) != 0 ? -1 : 1);
    }
    int k = d - 6;
    int plane = k / 4;
    int first = (k % 2 == 0) ? 1 : -1;
    int second = ((k / 2) % 2 == 0) ? 1 : -1;
    if (plane == 0) return ivec3(first, second, 0);
    if (plane == 1) return ivec3(0, first, second);
    return ivec3(second, 0, first);
}

float lattice_weight(int d, int directions) {
    if (directions == 6) return 1.0f / 6.0f;
    if (directions == 14) return d < 6 ? (3.0f - 1.7320508f) / 24.0f : (1.0f + 1.7320508f) / 32.0f;
    return d < 6 ? 1.0f / 30.0f : 1.0f / 15.0f;
}

// The links' length classes: 0–2 along x, y, z; 3–5 the diagonals of the
// xy, yz and zx planes; 6 the body diagonals (each class one length on any
// box voxel).
const int LATTICE_LENGTH_CLASSES = 7;
int lattice_length_class(int d) { return d < 6 ? d / 2 : (d < 18 ? 3 + (d - 6) / 4 : 6); }

// A direction of length class k.
int lattice_class_direction(int k) { return k < 3 ? 2 * k : (k < 6 ? 6 + 4 * (k - 3) : 18); }

// The direction with the opposite offset.
int lattice_opposite(int d) {
    if (d < 6) return (d % 2 == 0) ? d + 1 : d - 1;
    if (d >= 18) return 18 + (7 - (d - 18));
    int k = d - 6;
    return 6 + (k / 4) * 4 + (3 - k % 4);
}

// (1 − e^{−x})/x, the mean transmittance over a path of optical depth x: the
// track length a photon lays down per unit of geometric path crossed. Below
// x = 0.5 its Taylor series Σ (−x)^k/(k + 1)!, to k = 9 (error below 1e-9),
// where the quotient would lose digits to cancellation.
float mean_transmittance(float x) {
    if (x < 0.5f) {
        float sum = 1.0f / 3628800.0f;  // 1/10!
        float factorial = 3628800.0f;
        for (int k = 9; k >= 1; --k) {
            factorial /= float(k + 1);  // (k + 1)! → k!
            sum = 1.0f / factorial - x * sum;
        }
        return sum;
    }
    return (1.0f - exp(-x)) / x;
}

// The largest lattice's link count.
const int LATTICE_MAX_LINKS = 18;

// The unit direction in metres of link `slot` on voxels of `voxel_size`.
vec3 lattice_link_direction(int slot, vec3 voxel_size, int directions) {
    return normalize(vec3(lattice_offset(lattice_link(slot, directions))) * voxel_size);
}

// Every link's unit direction in metres, found once for many look-ups.
struct LatticeLinkDirections {
    vec3 unit[LATTICE_MAX_LINKS];
};

LatticeLinkDirections lattice_link_directions(vec3 voxel_size, int directions) {
    LatticeLinkDirections links;
    for (int i = 0; i < LATTICE_MAX_LINKS; ++i)
        links.unit[i] = i < directions ? lattice_link_direction(i, voxel_size, directions) : vec3(0.0f);
    return links;
}

// The slot of the link nearest to the unit vector `direction` (the largest
// cosine) among `links`.
int lattice_nearest_of(vec3 direction, LatticeLinkDirections links, int directions) {
    int best = 0;
    float best_cosine = -2.0f;
    for (int i = 0; i < directions; ++i) {
        float cosine = dot(links.unit[i], direction);
        if (cosine > best_cosine) {
            best_cosine = cosine;
            best = i;
        }
    }
    return best;
}

// The slot of the link nearest to the unit vector `direction` on voxels of
// `voxel_size` (the link's direction in metres).
int lattice_nearest_slot(vec3 direction, vec3 voxel_size, int directions) {
    return lattice_nearest_of(direction, lattice_link_directions(voxel_size, directions), directions);
}
