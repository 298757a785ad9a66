#include "verify/reference/SphereOptics.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::reference {

double sphereHit(const glm::dvec3& origin, const glm::dvec3& direction, const Sphere& sphere, double tMin) {
    const glm::dvec3 oc = origin - sphere.centre;
    const double b = glm::dot(oc, direction);
    const double c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0) return -1.0;
    const double root = std::sqrt(discriminant);
    const double near = -b - root, far = -b + root;
    if (near > tMin) return near;
    if (far > tMin) return far;
    return -1.0;
}

SurfaceCrossing crossSurface(const glm::dvec3& direction, const glm::dvec3& normal, double ni, double nt) {
    const double cosI = -glm::dot(direction, normal);
    SurfaceCrossing crossing;
    crossing.reflected = direction + 2.0 * cosI * normal;
    const double eta = ni / nt;
    const double sinT2 = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
    if (sinT2 >= 1.0) return crossing;  // total internal reflection
    const double cosT = std::sqrt(1.0 - sinT2);
    const double rs = (ni * cosI - nt * cosT) / (ni * cosI + nt * cosT);
    const double rp = (nt * cosI - ni * cosT) / (nt * cosI + ni * cosT);
    crossing.reflectance = 0.5 * (rs * rs + rp * rp);
    crossing.refracted = glm::normalize(eta * direction + (eta * cosI - cosT) * normal);
    return crossing;
}

std::optional<SphereTransit> transitSphere(const glm::dvec3& origin, const glm::dvec3& direction, const Sphere& sphere,
                                           double sphereIndex, double mediumIndex) {
    const double t = sphereHit(origin, direction, sphere, 0.0);
    if (t < 0.0) return std::nullopt;
    const glm::dvec3 entry = origin + t * direction;
    const glm::dvec3 inside =
        crossSurface(direction, (entry - sphere.centre) / sphere.radius, mediumIndex, sphereIndex).refracted;
    const glm::dvec3 exit = entry - 2.0 * glm::dot(entry - sphere.centre, inside) * inside;  // the chord's far end
    const glm::dvec3 out = crossSurface(inside, (sphere.centre - exit) / sphere.radius, sphereIndex, mediumIndex).refracted;
    return SphereTransit{exit, out, glm::length(glm::cross(origin - sphere.centre, direction))};
}

}  // namespace eikon::reference
