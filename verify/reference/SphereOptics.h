// Exact ray optics of a sharp sphere in double precision, sharing no code
// with the renderer: where a ray meets the sphere, Snell's law in vector
// form with the unpolarised Fresnel reflectance at its surface, and the
// two-interface path straight through it. The exact-sphere references
// (SphereCaustic) and the image-space checks (the tests, `eikon accuracy`)
// build on it. For tests only.
#pragma once

#include <glm/vec3.hpp>

#include <optional>

namespace eikon::reference {

struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

// Nearest t > tMin where origin + t·direction (unit) meets the sphere, or −1.
double sphereHit(const glm::dvec3& origin, const glm::dvec3& direction, const Sphere& sphere, double tMin);

// Unit `direction` meeting a surface from index ni into nt, `normal` the
// unit normal facing it: the refracted direction (unit; zero when totally
// reflected), the mirrored one and the unpolarised Fresnel reflectance
// ([Born99] §1.5.2; 1 beyond the critical angle).
struct SurfaceCrossing {
    glm::dvec3 refracted{0.0};
    glm::dvec3 reflected{0.0};
    double reflectance = 1.0;
};
SurfaceCrossing crossSurface(const glm::dvec3& direction, const glm::dvec3& normal, double ni, double nt);

// The path of the ray from `origin` along unit `direction` that refracts
// into the sphere, crosses it along a chord and refracts out (its angle
// inside is the same at both ends, so it always leaves): where it leaves and
// in which direction, and the distance of the incoming line from the centre
// (m). None when the ray misses the sphere.
struct SphereTransit {
    glm::dvec3 exitPoint{0.0};
    glm::dvec3 exitDirection{0.0};
    double impact = 0.0;
};
std::optional<SphereTransit> transitSphere(const glm::dvec3& origin, const glm::dvec3& direction, const Sphere& sphere,
                                           double sphereIndex, double mediumIndex = 1.0);

}  // namespace eikon::reference
