// Photon pass (Sun et al. 2008, §4.3–4.4): each invocation emits one photon
// toward the traced region, flies it straight outside the field grid
// (common/straight_flight.glsl) and
// marches it with fixed-step forward Euler of the ray equation inside,
// attenuating its power by Beer–Lambert, depositing fluence by the
// track-length estimator and irradiance where it lands on a receiver.
layout(local_size_x = 64) in;

#include "common/grid_sampling.glsl"
#include "common/random.glsl"
#include "common/ray_step.glsl"
#include "common/attenuation.glsl"
#include "common/sampling.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/straight_flight.glsl"

// Optional path recording for tests and export: the first
// EIKON_RECORDED_PHOTONS photons of a pass store up to EIKON_RECORD_PATHS
// vertices each (0: no recording).
#ifndef EIKON_RECORD_PATHS
#define EIKON_RECORD_PATHS 0
#endif
#ifndef EIKON_RECORDED_PHOTONS
#define EIKON_RECORDED_PHOTONS 64
#endif

struct Emitter {
    vec4 origin;        // w: kind (0 point, 1 directional)
    vec4 axis;          // w: point: cos of cone half-angle; directional: disk radius
    vec4 tangent;
    vec4 bitangent;
    vec4 photon_power;  // rgb W per photon
    uvec4 photons;      // x: first photon, y: count, z, w: strata
};
layout(std430, binding = 2) readonly buffer Emitters { Emitter emitters[]; };

#if EIKON_HAS_SCATTERING
layout(std430, binding = 5) buffer Fluence { float fluence[]; };  // RGB per cell, W/m²
#endif

// C++ mirror: layout::GpuPhotonStats (powers in 64-bit fixed point).
const int TALLY_EMITTED = 0;
const int TALLY_ABSORBED = 1;
const int TALLY_ESCAPED = 2;
const int TALLY_RECEIVED = 3;
const int TALLY_CUT_OFF = 4;
const int TALLY_BLOCKED = 5;
layout(std430, binding = 6) buffer PhotonStats {
    uint power_tallies[36];   // [2·(3·tally + channel) + word]
    uint photon_tallies[4];   // escaped, received, cut off, blocked
    uint step_tallies[4];     // low word, high word, max invariant error bits
};

#if EIKON_RECORD_PATHS > 0
layout(std430, binding = 9) writeonly buffer PhotonPaths { vec4 path_vertices[]; };  // xyz, w: 1 written
#endif

uniform uint photon_offset;    // index of this batch's first photon
uniform uint batch_size;
uniform uint emitter_count;
uniform uint seed;
uniform float step_length;     // Δs in metres
uniform uint max_steps;        // trapped-ray cap
uniform float power_cutoff;    // stop once every channel is below this fraction of the emitted power
uniform vec3 power_unit;       // W per fixed-point tally unit, per channel

// Adds to a 64-bit counter held as two words, carrying into the high word.
void add_wide(uint low_word, uint value) {
    uint before = atomicAdd(power_tallies[low_word], value);
    if (before + value < before) atomicAdd(power_tallies[low_word + 1u], 1u);
}

void add_power(int tally, vec3 power) {
    uvec3 units = uvec3(power / power_unit + 0.5f);
    for (int channel = 0; channel < 3; ++channel)
        if (units[channel] != 0u) add_wide(uint(2 * (3 * tally + channel)), units[channel]);
}

void record_vertex(uint photon, uint vertex, vec3 x) {
#if EIKON_RECORD_PATHS > 0
    if (photon < uint(EIKON_RECORDED_PHOTONS) && vertex < uint(EIKON_RECORD_PATHS))
        path_vertices[photon * uint(EIKON_RECORD_PATHS) + vertex] = vec4(x, 1.0f);
#endif
}

// Irradiance estimate on the receiver map: the photon's power is shared
// among the four nearest texel centres with bilinear (tent) weights, which
// sum to one, so the map's integral is exactly the received power.
void deposit_on_receiver(ReceiverHit hit, vec3 power) {
    int resolution = int(receivers[hit.receiver].map.y);
    vec2 texel = hit.map_uv * float(resolution) - 0.5f;
    ivec2 base = ivec2(floor(texel));
    vec2 f = texel - vec2(base);
    vec3 irradiance = power / receivers[hit.receiver].normal.w;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            ivec2 t = clamp(base + ivec2(i, j), ivec2(0), ivec2(resolution - 1));
            uint index = 3u * (receivers[hit.receiver].map.x + uint(t.y * resolution + t.x));
            float weight = (i == 0 ? 1.0f - f.x : f.x) * (j == 0 ? 1.0f - f.y : f.y);
            atomicAdd(receiver_irradiance[index + 0u], weight * irradiance.r);
            atomicAdd(receiver_irradiance[index + 1u], weight * irradiance.g);
            atomicAdd(receiver_irradiance[index + 2u], weight * irradiance.b);
        }
    }
}

