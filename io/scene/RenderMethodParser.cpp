#include "io/scene/RenderMethodParser.h"

#include "bridge/scene/ImageSpaceScope.h"

namespace eikon {

void readRenderMethod(const JsonObjectReader& renderFields, RenderDesc& render) {
    if (auto method = renderFields.optional("method"))
        render.method = method->oneOf({"eikonal", "image_space"}) == "image_space" ? RenderDesc::Method::ImageSpace
                                                                                  : RenderDesc::Method::Eikonal;
    if (auto fallback = renderFields.optional("method_fallback"))
        render.methodFallback = fallback->oneOf({"none", "surfaces_only"}) == "surfaces_only"
                                    ? RenderDesc::MethodFallback::SurfacesOnly
                                    : RenderDesc::MethodFallback::None;
    if (auto texels = renderFields.optional("caustic_map_texels"))
        render.causticMapTexels = static_cast<int>(texels->integer(16, 4096));
}

void checkRenderMethod(const JsonObjectReader& sceneFields, const Scene& scene) {
    if (scene.render.method != RenderDesc::Method::ImageSpace ||
        scene.render.methodFallback == RenderDesc::MethodFallback::SurfacesOnly || imageSpaceOmissions(scene).empty())
        return;
    sceneFields.member("render").member("method").fail(
        "\"eikonal\" for this scene, or render.method_fallback \"surfaces_only\" (" +
            describeImageSpaceOmissions(scene) + ")",
        "\"image_space\"");
}

}  // namespace eikon
