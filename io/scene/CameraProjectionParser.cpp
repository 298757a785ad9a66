#include "io/scene/CameraProjectionParser.h"

namespace eikon {

void readCameraProjection(const JsonObjectReader& cameraFields, CameraDesc& camera) {
    if (auto projection = cameraFields.optional("projection"))
        camera.projection = projection->oneOf({"perspective", "orthographic"}) == "orthographic"
                                ? CameraDesc::Projection::Orthographic
                                : CameraDesc::Projection::Perspective;
    const auto width = cameraFields.optional("width_m");
    if (!camera.orthographic()) {
        if (width) width->fail("no width_m beside a perspective projection (fov_deg sets its view)", "a width");
        return;
    }
    camera.widthM = cameraFields.member("width_m").number(kLengthRange);
}

void checkCameraProjection(const JsonObjectReader& sceneFields, const Scene& scene) {
    if (!scene.camera.orthographic() || scene.render.method != RenderDesc::Method::ImageSpace) return;
    sceneFields.member("camera").member("projection").fail(
        "\"perspective\" with render.method \"image_space\" (its surface layers are drawn from a viewpoint)",
        "\"orthographic\"");
}

}  // namespace eikon
