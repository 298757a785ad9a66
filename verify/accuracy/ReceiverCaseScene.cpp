#include "verify/accuracy/ReceiverCaseScene.h"

#include <cmath>

namespace eikon::accuracy {

Scene receiverCaseScene(glm::dvec3 boundsMin, glm::dvec3 boundsMax, glm::ivec3 resolution, double index) {
    Scene scene;
    scene.grid.boundsMin = boundsMin;
    scene.grid.boundsMax = boundsMax;
    scene.grid.resolution = resolution;
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.medium.index = index;
    scene.render.width = 8;
    scene.render.height = 8;
    scene.render.photons = 1 << 21;
    return scene;
}

LightDesc unitBeam(glm::dvec3 direction) {
    LightDesc light;
    light.kind = LightDesc::Kind::Directional;
    light.direction = direction;
    light.irradiance = Rgb(1.0);
    return light;
}

ReceiverDesc unfilteredReceiver(glm::dvec3 point, glm::dvec3 normal, double size, int resolution) {
    ReceiverDesc receiver;
    receiver.point = point;
    receiver.normal = normal;
    receiver.size = size;
    receiver.resolution = resolution;
    receiver.filter = ReceiverDesc::Filter::None;
    return receiver;
}

ObjectDesc coverBox(const Scene& scene, double index) {
    ObjectDesc cover;
    cover.kind = ObjectDesc::Kind::Box;
    cover.box = {scene.grid.boundsMin, scene.grid.boundsMax};
    cover.material.index = index;
    cover.surface = ObjectDesc::Surface::Smooth;
    return cover;
}

ObjectDesc coverSphere(glm::dvec3 centre, double radius, double index) {
    ObjectDesc cover;
    cover.kind = ObjectDesc::Kind::Sphere;
    cover.sphere = {centre, radius};
    cover.material.index = index;
    cover.surface = ObjectDesc::Surface::Smooth;
    return cover;
}

double texelMapError(const std::vector<float>& map, const std::vector<double>& truth) {
    double difference = 0.0, total = 0.0;
    for (std::size_t t = 0; t < truth.size(); ++t) {
        difference += std::abs(map[3 * t + 1] - truth[t]);
        total += truth[t];
    }
    return difference / total;
}

double layeredRowsError(const std::vector<float>& map, const std::vector<double>& rows, double size, double depth,
                        double margin) {
    const int n = static_cast<int>(rows.size());
    double difference = 0.0, total = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double z = depth - (0.5 * depth - 0.5 * size + (i + 0.5) / n * size);
            if (z < margin || z > depth - margin) continue;
            const double measured = map[static_cast<std::size_t>(3 * (j * n + i) + 1)];
            difference += std::abs(measured - rows[static_cast<std::size_t>(j)]);
            total += rows[static_cast<std::size_t>(j)];
        }
    return difference / total;
}

}  // namespace eikon::accuracy
