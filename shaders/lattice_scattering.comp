// Multiple scattering by lattice-Boltzmann lighting ([Bernabei12] §III-C,
// eqs. 4–5): per voxel and channel, the photon densities f_i along the
// lattice's links (common/lattice_directions.glsl) collide and stream,
//   f_i(r + c_i, t + 1) = Θ f(r, t),
// until the lattice holds the steady flow of light scattered at least once.
// Its source is the power the light pass's photons lose to scattering in
// each voxel (RawScattered, tallied by the σs/κ their attenuation used),
// born isotropically.
//
// The collision is eq. 5 in exponential form. The paper's linear
// Θ_ii = 1 − σt + σs/6 (σ per lattice step) goes negative once a voxel is
// thicker than one mean free path; here a density arriving through link i
// crosses its voxel with transmittance E_i = exp(−σt ℓ_i), the part
// 1 − E_i that interacts scatters with the albedo a = σs/σt and is absorbed
// otherwise, and light born in a voxel (scattered, or the source) leaves
// along link i with weight w_i after half a link, exp(−σt ℓ_i/2), what
// interacts on the way being born again in the same voxel (a geometric
// series, summed in closed form). In the limit of thin voxels this is the
// paper's Θ. Absorbed light leaves the lattice (the paper's rest density
// Θ_0j = σa, which this lattice tallies instead of keeping).
//
// Sharp surfaces (EIKON_LATTICE_INTERFACES): a link whose two cell centres
// lie inside different sharp objects of different index crosses an
// interface. Of the density it carries the diffuse Fresnel reflectance
// R_d(n_from → n_to) (common/fresnel.glsl; its total-internal-reflection
// part alone where the object's Fresnel reflection is off) returns to the
// cell it left along the opposite link, and the rest goes on: the lattice
// keeps no finer angular detail than an isotropic radiance, so each link
// takes the hemispherical average, which lets the continuum's flux through
// the interface on a lattice whose half-range flux is the continuum's
// (14 links). The reflection is bounce-back, not a mirror (a lattice has
// the mirror direction only for axis-aligned faces); the refraction of the
// transmitted part is not followed. Smooth index changes are not
// interfaces: light diffuses straight through them.
// Anisotropic media (EIKON_LATTICE_DIRECTED). The light pass's beam is
// attenuated by the true σt and its single scattering rendered with the
// true Henyey–Greenstein phase function; the lattice's source, what the
// beam loses to scattering (σs·φ_c), is light scattered exactly once. It is
// born in the HG distribution about the beam projected on the links
// (common/lattice_phase.glsl; the shares found once a frame by pass 5
// into LatticeBirth): a g = 0.8 medium sends most of it on forward. Every
// later scattering counts its δ-Eddington forward peak f = g² as no
// scattering ([Joseph76]), the lattice's extinction and albedo being
// σt′ = σa + σs(1 − f) and σs(1 − f)/σt′, and scatters the rest from link j
// to link i by the phase matrix P′_ij (common/lattice_phase.glsl; the
// table over g in LatticePhase, interpolated at the cell's g): the light
// arriving through link j and the source born on link j that interact in
// this voxel scatter in their first generation by P′_·j (later
// generations within the voxel isotropically: a voxel is thin against a
// mean free path within the validated resolution). Every watt is counted
// once: the unscattered beam by the light pass, everything scattered by
// the lattice. The beam's
// direction m and its coherence |m| ([Sun08] §4.4, as the view pass reads
// it) come from the light pass's fluence and power-weighted direction; the
// incoherent part is born isotropically. Where it stops being valid:
// docs/accuracy.md.
//
// Passes (EIKON_LATTICE_PASS): 4 once a frame, each cell's interface
// links and index (LatticeInterfaces); 5 once a frame with
// EIKON_LATTICE_DIRECTED, each cell's birth shares (LatticeBirth); 0 one collide-and-stream step of one channel
// from LatticeIn to LatticeOut; 1 the fluence at the convergence probes
// (every probe_stride-th cell on each axis); 2 the fluence of every cell
// into MultipleFluence and per work group the power ledger (source,
// absorbed, escaped through each grid face), summed on the host in a fixed
// order so that a run gives the same bits every time; 3, the survey, whether
// the three channels differ anywhere (medium, or source by more than float
// rounding): where they do not, one channel is solved and its densities
// copied to the other two; and the voxels too thick for the lattice's float
// arithmetic (LatticeScattering.h, the depth limit).
// Program options: EIKON_LATTICE_DIRECTIONS (6, 14 or 18), EIKON_LATTICE_PASS,
// EIKON_HAS_ANISOTROPY, EIKON_LATTICE_INTERFACES, EIKON_LATTICE_DIRECTED.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/grid_sampling.glsl"
#include "common/lattice_directions.glsl"
#include "common/lattice_phase.glsl"

