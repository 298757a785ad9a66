// Receiver irradiance from the photon pass's fixed-point texel tallies:
// E = units · unit / texel area per channel, filtered with a 3×3 binomial
// kernel ([1 2 1]/4 along each axis; weights outside the map are left out
// and the rest renormalised) — the density estimate the view pass reads —
// or, with kernel_radius 0 (`receivers[].filter: "none"`), each texel alone.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = kReceiverTallies) readonly buffer ReceiverTallies { uint receiver_tallies[]; };
layout(std430, binding = kReceiverMaps) writeonly buffer ReceiverMaps { float receiver_irradiance[]; };

uniform uint first_texel;
uniform int resolution;
uniform float texel_area;
uniform vec3 power_unit;
uniform int kernel_radius;  // 1: the 3×3 binomial; 0: none

vec3 irradiance_of(ivec2 texel) {
    uint base = 6u * (first_texel + uint(texel.y * resolution + texel.x));
    vec3 units;
    for (int channel = 0; channel < 3; ++channel) {
        uint low = receiver_tallies[base + uint(2 * channel)];
        uint high = receiver_tallies[base + uint(2 * channel) + 1u];
        units[channel] = float(high) * 4294967296.0f + float(low);
    }
    return units * power_unit / texel_area;
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(resolution)))) return;
    vec3 sum = vec3(0.0f);
    float weights = 0.0f;
    for (int dy = -kernel_radius; dy <= kernel_radius; ++dy)
        for (int dx = -kernel_radius; dx <= kernel_radius; ++dx) {
            ivec2 neighbour = texel + ivec2(dx, dy);
            if (any(lessThan(neighbour, ivec2(0))) || any(greaterThanEqual(neighbour, ivec2(resolution)))) continue;
            float weight = float((2 - abs(dx)) * (2 - abs(dy)));
            sum += weight * irradiance_of(neighbour);
            weights += weight;
        }
    vec3 result = sum / weights;
    uint index = 3u * (first_texel + uint(texel.y * resolution + texel.x));
    receiver_irradiance[index + 0u] = result.r;
    receiver_irradiance[index + 1u] = result.g;
    receiver_irradiance[index + 2u] = result.b;
}
