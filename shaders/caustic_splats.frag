// A splat's bilinear share of its power for one of the four atlas texels
// around it (caustic_splats.vert), added by blending; a texel off the
// splat's receiver takes none.
flat in vec2 splat_pixel;
flat in ivec3 splat_map;
flat in vec3 splat_watts;

layout(location = 0) out vec4 deposit;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy) - ivec2(0, splat_map.x);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(splat_map.y)))) discard;
    vec2 weight = max(1.0f - abs(gl_FragCoord.xy - splat_pixel), 0.0f);
    deposit = vec4(weight.x * weight.y * splat_watts, 0.0f);
}
