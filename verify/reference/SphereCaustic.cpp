#include "verify/reference/SphereCaustic.h"

#include "verify/reference/CircleDeposit.h"
#include "verify/reference/SphereOptics.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <thread>

namespace eikon::reference {

namespace {

struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction;  // unit
    double weight;         // W
    bool insideSphere;
};

// Where a ray meets the receiver's plane, and the power it brings there (W).
using Landing = std::function<void(const glm::dvec3& point, double weight)>;

class Tracer {
public:
    Tracer(const SphereCausticSetup& setup, Landing landing) : s_(setup), landing_(std::move(landing)) {}

    // Follows a ray and the branches Fresnel splits off it (depth-first).
    void trace(Ray ray, int crossings) {
        for (;;) {
            const double t = sphereHit(ray.origin, ray.direction, {s_.centre, s_.radius}, 1e-9);
            if (t < 0.0) {
                if (!ray.insideSphere) land(ray);
                return;
            }
            if (crossings >= s_.maxCrossings) return;
            ++crossings;
            const glm::dvec3 hit = ray.origin + t * ray.direction;
            glm::dvec3 normal = (hit - s_.centre) / s_.radius;  // outward
            if (ray.insideSphere) normal = -normal;              // facing the incoming ray
            const double ni = ray.insideSphere ? s_.sphereIndex : s_.mediumIndex;
            const double nt = ray.insideSphere ? s_.mediumIndex : s_.sphereIndex;
            const SurfaceCrossing crossing = crossSurface(ray.direction, normal, ni, nt);
            if (crossing.reflectance >= 1.0) {  // total internal reflection
                ray = {hit, crossing.reflected, ray.weight, ray.insideSphere};
                continue;
            }
            if (s_.fresnel && s_.followReflections)
                trace({hit, crossing.reflected, ray.weight * crossing.reflectance, ray.insideSphere}, crossings);
            const double kept = s_.fresnel ? 1.0 - crossing.reflectance : 1.0;
            ray = {hit, crossing.refracted, ray.weight * kept, !ray.insideSphere};
        }
    }

private:
    void land(const Ray& ray) {
        if (ray.direction.y >= 0.0) return;
        const double t = (s_.receiverCentre.y - ray.origin.y) / ray.direction.y;
        if (t <= 0.0) return;
        landing_(ray.origin + t * ray.direction, ray.weight);
    }

    const SphereCausticSetup& s_;
    Landing landing_;
};

// The cosine of the half-angle of the cone from the light that holds the
// whole receiver square.
double receiverConeCosine(const SphereCausticSetup& setup) {
    const double halfSize = 0.5 * setup.size;
    double cosCone = 1.0;
    for (double sx : {-1.0, 1.0})
        for (double sz : {-1.0, 1.0}) {
            const glm::dvec3 corner = setup.receiverCentre + glm::dvec3(sx * halfSize, 0.0, sz * halfSize);
            cosCone = std::min(cosCone, glm::dot(glm::normalize(corner - setup.light), glm::dvec3(0.0, -1.0, 0.0)));
        }
    return cosCone;
}

IrradianceMap toIrradiance(const SphereCausticSetup& setup, const std::vector<std::vector<double>>& partial) {
    const std::size_t texels = static_cast<std::size_t>(setup.resolution) * setup.resolution;
    IrradianceMap map{setup.resolution, setup.size, std::vector<double>(texels, 0.0)};
    const double texelArea = (setup.size / setup.resolution) * (setup.size / setup.resolution);
    for (const auto& part : partial)
        for (std::size_t t = 0; t < texels; ++t) map.irradiance[t] += part[t] / texelArea;
    return map;
}

template <typename Work>
std::vector<std::vector<double>> inParallel(const SphereCausticSetup& setup, Work work) {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t texels = static_cast<std::size_t>(setup.resolution) * setup.resolution;
    std::vector<std::vector<double>> partial(threads, std::vector<double>(texels, 0.0));
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < threads; ++w) workers.emplace_back([&, w] { work(w, threads, partial[w]); });
    for (auto& worker : workers) worker.join();
    return partial;
}

// Traces rings(k) for k < count, split among threads, each landing
// deposited as a circle about the sphere's axis (CircleDeposit.h).
template <typename RingRay>
IrradianceMap depositRings(const SphereCausticSetup& setup, long long count, RingRay ringRay) {
    const auto partial = inParallel(setup, [&](unsigned w, unsigned threads, std::vector<double>& power) {
        CircleDeposit circles(setup.resolution, setup.size, power);
        Tracer tracer(setup, [&](const glm::dvec3& p, double rayWeight) {
            circles.add(std::hypot(p.x - setup.centre.x, p.z - setup.centre.z), rayWeight);
        });
        const long long begin = count * w / threads, end = count * (w + 1) / threads;
        for (long long k = begin; k < end; ++k) tracer.trace(ringRay(k), 0);
    });
    return toIrradiance(setup, partial);
}

}  // namespace

