// The image-space caustics' deposits (image_space_caustics.comp,
// caustic_polygons.comp): power in W added to a receiver texel's 64-bit
// fixed-point tallies (common/wide_units.glsl, ReceiverMaps), which
// ReceiverMaps filters into W/m² as it does the eikonal photons'. GLSL only;
// needs receiver_blocks.glsl and wide_units.glsl.

layout(std430, binding = kReceiverTallies) buffer ReceiverTallies { uint receiver_tallies[]; };  // [2·(3·texel + channel) + word]

uniform vec3 power_unit;  // W per tally unit

void deposit_texel(int r, ivec2 texel, vec3 watts) {
    r = receiver_slot(r);
    int resolution = int(receivers[r].map.y);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(resolution)))) return;
    uint base = 6u * (receivers[r].map.x + uint(texel.y * resolution + texel.x));
    for (int c = 0; c < 3; ++c)
        if (watts[c] > 0.0f) ADD_WIDE_UNITS(receiver_tallies, base + uint(2 * c), wide_units(watts[c] / power_unit[c]));
}

// Power landing at map_uv on a map of `resolution` texels, shared
// bilinearly between the four texels around it: those of them on the map
// (at its edge, not all are) take their weights over the sum of theirs, so
// none is lost.
struct BilinearSplat {
    ivec2 base;    // the lowest of the four texels
    vec2 f;        // map_uv's place between their centres, in [0, 1)²
    float on_map;  // the weights of those on the map, summed (0: none is)
};

BilinearSplat bilinear_splat(vec2 map_uv, int resolution) {
    vec2 texel = map_uv * float(resolution) - 0.5f;
    ivec2 base = ivec2(floor(texel));
    return BilinearSplat(base, texel - vec2(base), bilinear_share_on_map(map_uv, resolution));
}

// The share of texel base + offset (offset ∈ {0, 1}²), if it lies on the map.
float bilinear_splat_share(BilinearSplat splat, ivec2 offset) {
    vec2 weight = mix(1.0f - splat.f, splat.f, vec2(offset));
    return splat.on_map > 0.0f ? weight.x * weight.y / splat.on_map : 0.0f;
}

// Power landing at map_uv on receiver r, splatted there. One deposit in a
// loop: a CPU rasterizer runs every call site a shader has under a mask,
// lanes that take it or not.
void splat_at(int r, vec2 map_uv, vec3 watts) {
    BilinearSplat splat = bilinear_splat(map_uv, int(receivers[receiver_slot(r)].map.y));
    for (int k = 0; k < 4 && splat.on_map > 0.0f; ++k) {
        ivec2 offset = ivec2(k & 1, k >> 1);
        deposit_texel(r, splat.base + offset, bilinear_splat_share(splat, offset) * watts);
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
