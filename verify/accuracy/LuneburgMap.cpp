#include "verify/accuracy/LuneburgMap.h"

#include "verify/accuracy/ReceiverCaseScene.h"

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
    Scene scene = receiverCaseScene(glm::dvec3(-0.5), glm::dvec3(0.5), glm::ivec3(64), 1.0);
    scene.lights.push_back(unitBeam(glm::dvec3(0.0, 0.0, 1.0)));
    scene.receivers.push_back(
        unfilteredReceiver(glm::dvec3(0.0, 0.0, kRadius + kDistance), glm::dvec3(0.0, 0.0, -1.0), kSize, kTexels));
    scene.objects.push_back(coverSphere(glm::dvec3(0.0), kRadius, 1.0));
    return scene;
}

std::vector<double> luneburgMapTexelMeans() {
    // The map is symmetric under the receiver's axes' signs, so its texel
    // order does not matter: texel (i, j) spans u, v ∈ side·[i, i + 1)/n − side/2.
    std::vector<double> means(kTexels * kTexels);
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
            means[static_cast<std::size_t>(j * kTexels + i)] = sum / 64.0;
        }
    return means;
}

}  // namespace eikon::accuracy
