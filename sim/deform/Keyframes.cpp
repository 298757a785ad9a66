#include "sim/deform/Keyframes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace eikon::sim {

namespace {

// Index of the last key at or before `time` and the fraction toward the next.
template <class Key>
std::pair<std::size_t, double> bracket(const std::vector<Key>& keys, double time) {
    if (time <= keys.front().time) return {0, 0.0};
    if (time >= keys.back().time) return {keys.size() - 1, 0.0};
    const auto after = std::upper_bound(keys.begin(), keys.end(), time,
                                        [](double t, const Key& key) { return t < key.time; });
    const std::size_t next = static_cast<std::size_t>(after - keys.begin());
    const Key& a = keys[next - 1];
    const Key& b = keys[next];
    return {next - 1, (time - a.time) / (b.time - a.time)};
}

}  // namespace

Placement poseAt(const std::vector<PoseKey>& keys, double time) {
    if (keys.empty()) return {};
    const auto [at, f] = bracket(keys, time);
    if (f == 0.0) return keys[at].pose;
    const Placement& a = keys[at].pose;
    const Placement& b = keys[at + 1].pose;
    return {a.translate + f * (b.translate - a.translate), a.rotateDeg + f * (b.rotateDeg - a.rotateDeg),
            a.scale + f * (b.scale - a.scale)};
}

double amountAt(const std::vector<AmountKey>& keys, double time) {
    if (keys.empty()) return 0.0;
    const auto [at, f] = bracket(keys, time);
    if (f == 0.0) return keys[at].value;
    return keys[at].value + f * (keys[at + 1].value - keys[at].value);
}

glm::dmat4 placementMatrix(const Placement& placement) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), placement.translate);
    m = glm::rotate(m, glm::radians(placement.rotateDeg.z), glm::dvec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(placement.rotateDeg.y), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(placement.rotateDeg.x), glm::dvec3(1, 0, 0));
    return glm::scale(m, glm::dvec3(placement.scale));
}

}  // namespace eikon::sim
