#include "verify/reference/SphereReflection.h"

#include "verify/reference/SphereOptics.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace eikon::reference {
namespace {

// The share of a circle of radius rho about the square's centre that lies
// inside the square of half-width h: beyond h each of its four sides cuts
// off an arc of 2·acos(h/rho); beyond h·√2 none of it is inside.
double circleShareInSquare(double rho, double h) {
    if (rho <= h) return 1.0;
    if (rho >= h * std::sqrt(2.0)) return 0.0;
    return 1.0 - 4.0 * std::acos(h / rho) / M_PI;
}

}  // namespace

SphereReflection integrateFirstSurfaceReflection(const SphereCausticSetup& setup, long long rings) {
    const glm::dvec3 axis = setup.light - setup.centre;
    if (axis.x != 0.0 || axis.z != 0.0 || setup.receiverCentre.x != setup.centre.x ||
        setup.receiverCentre.z != setup.centre.z || axis.y <= setup.radius)
        throw std::invalid_argument("integrateFirstSurfaceReflection: light, sphere and receiver must share a vertical axis");
    const double distance = axis.y;
    const double k = setup.radius / distance;  // sin of the sphere's angular radius from the light
    const Sphere sphere{setup.centre, setup.radius};
    const double intensity = setup.power / (4.0 * M_PI);
    const double dTheta = 0.5 * M_PI / static_cast<double>(rings);
    SphereReflection result;
    for (long long ring = 0; ring < rings; ++ring) {
        // Angle of incidence θi; the ray's angle α from the axis has
        // sin α = k·sin θi, so dα = k·cos θi / cos α · dθi.
        const double incidence = (static_cast<double>(ring) + 0.5) * dTheta;
        const double sinAlpha = k * std::sin(incidence);
        const double cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
        const double ringPower = intensity * 2.0 * M_PI * sinAlpha * k * std::cos(incidence) / cosAlpha * dTheta;
        const glm::dvec3 direction{sinAlpha, -cosAlpha, 0.0};
        const double t = sphereHit(setup.light, direction, sphere, 0.0);
        if (t < 0.0) continue;
        const glm::dvec3 hit = setup.light + t * direction;
        const SurfaceCrossing crossing =
            crossSurface(direction, glm::normalize(hit - setup.centre), setup.mediumIndex, setup.sphereIndex);
        const double reflected = ringPower * crossing.reflectance;
        result.reflected += reflected;
        if (crossing.reflected.y >= 0.0) continue;  // away from the receiver's plane
        const double s = (setup.receiverCentre.y - hit.y) / crossing.reflected.y;
        const double rho = std::abs(hit.x + s * crossing.reflected.x - setup.centre.x);
        result.onReceiver += reflected * circleShareInSquare(rho, 0.5 * setup.size);
    }
    return result;
}

}  // namespace eikon::reference
