// The pinhole camera and the environment (C++ mirror: layout::GpuCamera,
// built by render/stages/ViewStage's cameraBlock), and the direction of a
// pixel's ray through its centre (row 0 at the top). GLSL only.
layout(std140, binding = kCameraBlock) uniform CameraBlock {
    vec4 position;    // w: tan(fov / 2)
    vec4 forward;     // w: aspect
    vec4 right;
    vec4 up;
    uvec4 image;      // width, height, environment kind
    vec4 radiance;    // uniform: rgb; hdr: intensity, rotation
    vec4 zenith;
    vec4 horizon;
    vec4 ground_a;
    vec4 ground_b;
    vec4 ground;      // height, checker size
} camera;

vec3 camera_ray_direction(uvec2 pixel) {
    vec2 ndc = (vec2(pixel) + 0.5f) / vec2(camera.image.xy) * 2.0f - 1.0f;
    return normalize(camera.forward.xyz + ndc.x * camera.position.w * camera.forward.w * camera.right.xyz -
                     ndc.y * camera.position.w * camera.up.xyz);
}