#ifndef EIKON_LATTICE_DIRECTIONS
#define EIKON_LATTICE_DIRECTIONS 6
#endif
#ifndef EIKON_LATTICE_PASS
#define EIKON_LATTICE_PASS 0
#endif
#ifndef EIKON_HAS_ANISOTROPY
#define EIKON_HAS_ANISOTROPY 0
#endif
#ifndef EIKON_LATTICE_INTERFACES
#define EIKON_LATTICE_INTERFACES 0
#endif
#ifndef EIKON_LATTICE_DIRECTED
#define EIKON_LATTICE_DIRECTED 0
#endif
#if EIKON_LATTICE_INTERFACES
// Per cell: x the slots of its links that cross an interface; y, z (float
// bits) the reflectance of light leaving the cell across it and of light
// entering it (a cell whose links cross into two different indices takes
// the last one's, and the exchange between it and the other is not quite
// conservative).
#if EIKON_LATTICE_PASS == 4
#include "common/fresnel.glsl"
#include "common/sharp_surfaces.glsl"
#include "common/sharp_surface_blocks.glsl"
layout(std430, binding = kLatticeInterfaces) buffer LatticeInterfaces { uvec4 interfaces[]; };
#else
layout(std430, binding = kLatticeInterfaces) readonly buffer LatticeInterfaces { uvec4 interfaces[]; };
#endif
#endif
const int DIRECTIONS = EIKON_LATTICE_DIRECTIONS;
#if EIKON_LATTICE_DIRECTED
// Per link slot and cell (slot-major, as the densities): the share of the
// cell's source born along the link, summing to 1 over its links.
#if EIKON_LATTICE_PASS == 5
layout(std430, binding = kLatticeBirth) buffer LatticeBirth { float birth_share[]; };  // collide reads it, compiled here too
// The light pass's beam: smoothed fluence (RGB) and power-weighted direction (xyz) per cell.
layout(std430, binding = kFluence) readonly buffer Fluence { float beam_fluence[]; };
layout(std430, binding = kFluenceDirection) readonly buffer FluenceDirection { float beam_direction[]; };
// Each link's share of the sphere's directions by nearest link (its
// Voronoi cell), on this grid's voxels (latticeLinkSolidAngles); the first
// DIRECTIONS are set.
uniform float link_solid_angle[LATTICE_MAX_LINKS];
#else
layout(std430, binding = kLatticeBirth) readonly buffer LatticeBirth { float birth_share[]; };
#endif
#endif

layout(std430, binding = kRawScattered) readonly buffer RawScattered { float raw_scattered[]; };
layout(std430, binding = kLatticeIn) readonly buffer LatticeIn { float density_in[]; };
#if EIKON_LATTICE_PASS == 0
layout(std430, binding = kLatticeOut) writeonly buffer LatticeOut { float density_out[]; };
#elif EIKON_LATTICE_PASS == 1
layout(std430, binding = kLatticeProbes) writeonly buffer LatticeProbes { float probe_fluence[]; };
uniform int probe_stride;
#elif EIKON_LATTICE_PASS == 3
// channels_differ: 1 where the channels' media or sources differ; thick_voxels
// and deepest_depth (float bits): the cells whose retention is below
// min_retention in some channel, and the largest optical depth across the
// shortest voxel edge among them; coarse_voxels and coarsest_depth (float
// bits): the scattering cells whose optical depth (the lattice's σt′) along the longest
// voxel edge exceeds validated_depth (LatticeScattering.h, the validated
// resolution), and the largest such depth of any scattering cell.
layout(std430, binding = kLatticeSurvey) buffer LatticeSurvey { EIKON_GPU_LATTICE_SURVEY };
uniform float min_retention;
uniform float validated_depth;
#else
layout(std430, binding = kMultipleFluence) writeonly buffer MultipleFluence { float multiple_fluence[]; };
layout(std430, binding = kLatticeTallies) writeonly buffer LatticeTallies { vec4 group_tallies[]; };
shared float group_values[64 * 8];
#endif
#if EIKON_HAS_ANISOTROPY
layout(binding = kAnisotropyTexture) uniform sampler3D anisotropy_texture;
// The phase matrix of later scatterings over g (LatticePhase; layout:
// common/lattice_phase.glsl); collide reads it, compiled in every pass.
layout(std430, binding = kLatticePhase) readonly buffer LatticePhase { float phase_matrix[]; };
#endif

