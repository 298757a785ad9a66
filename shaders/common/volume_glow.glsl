// A glowing volume as a photon emitter (render/stages/VolumeGlow.h): its
// emitting cells in cell order, each with its colour and the cumulative
// share of the volume's power up to and including it. GLSL only; needs
// grid_sampling.glsl, random.glsl, sampling.glsl and loop_budget.glsl.
struct GlowCell { EIKON_GPU_GLOW_CELL };
layout(std430, binding = kGlowCells) readonly buffer GlowCells { GlowCell glow_cells[]; };

// Random dimensions of a glow photon's cell and point (beyond any bounce,
// surface or roulette dimension).
const uint kGlowDimensions = 0x40000000u;

// The first cell whose cumulative share exceeds u, by bisection.
uint glow_cell_at(float u) {
    uint lo = 0u;
    uint hi = uint(glow_cells.length()) - 1u;
    spend_loops(32u);
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (glow_cells[mid].colour.w > u) hi = mid;
        else lo = mid + 1u;
    }
    return lo;
}

// Photon `photon` of the glow: a cell by its share, a point uniform in it,
// a direction uniform over the sphere from the stratified (u.x, u.y); the
// power is the emitter's per-photon power times the cell's colour.
void emit_glow_photon(uint photon, vec2 u, vec3 photon_power, out vec3 x, out vec3 direction, out vec3 emitted) {
    GlowCell picked = glow_cells[glow_cell_at(random_uniform(seed, photon, kGlowDimensions))];
    ivec3 r = grid.resolution.xyz;
    int index = int(picked.cell.x);
    vec3 corner = vec3(index % r.x, (index / r.x) % r.y, index / (r.x * r.y));
    vec3 inside = vec3(random_uniform(seed, photon, kGlowDimensions + 1u), random_uniform(seed, photon, kGlowDimensions + 2u),
                       random_uniform(seed, photon, kGlowDimensions + 3u));
    x = grid.bounds_min.xyz + (corner + inside) * grid.voxel_size.xyz;
    direction = sample_cone(vec3(0.0f, 0.0f, 1.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f), 2.0f, u.x, u.y);
    emitted = photon_power * picked.colour.rgb;
}
