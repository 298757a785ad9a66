// The sRGB transfer function (IEC 61966-2-1): linear light → encoded value,
// for 8-bit pictures. GLSL only.
vec3 srgb_encode(vec3 linear) {
    return mix(12.92f * linear, 1.055f * pow(linear, vec3(1.0f / 2.4f)) - 0.055f, greaterThan(linear, vec3(0.0031308f)));
}