uniform int channel;     // 0, 1, 2: the lattice runs one channel at a time
uniform ivec3 periodic;  // 1 on an axis whose faces wrap (slab and infinite-medium checks); 0: outflow

int cell_count() { return grid.resolution.x * grid.resolution.y * grid.resolution.z; }

// The cell a link from `cell` along `offset` reaches: wrapped on periodic
// axes; x = −1 where it leaves the grid.
ivec3 linked_cell(ivec3 cell, ivec3 offset) {
    ivec3 next = cell + offset;
    ivec3 size = grid.resolution.xyz;
    for (int axis = 0; axis < 3; ++axis) {
        if (next[axis] >= 0 && next[axis] < size[axis]) continue;
        if (periodic[axis] == 0) return ivec3(-1);
        next[axis] = (next[axis] + size[axis]) % size[axis];
    }
    return next;
}

#if EIKON_LATTICE_INTERFACES && EIKON_LATTICE_PASS == 4
float interface_reflectance(float n_i, float n_t, bool fresnel) {
    if (fresnel) return diffuse_fresnel_reflectance(n_i, n_t);
    return n_i > n_t ? 1.0f - (n_t / n_i) * (n_t / n_i) : 0.0f;  // total internal reflection alone
}
#endif

struct Collision {
    float outgoing[DIRECTIONS];  // W along each link
    float absorbed;              // W
    float source;                // W born from the light pass's scattering
    float fluence;               // W/m²
};

// A cell's medium as the lattice sees it in channel `c`: extinction and
// albedo after the δ-Eddington scaling, and the HG asymmetry.
struct LatticeMedium {
    float sigma_t;  // 1/m
    float albedo;
    float forward;  // f, the share of scattering that goes straight on
    float g;        // the Henyey–Greenstein asymmetry
};

LatticeMedium medium_at(ivec3 cell, int c) {
    float kappa = texelFetch(extinction_texture, cell, 0)[c];
    float sigma_s = texelFetch(scattering_texture, cell, 0)[c];
#if EIKON_HAS_ANISOTROPY
    float g = texelFetch(anisotropy_texture, cell, 0).r;
#else
    float g = 0.0f;
#endif
    LatticeMedium m;
    m.g = g;
    m.forward = lattice_delta_fraction(g);
    float reduced = sigma_s * (1.0f - m.forward);
    m.sigma_t = max(kappa - sigma_s + reduced, 0.0f);
    m.albedo = m.sigma_t > 0.0f ? min(reduced / m.sigma_t, 1.0f) : 0.0f;
    return m;
}

