// Anisotropic scattering on the multiple-scattering lattice
// (common/lattice_directions.glsl): how light that a Henyey–Greenstein
// medium of asymmetry g ([Ihrke07] eq. 3) scatters is shared among the
// links. Shared by GLSL and C++ (cpp_shim.h).
//
// - The first scattering (light the light pass scatters out of its beam) is
//   born in HG about the beam's direction projected on the links
//   (lattice_hg_shares).
// - Every later scattering: a share f = g² of it counts as no scattering at
//   all, the δ-Eddington forward peak ([Joseph76], the paper's f = g²): the
//   lattice's medium is σs′ = σs(1 − f), σt′ = σa + σs′. The rest scatters
//   from link j to link i by the phase matrix
//     P′_ij = (S_i(ĉ_j) − f δ_ij) / (1 − f),
//   S(ĉ_j) the same projection of HG about link j (a lattice-Boltzmann
//   collision with an anisotropic phase matrix; tabulated over g once per
//   grid, render/stages/LatticePhase). P′ is non-negative, its columns sum to
//   1, its mean cosine is (g − f)/(1 − f) and its backward half-range flux
//   HG's over (1 − f): the remainder of HG once its forward peak is taken
//   out, as far as the links resolve it.
// Where it stops being valid: docs/accuracy.md.

// Per-link values of any lattice.
struct LatticeLinkValues {
    float value[LATTICE_MAX_LINKS];
};

// f: the share of each later scattering counted as going straight on
// ([Joseph76]'s f = g²; none for a backward medium).
float lattice_delta_fraction(float g) { return g > 0.0f ? g * g : 0.0f; }

// HG's backward half-range flux, ∫ p(θ)·max(−cos θ, 0) dΩ over the sphere:
// integrating [Ihrke07] eq. 3 over the backward hemisphere gives
// (1 − g²)/(4g²)·((1 + g) + (1 + g²)/(1 + g) − 2√(1 + g²)), which is
// (1 − g)/(1 + g + √(1 + g²))² without the cancellation near g = 0
// (1/4 there, as isotropic light; 0.0211 at g = 0.8).
float lattice_hg_backward_flux(float g) {
    float r = 1.0f + g + sqrt(1.0f + g * g);
    return (1.0f - g) / (r * r);
}

// ---- HG projected on the links ---------------------------------------------
// The HG distribution about `axis` is summed over a fixed product quadrature
// of `rings` rings of equal HG probability (midpoints of the inverse
// distribution) times LATTICE_BIRTH_AZIMUTHS azimuths, each
// direction to its nearest link (the link's Voronoi cell on the sphere);
// each link's share is the HG mass of its cell relative to an isotropic
// distribution's, times the link's weight (so g = 0 gives the weights).
// The first scattering's, per cell and frame on the GPU: 32 rings (past
// g ≈ 0.93 HG's backward share, 1/64 at 0.93, is under the first ring's and
// none of it reaches a backward link); the phase matrix's, once on the host:
// 256.
const int LATTICE_BIRTH_RINGS = 32;
const int LATTICE_PHASE_RINGS = 256;
const int LATTICE_BIRTH_AZIMUTHS = 8;

// cos θ at which the HG distribution of asymmetry g reaches probability u.
float lattice_hg_quantile(float u, float g) {
    if (abs(g) < 1e-4f) return 2.0f * u - 1.0f;
    float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u);
    return clamp((1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
}

// Quadrature direction (ring j of `rings`, azimuth k) about the unit vector `axis`;
// each ring is turned by the golden ratio of an azimuth step against the
// last. The frame about the axis is [Duff17]'s, defined for every unit
// axis.
vec3 lattice_birth_direction(vec3 axis, float g, int j, int k, int rings) {
    float mu = lattice_hg_quantile((float(j) + 0.5f) / float(rings), g);
    float s = sqrt(max(0.0f, 1.0f - mu * mu));
    float turn = 0.618034f * float(j);
    float phi = 6.2831853f * (float(k) + turn - floor(turn)) / float(LATTICE_BIRTH_AZIMUTHS);
    float sign_ = axis.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sign_ + axis.z);
    float b = axis.x * axis.y * a;
    vec3 t1 = vec3(1.0f + sign_ * axis.x * axis.x * a, sign_ * b, -sign_ * axis.x);
    vec3 t2 = vec3(b, sign_ + axis.y * axis.y * a, -axis.y);
    return mu * axis + s * (cos(phi) * t1 + sin(phi) * t2);
}

