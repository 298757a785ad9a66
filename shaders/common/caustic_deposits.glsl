// The image-space caustics' deposits (image_space_caustics.comp,
// caustic_polygons.comp): power in W added to a receiver texel's 64-bit
// fixed-point tallies (common/wide_units.glsl, ReceiverMaps), which
// ReceiverMaps filters into W/m² as it does the eikonal photons'. GLSL only;
// needs receiver_blocks.glsl and wide_units.glsl.

layout(std430, binding = kReceiverTallies) buffer ReceiverTallies { uint receiver_tallies[]; };  // [2·(3·texel + channel) + word]

uniform vec3 power_unit;  // W per tally unit

void deposit_texel(int r, ivec2 texel, vec3 watts) {
    int resolution = int(receivers[r].map.y);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(resolution)))) return;
    uint base = 6u * (receivers[r].map.x + uint(texel.y * resolution + texel.x));
    for (int c = 0; c < 3; ++c)
        if (watts[c] > 0.0f) ADD_WIDE_UNITS(receiver_tallies, base + uint(2 * c), wide_units(watts[c] / power_unit[c]));
}

// Power landing at map_uv on receiver r, shared bilinearly between the four
// texels around it (those of them on the receiver, at its edge: none is
// lost). One deposit in a loop: a CPU rasterizer runs every call site a
// shader has under a mask, lanes that take it or not.
void splat_at(int r, vec2 map_uv, vec3 watts) {
    int resolution = int(receivers[r].map.y);
    vec2 texel = map_uv * float(resolution) - 0.5f;
    ivec2 base = ivec2(floor(texel));
    vec2 f = texel - vec2(base);
    float on_receiver = bilinear_share_on_map(map_uv, resolution);
    for (int k = 0; k < 4 && on_receiver > 0.0f; ++k) {
        ivec2 offset = ivec2(k & 1, k >> 1);
        vec2 weight = mix(1.0f - f, f, vec2(offset));
        deposit_texel(r, base + offset, weight.x * weight.y / on_receiver * watts);
    }
}

// This invocation's receiver and texel, one invocation per texel of all
// receivers' maps in the rows ReceiverMaps::dispatchOverTexels dispatches
// (false: past the last of texel_count). Compute shaders only.
bool receiver_texel_of_invocation(uint texel_count, out int r, out ivec2 texel) {
    uint index = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x + gl_GlobalInvocationID.x;
    r = 0;
    texel = ivec2(0);
    if (index >= texel_count) return false;
    for (int q = 1; q < int(receiver_count); ++q) r = index >= receivers[q].map.x ? q : r;  // maps in order
    uint resolution = receivers[r].map.y;
    uint local = index - receivers[r].map.x;
    texel = ivec2(local % resolution, local / resolution);
    return true;
}