IrradianceMap traceSphereCaustic(const SphereCausticSetup& setup) {
    const double cosCone = receiverConeCosine(setup);
    const double solidAngle = 2.0 * std::numbers::pi * (1.0 - cosCone);
    const double weight = setup.power / (4.0 * std::numbers::pi) * solidAngle / static_cast<double>(setup.rays);
    const auto partial = inParallel(setup, [&](unsigned w, unsigned threads, std::vector<double>& power) {
        std::mt19937_64 random(setup.seed * 0x9E3779B97F4A7C15ull + w);
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        Tracer tracer(setup, [&](const glm::dvec3& p, double rayWeight) {
            const double u = (p.x - setup.receiverCentre.x) / setup.size + 0.5;
            const double v = (p.z - setup.receiverCentre.z) / setup.size + 0.5;
            if (u < 0.0 || u >= 1.0 || v < 0.0 || v >= 1.0) return;
            const int i = std::min(static_cast<int>(u * setup.resolution), setup.resolution - 1);
            const int j = std::min(static_cast<int>(v * setup.resolution), setup.resolution - 1);
            power[static_cast<std::size_t>(j) * setup.resolution + i] += rayWeight;
        });
        const long long begin = setup.rays * w / threads, end = setup.rays * (w + 1) / threads;
        for (long long k = begin; k < end; ++k) {
            // Uniform in the cone about −y: cos θ uniform in [cosCone, 1].
            const double cosTheta = 1.0 - uniform(random) * (1.0 - cosCone);
            const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
            const double phi = 2.0 * std::numbers::pi * uniform(random);
            const glm::dvec3 direction(sinTheta * std::cos(phi), -cosTheta, sinTheta * std::sin(phi));
            tracer.trace({setup.light, direction, weight, false}, 0);
        }
    });
    return toIrradiance(setup, partial);
}

IrradianceMap integrateSphereCaustic(const SphereCausticSetup& setup, long long angles) {
    if (setup.resolution % 2 != 0 || setup.light.x != setup.centre.x || setup.light.z != setup.centre.z ||
        setup.receiverCentre.x != setup.centre.x || setup.receiverCentre.z != setup.centre.z)
        throw std::invalid_argument("integrateSphereCaustic: the light, sphere and receiver must share one axis, "
                                    "and the resolution must be even");
    const double thetaMax = std::acos(receiverConeCosine(setup));
    const double step = thetaMax / static_cast<double>(angles);
    const double intensity = setup.power / (4.0 * std::numbers::pi);  // W/sr
    return depositRings(setup, angles, [&](long long k) {
        // The ring of directions θ ± step/2 about −y: solid angle 2π sin θ dθ (midpoint rule).
        const double theta = (static_cast<double>(k) + 0.5) * step;
        const double ring = intensity * 2.0 * std::numbers::pi * std::sin(theta) * step;
        return Ray{setup.light, glm::dvec3(std::sin(theta), -std::cos(theta), 0.0), ring, false};
    });
}

IrradianceMap integrateSphereCausticUnderBeam(const SphereCausticSetup& setup, double irradiance, long long rings) {
    if (setup.resolution % 2 != 0 || setup.receiverCentre.x != setup.centre.x || setup.receiverCentre.z != setup.centre.z)
        throw std::invalid_argument("integrateSphereCausticUnderBeam: the sphere and receiver must share one vertical "
                                    "axis, and the resolution must be even");
    // Rays past both the sphere and the receiver's corners land off the receiver.
    const double outermost = std::max(setup.radius, std::sqrt(0.5) * setup.size);
    const double step = outermost / static_cast<double>(rings);
    const double above = std::max(setup.centre.y + setup.radius, setup.receiverCentre.y) + 1.0;
    return depositRings(setup, rings, [&](long long k) {
        // The ring of impact parameters b ± step/2 about the axis: area 2π b db (midpoint rule).
        const double b = (static_cast<double>(k) + 0.5) * step;
        const double ring = irradiance * 2.0 * std::numbers::pi * b * step;
        return Ray{setup.centre + glm::dvec3(b, above - setup.centre.y, 0.0), glm::dvec3(0.0, -1.0, 0.0), ring, false};
    });
}

double shadowRadius(const SphereCausticSetup& setup) {
    const double h = setup.light.y - setup.receiverCentre.y;
    const double d = glm::length(setup.centre - setup.light);
    return h * std::tan(std::asin(setup.radius / d));
}

}  // namespace eikon::reference
