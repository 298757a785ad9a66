// What a camera ray sees when it leaves the scene along d from x: a uniform
// radiance, a sky gradient over a checkerboard ground plane, or an
// equirectangular HDR image. GLSL only; needs the CameraBlock (`camera`).
//
// The checkerboard is filtered over the footprint of the ray's sample
// (texture antialiasing, Pharr, Jakob & Humphreys, Physically Based
// Rendering, 3rd ed., §10.1): a caller that knows it sets
// `footprint_width`, the width in metres across the ray of the share of the
// pixel its sample stands for, at x, and `footprint_growth`, how much it
// widens per metre travelled (a pinhole's rays spread; zero leaves the
// checkerboard point-sampled). Where the ray meets the ground the footprint
// is a rectangle, stretched by 1/|d_y| along the ray's heading; the
// checkerboard is averaged exactly over boxes that bound pieces of it, each
// the product of two square waves' box averages (each the difference of the
// waves' integral, a triangle wave, across the box).
#ifndef EIKON_ENVIRONMENT
#define EIKON_ENVIRONMENT 0  // layout::EnvironmentKind
#endif

#if EIKON_ENVIRONMENT == 2
layout(binding = kEnvironmentTexture) uniform sampler2D environment_texture;
#endif

float footprint_width = 0.0f;   // m across the ray at its origin
float footprint_growth = 0.0f;  // m of width per m travelled
const int kFootprintPieces = 16;  // most pieces a footprint is cut into

#if EIKON_ENVIRONMENT == 1
// The mean of the square wave sign(cos(π·u)) (+1 on [0, 1), −1 on [1, 2)) over [u − w/2, u + w/2].
float square_wave_mean(float u, float w) {
    if (w < 1e-4f) return (int(floor(u)) & 1) == 0 ? 1.0f : -1.0f;
    float upper = 1.0f - abs(1.0f - mod(u + 0.5f * w, 2.0f));
    float lower = 1.0f - abs(1.0f - mod(u - 0.5f * w, 2.0f));
    return (upper - lower) / w;
}
#endif

vec3 environment_radiance(vec3 x, vec3 d) {
#if EIKON_ENVIRONMENT == 1
    // A ray leaving downward meets the ground; one that left the grid at or
    // just below the ground plane (a grid floor on the ground) meets it there.
    float height = max(x.y - camera.ground.x, 0.0f);
    if (d.y < 0.0f) {
        float distance = height / -d.y;
        vec3 hit = x + distance * d;
        float width = footprint_width + footprint_growth * distance;
        vec2 heading = length(d.xz) > 0.0f ? normalize(d.xz) : vec2(1.0f, 0.0f);
        vec2 across = width * vec2(-heading.y, heading.x) / camera.ground.y;  // in squares
        vec2 along = (width / max(-d.y, 1e-4f)) * heading / camera.ground.y;
        // A long footprint is cut along its length into pieces about as long
        // as it is wide, each averaged over its own bounding box (a tilted
        // sliver's box would be much larger than it).
        int pieces = int(clamp(ceil(length(along) / max(length(across), 1e-6f)), 1.0f, float(kFootprintPieces)));
        vec2 piece = along / float(pieces);
        vec2 box = abs(across) + abs(piece);
        vec2 u = hit.xz / camera.ground.y;
        float parity = 0.0f;  // +1: ground_a
        for (int i = 0; i < pieces; ++i) {
            vec2 centre = u + (float(i) + 0.5f - 0.5f * float(pieces)) * piece;
            parity += square_wave_mean(centre.x, box.x) * square_wave_mean(centre.y, box.y);
        }
        parity /= float(pieces);
        return mix(camera.ground_b.rgb, camera.ground_a.rgb, 0.5f + 0.5f * parity);
    }
    return mix(camera.horizon.rgb, camera.zenith.rgb, sqrt(clamp(d.y, 0.0f, 1.0f)));
#elif EIKON_ENVIRONMENT == 2
    float longitude = atan(d.z, d.x) + camera.radiance.y;
    vec2 uv = vec2(longitude / (2.0f * 3.14159265358979f) + 0.5f, acos(clamp(d.y, -1.0f, 1.0f)) / 3.14159265358979f);
    return camera.radiance.x * textureLod(environment_texture, uv, 0.0f).rgb;
#else
    return camera.radiance.rgb;
#endif
}