Collision collide(ivec3 cell) {
    LatticeMedium medium = medium_at(cell, channel);
    float sigma_t = medium.sigma_t;
    float albedo = medium.albedo;
    float volume = grid.voxel_size.w;
    int index = grid_linear_index(cell);

    Collision c;
    c.source = raw_scattered[3 * index + channel];
    int cells = cell_count();
    // Per length class (common/lattice_directions.glsl): a link's
    // transmittance, its mean transmittance, and those of half a link.
    const int K = LATTICE_LENGTH_CLASSES;
    float transmittance[K], track_per_length[K], half_transmittance[K], half_track_per_length[K], link_length[K];
    for (int k = 0; k < K; ++k) {
        bool used = k < 3 || (DIRECTIONS == 18 && k < 6) || (DIRECTIONS == 14 && k == 6);
        if (!used) continue;
        ivec3 offset = lattice_offset(lattice_class_direction(k));
        link_length[k] = length(vec3(offset) * grid.voxel_size.xyz);
        float depth = sigma_t * link_length[k];
        half_transmittance[k] = exp(-0.5f * depth);
        transmittance[k] = half_transmittance[k] * half_transmittance[k];
        track_per_length[k] = mean_transmittance(depth);
        half_track_per_length[k] = mean_transmittance(0.5f * depth);
    }
    float interactions = 0.0f;  // W of the arriving light that scatters or is absorbed in this voxel
    float track = 0.0f;         // W·m: its track length
    float escape = 0.0f;        // share of light born here that leaves its half link unscattered
    float half_track = 0.0f;    // m: the mean track of that half link
    float half_link[DIRECTIONS];  // transmittance of each half link, weighted
    float source_escape = 0.0f;   // share of the source that leaves its half link unscattered
    float source_track = 0.0f;    // m: the source's mean track over that half link
#if EIKON_HAS_ANISOTROPY
    float interacting_on[DIRECTIONS];  // W: of what arrives through link j or is born on it, what interacts here
#endif
#if EIKON_LATTICE_INTERFACES
    uvec4 here = interfaces[index];
#endif
    for (int i = 0; i < DIRECTIONS; ++i) {
        int d = lattice_link(i, DIRECTIONS);
        int k = lattice_length_class(d);
        ivec3 from = linked_cell(cell, -lattice_offset(d));
        float arriving = from.x < 0 ? 0.0f : density_in[i * cells + grid_linear_index(from)];
#if EIKON_LATTICE_INTERFACES
        // Across an interface: what the neighbour sent and the interface
        // transmits, plus what this cell sent toward it last step and the
        // interface reflects.
        int back = lattice_slot(lattice_opposite(d), DIRECTIONS);  // this cell's link toward `from`
        if (((here.x >> uint(back)) & 1u) != 0u)
            arriving = (1.0f - uintBitsToFloat(here.z)) * arriving +
                       uintBitsToFloat(here.y) * density_in[back * cells + index];
#endif
        float weight = lattice_weight(d, DIRECTIONS);
#if EIKON_LATTICE_DIRECTED
        float share = birth_share[i * cells + index];
#else
        float share = weight;
#endif
        // The source leaves along its links after half a link, like light
        // born by the collision, but in its own shares.
        float source_out = c.source * share * half_transmittance[k];
        c.outgoing[i] = arriving * transmittance[k] + source_out;
        source_escape += share * half_transmittance[k];
        source_track += share * 0.5f * link_length[k] * half_track_per_length[k];
        interactions += arriving * (1.0f - transmittance[k]);
#if EIKON_HAS_ANISOTROPY
        interacting_on[i] = arriving * (1.0f - transmittance[k]) + c.source * share * (1.0f - half_transmittance[k]);
#endif
        track += arriving * link_length[k] * track_per_length[k];
        half_link[i] = weight * half_transmittance[k];
        escape += half_link[i];
        half_track += weight * 0.5f * link_length[k] * half_track_per_length[k];
    }
    // What interacts here — arriving light and the source on its half links
    // — scatters with the albedo. All generations born isotropically here:
    // born / (1 − a(1 − escape)). A voxel so thick that its escape
    // underflows keeps its born light (absorbed); the survey pass finds
    // voxels whose retention is too small for float (LatticeScattering.h,
    // the depth limit).
    float interacting = interactions + c.source * (1.0f - source_escape);
    float retention = max(1.0f - albedo * (1.0f - escape), 1e-7f);
#if EIKON_HAS_ANISOTROPY
    // The first generation scatters from link j to link i by the phase
    // matrix P′ at the cell's g, leaving along link i after half a link;
    // what interacts on those half links is born again isotropically, all
    // its generations as above. Every watt that interacts here is absorbed,
    // leaves, or is born again, so the ledger closes whatever P′ rounds to.
    vec2 position = lattice_phase_position(medium.g);
    int lower = int(position.x) * DIRECTIONS * DIRECTIONS;
    int upper = lower + DIRECTIONS * DIRECTIONS;
    float first_born = 0.0f;      // W scattered in the first generation
    float first_escaping = 0.0f;  // W of it that leaves its half links unscattered
    float first_track = 0.0f;     // W·m: its track over them
    for (int i = 0; i < DIRECTIONS; ++i) {
        float scattered = 0.0f;
        for (int j = 0; j < DIRECTIONS; ++j)
            scattered += interacting_on[j] * mix(phase_matrix[lower + j * DIRECTIONS + i],
                                                 phase_matrix[upper + j * DIRECTIONS + i], position.y);
        scattered *= albedo;
        int k = lattice_length_class(lattice_link(i, DIRECTIONS));
        c.outgoing[i] += scattered * half_transmittance[k];
        first_born += scattered;
        first_escaping += scattered * half_transmittance[k];
        first_track += scattered * 0.5f * link_length[k] * half_track_per_length[k];
    }
    float again = first_born - first_escaping;  // W: interacts on the first generation's half links
    float born = albedo * again;
    float escaping = born * (escape / retention);
    c.absorbed = (interacting - first_born) + (again - escaping);
    c.fluence = (track + c.source * source_track + first_track + born / retention * half_track) / volume;
#else
    float born = albedo * interacting;
    float escaping = born * (escape / retention);
    c.absorbed = (1.0f - albedo) * interacting + (born - escaping);
    c.fluence = (track + c.source * source_track + born / retention * half_track) / volume;
#endif
    for (int i = 0; i < DIRECTIONS; ++i) c.outgoing[i] += escape > 0.0f ? escaping * (half_link[i] / escape) : 0.0f;
    return c;
}