void deposit_fluence(vec3 x, vec3 power_times_length) {
#if EIKON_HAS_SCATTERING
    uint index = 3u * uint(grid_linear_index(grid_cell(x)));
    vec3 value = power_times_length / grid.voxel_size.w;
    atomicAdd(fluence[index + 0u], value.r);
    atomicAdd(fluence[index + 1u], value.g);
    atomicAdd(fluence[index + 2u], value.b);
#endif
}

uint emitter_of(uint photon) {
    uint e = 0u;
    while (e + 1u < emitter_count && photon >= emitters[e + 1u].photons.x) ++e;
    return e;
}

// Stratified (u1, u2): the first strata.x·strata.y photons of an emitter each
// take one jittered cell of the unit square; any remainder is uniform.
vec2 emission_sample(Emitter emitter, uint photon) {
    uint local = photon - emitter.photons.x;
    vec2 jitter = vec2(random_uniform(seed, photon, 0u), random_uniform(seed, photon, 1u));
    uvec2 strata = emitter.photons.zw;
    if (local >= strata.x * strata.y) return jitter;
    return (vec2(local % strata.x, local / strata.x) + jitter) / vec2(strata);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= batch_size) return;
    uint photon = photon_offset + id;
    Emitter emitter = emitters[emitter_of(photon)];
    vec2 u = emission_sample(emitter, photon);

    vec3 x;
    vec3 direction;
    if (emitter.origin.w == 0.0f) {
        x = emitter.origin.xyz;
        direction = sample_cone(emitter.axis.xyz, emitter.tangent.xyz, emitter.bitangent.xyz, emitter.axis.w, u.x, u.y);
    } else {
        vec2 disk = emitter.axis.w * sample_disk_concentric(u.x, u.y);
        x = emitter.origin.xyz + disk.x * emitter.tangent.xyz + disk.y * emitter.bitangent.xyz;
        direction = emitter.axis.xyz;
    }

    vec3 x_lost = vec3(0.0f);  // Kahan compensation of x
    vec3 power = emitter.photon_power.rgb;
    vec3 absorbed = vec3(0.0f);
    float cutoff = power_cutoff * max(power.r, max(power.g, power.b));
    vec3 v = reference_index() * direction;
    uint steps = 0u;
    uint vertex = 0u;
    float max_invariant_error = 0.0f;
    int fate = TALLY_ESCAPED;
    record_vertex(photon, vertex++, x);

    for (;;) {
        if (!grid_contains(x)) {
            vec3 d = normalize(v);
            StraightFlight flight = fly_straight(x, d);
            if (flight.hit.receiver >= 0) {
                x = x + flight.distance * d;
                record_vertex(photon, vertex++, x);
                fate = flight.hit.lit_side ? TALLY_RECEIVED : TALLY_BLOCKED;
                if (flight.hit.lit_side) deposit_on_receiver(flight.hit, power);
                break;
            }
            if (!flight.enters_grid) {
                record_vertex(photon, vertex++, x + flight.distance * d);
                fate = TALLY_ESCAPED;
                break;
            }
            x = grid_entry_point(x, d, flight);
            x_lost = vec3(0.0f);
            if (!grid_contains(x)) continue;
            // Keep |v| = n at entry so the invariant starts exact.
            v = (reference_index() + sample_gradient_and_delta(x).w) * d;
            record_vertex(photon, vertex++, x);
            continue;
        }
        if (steps >= max_steps) {
            fate = TALLY_CUT_OFF;
            break;
        }
        vec4 field = sample_gradient_and_delta(x);
        float n = reference_index() + field.w;
        max_invariant_error = max(max_invariant_error, eikonal_invariant_error(v, n));
        vec3 start = x;
        eikonal_euler_step(x, x_lost, v, n, field.xyz, step_length);
        ++steps;

        ReceiverHit hit = first_receiver_crossing(start, x);
        float travelled = hit.receiver >= 0 ? hit.fraction * step_length : step_length;
        vec3 kappa = sample_extinction(start);
        deposit_fluence(0.5f * (start + x), power * attenuated_track_length(kappa, travelled));
        vec3 transmitted = power * beer_lambert_transmittance(kappa, travelled);
        absorbed += power - transmitted;
        power = transmitted;

        if (hit.receiver >= 0) {
            x = mix(start, x, hit.fraction);
            record_vertex(photon, vertex++, x);
            fate = hit.lit_side ? TALLY_RECEIVED : TALLY_BLOCKED;
            if (hit.lit_side) deposit_on_receiver(hit, power);
            break;
        }
        record_vertex(photon, vertex++, x);
        if (max(power.r, max(power.g, power.b)) < cutoff) {
            fate = TALLY_CUT_OFF;
            break;
        }
        if (!grid_contains(x)) v = reference_index() * normalize(v);
    }

    add_power(TALLY_EMITTED, emitter.photon_power.rgb);
    add_power(TALLY_ABSORBED, absorbed);
    add_power(fate, power);
    atomicAdd(photon_tallies[fate - TALLY_ESCAPED], 1u);
    uint steps_before = atomicAdd(step_tallies[0], steps);
    if (steps_before + steps < steps_before) atomicAdd(step_tallies[1], 1u);
    atomicMax(step_tallies[2], floatBitsToUint(max_invariant_error));
}
