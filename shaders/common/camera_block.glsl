// The camera and the environment (members: layout::GpuCamera, built by
// render/stages/ViewStage's cameraBlock), and the ray through a point of the
// image or a pixel's centre (row 0 at the top): from the pinhole, or — orthographic — from the
// pixel's point on the image plane through `position`, along `forward`.
// GLSL only.
layout(std140, binding = kCameraBlock) uniform CameraBlock { EIKON_GPU_CAMERA } camera;

bool camera_is_orthographic() { return camera.image.w == uint(kOrthographicProjection); }

// The offset of a point of the image (in pixels from its top-left corner,
// x right, y down) from the image's centre along right and up, in units of
// the image plane at unit distance (perspective) or in metres.
vec3 camera_image_offset_at(vec2 point) {
    vec2 ndc = point / vec2(camera.image.xy) * 2.0f - 1.0f;
    return ndc.x * camera.position.w * camera.forward.w * camera.right.xyz - ndc.y * camera.position.w * camera.up.xyz;
}

// The ray through a point of the image (in pixels, as above).
vec3 camera_ray_origin_at(vec2 point) {
    return camera_is_orthographic() ? camera.position.xyz + camera_image_offset_at(point) : camera.position.xyz;
}

vec3 camera_ray_direction_at(vec2 point) {
    return camera_is_orthographic() ? camera.forward.xyz
                                     : normalize(camera.forward.xyz + camera_image_offset_at(point));
}

// The direction of the ray through a pixel's centre.
vec3 camera_ray_direction(uvec2 pixel) { return camera_ray_direction_at(vec2(pixel) + 0.5f); }