// The share of light scattered by HG about the unit vector `axis` that each
// link of a lattice of `directions` links on voxels of `voxel_size` takes;
// `cell_solid_angle`: each link's share of the sphere's directions by
// nearest link (latticeLinkSolidAngles, render/stages/LatticePhase).
//
// The projection by nearest link keeps too little of HG's backward light on
// a lattice with few directions against the axis: on 14 links, about a link,
// the five cosines 1, ±0.58, 0, −1 hold a backward half-range flux of 0.012
// where HG has 0.021 at g = 0.8, and the cells at cosine 0 take backward
// light that then never goes back. So the projection is renormalised, as
// discrete-ordinates phase functions are to keep their energy and asymmetry
// factor ([Hunter12]): each share s_i becomes s_i·(α + β μ_i + γ|μ_i|), μ_i
// the link's cosine to the axis, with α, β, γ such that the shares sum to 1,
// their mean cosine is g and their backward half-range flux is HG's
// (lattice_hg_backward_flux; Marshak's condition, which the 14 links'
// weights meet for isotropic light: what a face lets out is right). Where
// the full correction would make some share negative it is applied as far as
// keeps every share non-negative; where the three conditions cannot be told
// apart on the links (6 links about a body diagonal: every |μ_i| equal) the
// projection stays as it is.
LatticeLinkValues lattice_hg_shares(vec3 axis, float g, vec3 voxel_size, int directions,
                                    LatticeLinkValues cell_solid_angle, int rings) {
    LatticeLinkDirections links = lattice_link_directions(voxel_size, directions);
    LatticeLinkValues shares;
    for (int i = 0; i < LATTICE_MAX_LINKS; ++i) shares.value[i] = 0.0f;
    for (int j = 0; j < rings; ++j)
        for (int k = 0; k < LATTICE_BIRTH_AZIMUTHS; ++k)
            shares.value[lattice_nearest_of(lattice_birth_direction(axis, g, j, k, rings), links, directions)] += 1.0f;
    float total = 0.0f;
    for (int i = 0; i < directions; ++i) {
        shares.value[i] *= lattice_weight(lattice_link(i, directions), directions) / cell_solid_angle.value[i];
        total += shares.value[i];
    }
    // Rows: Σ s_i·b(μ_i), Σ s_i·μ_i·b(μ_i), Σ s_i·max(−μ_i, 0)·b(μ_i), b = (1, μ, |μ|).
    vec3 sums = vec3(0.0f), means = vec3(0.0f), backward = vec3(0.0f);
    for (int i = 0; i < directions; ++i) {
        shares.value[i] /= total;
        float mu = dot(links.unit[i], axis);
        vec3 basis = shares.value[i] * vec3(1.0f, mu, abs(mu));
        sums += basis;
        means += mu * basis;
        backward += max(-mu, 0.0f) * basis;
    }
    mat3 system = transpose(mat3(sums, means, backward));
    if (abs(determinant(system)) < 1e-9f) return shares;
    vec3 factors = inverse(system) * vec3(1.0f, g, lattice_hg_backward_flux(g));
    // The largest step toward the corrected shares that keeps them all ≥ 0.
    float reach = 1.0f;
    for (int i = 0; i < directions; ++i) {
        float mu = dot(links.unit[i], axis);
        float factor = factors.x + factors.y * mu + factors.z * abs(mu);
        if (factor < 0.0f) reach = min(reach, 1.0f / (1.0f - factor));
    }
    total = 0.0f;
    for (int i = 0; i < directions; ++i) {
        float mu = dot(links.unit[i], axis);
        float factor = factors.x + factors.y * mu + factors.z * abs(mu);
        shares.value[i] *= 1.0f + reach * (factor - 1.0f);
        total += shares.value[i];
    }
    // The factors solve the system in float: the total to rounding.
    for (int i = 0; i < directions; ++i) shares.value[i] /= total;
    return shares;
}

// ---- The phase matrix of later scatterings, tabulated over g ----------------
// LATTICE_PHASE_NODES values of g evenly from −1 to 1 (node k at
// −1 + 2k/(LATTICE_PHASE_NODES − 1), HG evaluated at ±0.999 at the ends);
// a cell's matrix is the linear interpolation between its g's two nodes,
// itself non-negative with columns summing to 1. Layout: entry (i, j) of
// node k at (k·directions + j)·directions + i.
const int LATTICE_PHASE_NODES = 41;

float lattice_phase_node_asymmetry(int k) {
    return clamp(-1.0f + 2.0f * float(k) / float(LATTICE_PHASE_NODES - 1), -0.999f, 0.999f);
}

// The interpolation position of g among the nodes: the lower node (x, as
// float) and the weight of the upper one (y).
vec2 lattice_phase_position(float g) {
    float u = clamp((g + 1.0f) * 0.5f * float(LATTICE_PHASE_NODES - 1), 0.0f, float(LATTICE_PHASE_NODES - 1));
    float lower = min(floor(u), float(LATTICE_PHASE_NODES - 2));
    return vec2(lower, u - lower);
}
