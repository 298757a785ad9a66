#include "verify/accuracy/LuneburgMap.h"

#include <cmath>

namespace eikon::accuracy {

namespace {

constexpr double kRadius = 0.4;     // m: the lens
constexpr double kDistance = 0.2;   // m: the receiver's plane past the focus
constexpr double kSize = 0.5;       // m: the receiver's side
constexpr int kTexels = 32;

double closedForm(double rho) {
    const double d2 = kDistance * kDistance;
    return kRadius * kRadius * d2 / ((rho * rho + d2) * (rho * rho + d2));
}

}  // namespace

const reference::LuneburgField& luneburgMapField() {
    static const reference::LuneburgField field(glm::dvec3(0.0), kRadius);
    return field;
}

Scene luneburgMapScene() {
    Scene scene;
    scene.grid.boundsMin = glm::dvec3(-0.5);
    scene.grid.boundsMax = glm::dvec3(0.5);
    scene.grid.resolution = glm::ivec3(64);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.medium.index = 1.0;
    scene.render.width = 8;
    scene.render.height = 8;
    scene.render.photons = 1 << 21;
    LightDesc light;
    light.kind = LightDesc::Kind::Directional;
    light.direction = glm::dvec3(0.0, 0.0, 1.0);
    light.irradiance = Rgb(1.0);
    scene.lights.push_back(light);
    ReceiverDesc receiver;
    receiver.point = glm::dvec3(0.0, 0.0, kRadius + kDistance);
    receiver.normal = glm::dvec3(0.0, 0.0, -1.0);
    receiver.size = kSize;
    receiver.resolution = kTexels;
    receiver.filter = ReceiverDesc::Filter::None;
    scene.receivers.push_back(receiver);
    ObjectDesc cover;
    cover.kind = ObjectDesc::Kind::Sphere;
    cover.sphere = {glm::dvec3(0.0), kRadius};
    cover.material.index = 1.0;
    cover.surface = ObjectDesc::Surface::Smooth;
    scene.objects.push_back(cover);
    return scene;
}

std::vector<double> luneburgMapTexelMeans() {
    // The map is symmetric under the receiver's axes' signs, so its texel
    // order does not matter: texel (i, j) spans u, v ∈ side·[i, i + 1)/n − side/2.
    std::vector<double> means(3 * kTexels * kTexels);
    const double texel = kSize / kTexels;
    for (int j = 0; j < kTexels; ++j)
        for (int i = 0; i < kTexels; ++i) {
            double sum = 0.0;
            for (int b = 0; b < 8; ++b)
                for (int a = 0; a < 8; ++a) {
                    const double u = (i + (a + 0.5) / 8.0) * texel - 0.5 * kSize;
                    const double v = (j + (b + 0.5) / 8.0) * texel - 0.5 * kSize;
                    sum += closedForm(std::hypot(u, v));
                }
            for (int c = 0; c < 3; ++c) means[static_cast<std::size_t>(3 * (j * kTexels + i) + c)] = sum / 64.0;
        }
    return means;
}

double luneburgMapError(const std::vector<float>& map, const std::vector<double>& means) {
    double difference = 0.0, total = 0.0;
    for (std::size_t t = 1; t < means.size(); t += 3) {
        difference += std::abs(map[t] - means[t]);
        total += means[t];
    }
    return difference / total;
}

}  // namespace eikon::accuracy
