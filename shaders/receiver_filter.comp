// Receiver irradiance from the light pass's fixed-point texel tallies:
// E = units · unit / texel area per channel, then one of
// - EIKON_FILTER_RADIUS 1 (`receivers[].filter: "binomial"`): the 3×3
//   binomial kernel ([1 2 1]/4 along each axis) — the density estimate the
//   view pass reads by default for photons;
// - EIKON_FILTER_RADIUS 0 (`"none"`, the wavefront's default): each texel alone;
// - EIKON_FILTER_RADIUS −1 (`"adaptive"`): a tent kernel whose radius is the
//   smallest of 0 … kMaxAdaptiveRadius texels whose square holds about
//   kAdaptivePhotons photons (counted as units over the units of the
//   brightest photon), so that bright caustics stay sharp while faint,
//   sparsely hit texels are smoothed as far as they need.
// Weights outside the map are left out and the rest renormalised. A fixed
// radius is a constant, so its loops unroll (a CPU rasterizer keeps books
// on every turn of a loop it cannot), and the tallies are read as a buffer
// texture of (low, high) words, which it fetches for all lanes at once.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = kReceiverTallyTexture) uniform usamplerBuffer receiver_tally_texels;  // per texel and channel
layout(std430, binding = kReceiverMaps) writeonly buffer ReceiverMaps { float receiver_irradiance[]; };

uniform uint first_texel;
uniform int resolution;
uniform float texel_area;
uniform vec3 power_unit;

const int kFilterRadius = EIKON_FILTER_RADIUS;

bool on_map(ivec2 texel) { return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(resolution))); }

vec3 units_of(ivec2 texel) {
    int base = 3 * int(first_texel + uint(texel.y * resolution + texel.x));
    vec3 units;
    for (int channel = 0; channel < 3; ++channel) {
        uvec2 words = texelFetch(receiver_tally_texels, base + channel).rg;  // low, high
        units[channel] = float(words.y) * 4294967296.0f + float(words.x);
    }
    return units;
}

// The tent (r + 1 − |dx|)(r + 1 − |dy|) of radius r over the texels around
// `texel` that lie on the map, as a sum of units and of weights.
void tent_sum(ivec2 texel, int radius, inout vec3 sum, inout float weights) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            ivec2 neighbour = texel + ivec2(dx, dy);
            float weight = on_map(neighbour) ? float((radius + 1 - abs(dx)) * (radius + 1 - abs(dy))) : 0.0f;
            sum += weight * units_of(clamp(neighbour, ivec2(0), ivec2(resolution - 1)));
            weights += weight;
        }
}

#if EIKON_FILTER_RADIUS < 0
uniform float units_per_photon;  // tally units of one photon of the brightest light (per channel)

const int kMaxAdaptiveRadius = 4;
const float kAdaptivePhotons = 128.0f;

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
#endif

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(resolution)))) return;
    vec3 sum = vec3(0.0f);
    float weights = 0.0f;
#if EIKON_FILTER_RADIUS < 0
    tent_sum(texel, adaptive_radius(texel), sum, weights);
#else
    tent_sum(texel, kFilterRadius, sum, weights);  // the binomial kernel at radius 1
#endif
    vec3 result = sum / weights * power_unit / texel_area;
    uint index = 3u * (first_texel + uint(texel.y * resolution + texel.x));
    receiver_irradiance[index + 0u] = result.r;
    receiver_irradiance[index + 1u] = result.g;
    receiver_irradiance[index + 2u] = result.b;
}
