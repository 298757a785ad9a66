// What a camera ray sees when it leaves the scene along d from x: a uniform
// radiance, a sky gradient over a checkerboard ground plane, or an
// equirectangular HDR image. GLSL only; needs the CameraBlock (`camera`).
#ifndef EIKON_ENVIRONMENT
#define EIKON_ENVIRONMENT 0  // layout::EnvironmentKind
#endif

#if EIKON_ENVIRONMENT == 2
layout(binding = kEnvironmentTexture) uniform sampler2D environment_texture;
#endif

vec3 environment_radiance(vec3 x, vec3 d) {
#if EIKON_ENVIRONMENT == 1
    // A ray leaving downward meets the ground; one that left the grid at or
    // just below the ground plane (a grid floor on the ground) meets it there.
    float height = max(x.y - camera.ground.x, 0.0f);
    if (d.y < 0.0f) {
        vec3 hit = x + (height / -d.y) * d;
        ivec2 square = ivec2(floor(hit.xz / camera.ground.y));
        return ((square.x + square.y) & 1) == 0 ? camera.ground_a.rgb : camera.ground_b.rgb;
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
