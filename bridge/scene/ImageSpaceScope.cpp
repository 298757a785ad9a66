#include "bridge/scene/ImageSpaceScope.h"

namespace eikon {

namespace {

bool anyPositive(const Rgb& value) { return value.r > 0.0 || value.g > 0.0 || value.b > 0.0; }

}  // namespace

std::vector<std::string> imageSpaceOmissions(const Scene& scene) {
    std::vector<std::string> dropped;
    if (scene.sim) dropped.push_back("the sim section's fluid (a graded medium)");
    if (scene.volume) dropped.push_back("the imported volume");
    if (scene.airProfile) dropped.push_back("medium.air_temperature_profile (graded air: the mirage)");
    if (anyPositive(scene.medium.extinction) || anyPositive(scene.medium.scattering))
        dropped.push_back("the medium's extinction and scattering");
    if (!scene.paint.empty()) dropped.push_back("the paint strokes");
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectDesc& object = scene.objects[i];
        const std::string name = "objects[" + std::to_string(i) + "]";
        if (!object.isSharp()) dropped.push_back(name + " (a smooth surface is a graded field)");
        else if (anyPositive(object.material.scattering)) dropped.push_back(name + "'s scattering");
    }
    if (scene.tracer.dispersive()) dropped.push_back("tracer.dispersion");
    return dropped;
}

std::string describeImageSpaceOmissions(const Scene& scene) {
    const std::vector<std::string> dropped = imageSpaceOmissions(scene);
    if (dropped.empty()) return "";
    std::string text = "render.method \"image_space\" draws the surfaces only and drops ";
    for (std::size_t i = 0; i < dropped.size(); ++i)
        text += (i == 0 ? "" : i + 1 == dropped.size() ? " and " : ", ") + dropped[i];
    return text + ": it bends no ray inside a graded medium and gathers no light from a volume";
}

}  // namespace eikon
