// Receiver irradiance from the light pass's fixed-point texel tallies:
// E = units · unit / texel area per channel, then one of
// - kernel_radius 1 (`receivers[].filter: "binomial"`): the 3×3 binomial
//   kernel ([1 2 1]/4 along each axis) — the density estimate the view pass
//   reads by default for photons;
// - kernel_radius 0 (`"none"`, the wavefront's default): each texel alone;
// - kernel_radius −1 (`"adaptive"`): a tent kernel whose radius is the
//   smallest of 0 … kMaxAdaptiveRadius texels whose square holds about
//   kAdaptivePhotons photons (counted as units over the units of the
//   brightest photon), so that bright caustics stay sharp while faint,
//   sparsely hit texels are smoothed as far as they need.
// Weights outside the map are left out and the rest renormalised.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = kReceiverTallies) readonly buffer ReceiverTallies { uint receiver_tallies[]; };
layout(std430, binding = kReceiverMaps) writeonly buffer ReceiverMaps { float receiver_irradiance[]; };

uniform uint first_texel;
uniform int resolution;
uniform float texel_area;
uniform vec3 power_unit;
uniform float units_per_photon;  // tally units of one photon of the brightest light (per channel)
uniform int kernel_radius;       // 1: the 3×3 binomial; 0: none; −1: adaptive

const int kMaxAdaptiveRadius = 4;
const float kAdaptivePhotons = 128.0f;

bool on_map(ivec2 texel) { return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(resolution))); }

vec3 units_of(ivec2 texel) {
    uint base = 6u * (first_texel + uint(texel.y * resolution + texel.x));
    vec3 units;
    for (int channel = 0; channel < 3; ++channel) {
        uint low = receiver_tallies[base + uint(2 * channel)];
        uint high = receiver_tallies[base + uint(2 * channel) + 1u];
        units[channel] = float(high) * 4294967296.0f + float(low);
    }
    return units;
}

// The smallest radius whose square of texels holds kAdaptivePhotons photons.
int adaptive_radius(ivec2 texel) {
    float photons = 0.0f;
    for (int r = 0; r < kMaxAdaptiveRadius; ++r) {
        // The ring of texels at Chebyshev distance r.
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                if (max(abs(dx), abs(dy)) != r || !on_map(texel + ivec2(dx, dy))) continue;
                vec3 units = units_of(texel + ivec2(dx, dy));
                photons += max(units.r, max(units.g, units.b)) / units_per_photon;
            }
        if (photons >= kAdaptivePhotons) return r;
    }
    return kMaxAdaptiveRadius;
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(resolution)))) return;
    int radius = kernel_radius >= 0 ? kernel_radius : adaptive_radius(texel);
    vec3 sum = vec3(0.0f);
    float weights = 0.0f;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            ivec2 neighbour = texel + ivec2(dx, dy);
            if (!on_map(neighbour)) continue;
            // The tent (r + 1 − |dx|)(r + 1 − |dy|): the binomial kernel at r = 1.
            float weight = float((radius + 1 - abs(dx)) * (radius + 1 - abs(dy)));
            sum += weight * units_of(neighbour);
            weights += weight;
        }
    vec3 result = sum / weights * power_unit / texel_area;
    uint index = 3u * (first_texel + uint(texel.y * resolution + texel.x));
    receiver_irradiance[index + 0u] = result.r;
    receiver_irradiance[index + 1u] = result.g;
    receiver_irradiance[index + 2u] = result.b;
}