#if EIKON_LATTICE_PASS == 4
vec3 cell_centre(ivec3 cell) { return grid.bounds_min.xyz + (vec3(cell) + 0.5f) * grid.voxel_size.xyz; }
#endif

void main() {
#if EIKON_LATTICE_PASS == 5
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    int index = grid_linear_index(cell);
    int cells = cell_count();
    vec3 sum = vec3(beam_direction[3 * index], beam_direction[3 * index + 1], beam_direction[3 * index + 2]);
    float total = beam_fluence[3 * index] + beam_fluence[3 * index + 1] + beam_fluence[3 * index + 2];
    float coherence = total > 0.0f ? min(length(sum) / total, 1.0f) : 0.0f;
    float g = texelFetch(anisotropy_texture, cell, 0).r;
    LatticeLinkValues shares;
    if (coherence > 0.0f && g != 0.0f) {
        LatticeLinkValues cells_on_sphere;
        for (int i = 0; i < LATTICE_MAX_LINKS; ++i) cells_on_sphere.value[i] = link_solid_angle[i];
        shares = lattice_hg_shares(normalize(sum), g, grid.voxel_size.xyz, DIRECTIONS, cells_on_sphere,
                                   LATTICE_BIRTH_RINGS);
    } else {
        coherence = 0.0f;
        for (int i = 0; i < LATTICE_MAX_LINKS; ++i) shares.value[i] = 0.0f;
    }
    for (int i = 0; i < DIRECTIONS; ++i)
        birth_share[i * cells + index] =
            (1.0f - coherence) * lattice_weight(lattice_link(i, DIRECTIONS), DIRECTIONS) + coherence * shares.value[i];
#elif EIKON_LATTICE_PASS == 4
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    vec3 x = cell_centre(cell);
    uint mask = inside_mask_at(x);
    float n_here = reference_index() + sample_gradient_and_delta(x).w + sharp_index_offset(mask);
    uvec4 record = uvec4(0u);
    for (int i = 0; i < DIRECTIONS; ++i) {
        ivec3 next = linked_cell(cell, lattice_offset(lattice_link(i, DIRECTIONS)));
        if (next.x < 0) continue;
        vec3 y = cell_centre(next);
        uint beyond = inside_mask_at(y);
        if (beyond == mask) continue;
        float n_beyond = reference_index() + sample_gradient_and_delta(y).w + sharp_index_offset(beyond);
        if (n_beyond == n_here) continue;
        record.x |= 1u << uint(i);
        uint crossed = mask ^ beyond;
        bool fresnel = false;
        for (uint k = 0u; k < sharp_surface_count; ++k)
            if (((crossed >> k) & 1u) != 0u && sharp_surfaces[k].optics.y > 0.5f) fresnel = true;
        record.y = floatBitsToUint(interface_reflectance(n_here, n_beyond, fresnel));
        record.z = floatBitsToUint(interface_reflectance(n_beyond, n_here, fresnel));
    }
    interfaces[grid_linear_index(cell)] = record;
#elif EIKON_LATTICE_PASS == 3
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    // Light born here leaves in the share escape / (1 − a(1 − escape)) per
    // generation, its denominator rounded to float near 1 (collide).
    bool thick = false;
    float deepest = 0.0f, coarsest = 0.0f;
    float shortest_edge = min(grid.voxel_size.x, min(grid.voxel_size.y, grid.voxel_size.z));
    float longest_edge = max(grid.voxel_size.x, max(grid.voxel_size.y, grid.voxel_size.z));
    for (int c = 0; c < 3; ++c) {
        LatticeMedium m = medium_at(cell, c);
        if (m.albedo == 0.0f) continue;
        coarsest = max(coarsest, m.sigma_t * longest_edge);
        float escape = 0.0f;
        for (int i = 0; i < DIRECTIONS; ++i) {
            int d = lattice_link(i, DIRECTIONS);
            float depth = m.sigma_t * length(vec3(lattice_offset(d)) * grid.voxel_size.xyz);
            escape += lattice_weight(d, DIRECTIONS) * exp(-0.5f * depth);
        }
        if (1.0f - m.albedo * (1.0f - escape) < min_retention) {
            thick = true;
            deepest = max(deepest, m.sigma_t * shortest_edge);
        }
    }
    if (thick) {
        atomicAdd(thick_voxels, 1u);
        atomicMax(deepest_depth, floatBitsToUint(deepest));  // non-negative floats order as their bits
    }
    if (coarsest > validated_depth) atomicAdd(coarse_voxels, 1u);
    if (coarsest > 0.0f) atomicMax(coarsest_depth, floatBitsToUint(coarsest));
    int index = 3 * grid_linear_index(cell);
    vec3 kappa = texelFetch(extinction_texture, cell, 0).rgb;
    vec3 sigma_s = texelFetch(scattering_texture, cell, 0).rgb;
    vec3 source = vec3(raw_scattered[index], raw_scattered[index + 1], raw_scattered[index + 2]);
    // The sources are float sums in an order the channels need not share:
    // equal to a part in 1e6 counts as the same.
    float largest = max(source.r, max(source.g, source.b));
    if (kappa.r != kappa.g || kappa.g != kappa.b || sigma_s.r != sigma_s.g || sigma_s.g != sigma_s.b ||
        largest - min(source.r, min(source.g, source.b)) > 1e-6f * largest)
        atomicOr(channels_differ, 1u);
#elif EIKON_LATTICE_PASS == 1
    ivec3 probe = ivec3(gl_GlobalInvocationID);
    ivec3 probes = (grid.resolution.xyz + probe_stride - 1) / probe_stride;
    if (any(greaterThanEqual(probe, probes))) return;
    ivec3 cell = min(probe * probe_stride + probe_stride / 2, grid.resolution.xyz - 1);
    probe_fluence[probe.x + probes.x * (probe.y + probes.y * probe.z)] = collide(cell).fluence;
#else
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    bool inside = all(lessThan(cell, grid.resolution.xyz));
#if EIKON_LATTICE_PASS == 0
    if (!inside) return;
    Collision c = collide(cell);
    int cells = cell_count();
    int index = grid_linear_index(cell);
    for (int i = 0; i < DIRECTIONS; ++i) density_out[i * cells + index] = c.outgoing[i];
#else
    // Ledger values of this cell: source, absorbed, escaped through −x, +x, −y, +y, −z, +z.
    float values[8] = float[8](0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f);
    if (inside) {
        Collision c = collide(cell);
        multiple_fluence[3 * grid_linear_index(cell) + channel] = c.fluence;
        values[0] = c.source;
        values[1] = c.absorbed;
        for (int i = 0; i < DIRECTIONS; ++i) {
            ivec3 offset = lattice_offset(lattice_link(i, DIRECTIONS));
            if (linked_cell(cell, offset).x >= 0) continue;
            // The first axis on which the link leaves names the face.
            ivec3 next = cell + offset;
            int face = 0;
            for (int axis = 2; axis >= 0; --axis)
                if (periodic[axis] == 0 && (next[axis] < 0 || next[axis] >= grid.resolution[axis]))
                    face = 2 * axis + (offset[axis] > 0 ? 1 : 0);
            values[2 + face] += c.outgoing[i];
        }
    }
    uint local = gl_LocalInvocationIndex;
    for (int k = 0; k < 8; ++k) group_values[int(local) * 8 + k] = values[k];
    barrier();
    if (local == 0u) {
        float sums[8] = float[8](0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f);
        for (int l = 0; l < 64; ++l)
            for (int k = 0; k < 8; ++k) sums[k] += group_values[l * 8 + k];
        uint group = gl_WorkGroupID.x + gl_NumWorkGroups.x * (gl_WorkGroupID.y + gl_NumWorkGroups.y * gl_WorkGroupID.z);
        group_tallies[2u * group] = vec4(sums[0], sums[1], sums[2], sums[3]);
        group_tallies[2u * group + 1u] = vec4(sums[4], sums[5], sums[6], sums[7]);
    }
#endif
#endif
}
