#include "render/stages/PhotonEmission.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eikon::render {

namespace {

void include(Box& box, const glm::dvec3& point) {
    box.min = glm::min(box.min, point);
    box.max = glm::max(box.max, point);
}

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

double channelSum(const Rgb& rgb) { return rgb.r + rgb.g + rgb.b; }

// Any unit vector perpendicular to `axis`, and a third completing the basis.
void orthonormalBasis(const glm::dvec3& axis, glm::dvec3& tangent, glm::dvec3& bitangent) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    tangent = glm::normalize(glm::cross(axis, helper));
    bitangent = glm::cross(axis, tangent);
}

struct EmitterGeometry {
    glm::dvec3 origin{0.0};
    glm::dvec3 axis{0, 0, 1};
    double shape = 0.0;  // versine 1 − cos of the cone's half-angle, or disk radius
    // What all photons together carry where a spot's profile is 1: the power
    // into the sampled cone or disk (exactly the power into it for point and
    // directional lights).
    Rgb powerIntoRegion{0.0};
    float kind = 0.0f;
    glm::dvec3 spotAxis{0.0};
    double spotVersineOuter = -1.0;  // no spot profile
    double spotVersineInner = 0.0;
};

// The versine 1 − cos θ of the angle between unit vectors a and b: |a − b|²/2,
// which keeps its digits for small angles where 1 − a·b cancels.
double versineBetween(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 apart = a - b;
    return 0.5 * glm::dot(apart, apart);
}

// The narrowest cone around the direction to the region's centre that holds
// all eight corners; a convex cone of half-angle < 90° holding the corners
// holds the box. Otherwise (light inside or beside a large box) the full sphere.
EmitterGeometry pointEmitter(const LightDesc& light, const Box& region) {
    EmitterGeometry geometry;
    geometry.origin = light.position;
    const glm::dvec3 toCentre = 0.5 * (region.min + region.max) - light.position;
    double versineMax = 2.0;
    if (glm::length(toCentre) > 0.0) {
        geometry.axis = glm::normalize(toCentre);
        versineMax = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 point((corner & 1) ? region.max.x : region.min.x, (corner & 2) ? region.max.y : region.min.y,
                                   (corner & 4) ? region.max.z : region.min.z);
            const glm::dvec3 toCorner = point - light.position;
            const double length = glm::length(toCorner);
            if (length > 0.0) versineMax = std::max(versineMax, versineBetween(toCorner / length, geometry.axis));
            else versineMax = 2.0;
        }
        if (versineMax >= 1.0 - 1e-6) versineMax = 2.0;
    }
    geometry.shape = versineMax;
    // Isotropic: intensity Φ/4π over the cap's solid angle 2π(1 − cos α).
    geometry.powerIntoRegion = light.power * (0.5 * versineMax);
    return geometry;
}

}  // namespace

glm::dvec2 spotVersines(const LightDesc& light) {
    auto versine = [](double degrees) { return 2.0 * std::pow(std::sin(0.5 * glm::radians(degrees)), 2); };
    return {versine(light.coneAngleDeg), versine(light.coneAngleDeg - light.falloffDeg)};
}

Rgb spotPeakIntensity(const LightDesc& light) {
    const glm::dvec2 versines = spotVersines(light);
    return light.power / (std::numbers::pi * (versines.x + versines.y));
}

namespace {

// A spot (spotPeakIntensity):
// Photons are sampled in the narrower of the spot's cone and the cone
// toward the region.
EmitterGeometry spotEmitter(const LightDesc& light, const Box& region) {
    EmitterGeometry geometry = pointEmitter(light, region);
    const glm::dvec2 versines = spotVersines(light);
    const Rgb peakIntensity = spotPeakIntensity(light);
    if (versines.x < geometry.shape) {
        geometry.axis = glm::normalize(light.direction);
        geometry.shape = versines.x;
    }
    geometry.powerIntoRegion = peakIntensity * (2.0 * std::numbers::pi * geometry.shape);
    geometry.spotAxis = glm::normalize(light.direction);
    geometry.spotVersineOuter = versines.x;
    geometry.spotVersineInner = versines.y;
    return geometry;
}

// A disk ⟂ the light's direction, upstream of the region, covering the
// region's bounding sphere.
EmitterGeometry directionalEmitter(const LightDesc& light, const Box& region) {
    EmitterGeometry geometry;
    geometry.kind = 1.0f;
    geometry.axis = glm::normalize(light.direction);
    const glm::dvec3 centre = 0.5 * (region.min + region.max);
    const double radius = 0.5 * glm::length(region.max - region.min) * 1.001 + 1e-9;
    geometry.origin = centre - geometry.axis * radius * 1.01;
    geometry.shape = radius;
    geometry.powerIntoRegion = light.irradiance * (std::numbers::pi * radius * radius);
    return geometry;
}

}  // namespace

namespace {

EmitterGeometry emitterGeometry(const LightDesc& light, const Box& region) {
    return light.kind == LightDesc::Kind::Point  ? pointEmitter(light, region)
           : light.kind == LightDesc::Kind::Spot ? spotEmitter(light, region)
                                                 : directionalEmitter(light, region);
}

// The spot's profile (spotPeakIntensity) at versine h from its axis.
double spotProfile(double h, double versineOuter, double versineInner) {
    if (versineInner >= versineOuter) return h <= versineOuter ? 1.0 : 0.0;
    const double t = std::clamp((versineOuter - h) / (versineOuter - versineInner), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// ∫ profile dΩ of a spot over an emitter's domain that cuts its cone, by a
// midpoint rule of kCuts² cells in the domain's own coordinates: the cap in
// (1 − cos θ, φ), where dΩ = dh·dφ; the gnomonic square in (x, y), where
// dΩ = dx·dy/(1 + x² + y²)^{3/2}.
constexpr int kCuts = 1000;

double spotSolidAngleIn(const EmitterGeometry& geometry, bool square) {
    glm::dvec3 tangent, bitangent;
    orthonormalBasis(geometry.axis, tangent, bitangent);
    const double v = geometry.shape;
    const double spread = std::sqrt(v * (2.0 - v)) / (1.0 - v);  // tan α, the square's half-side
    double sum = 0.0;
    for (int j = 0; j < kCuts; ++j)
        for (int i = 0; i < kCuts; ++i) {
            const double a = (i + 0.5) / kCuts, b = (j + 0.5) / kCuts;
            glm::dvec3 direction;
            double weight;
            if (square) {
                const double x = spread * (2.0 * a - 1.0), y = spread * (2.0 * b - 1.0);
                direction = glm::normalize(geometry.axis + x * tangent + y * bitangent);
                weight = 4.0 * spread * spread / std::pow(1.0 + x * x + y * y, 1.5);
            } else {
                const double h = a * v, phi = 2.0 * std::numbers::pi * b;
                direction = (1.0 - h) * geometry.axis +
                            std::sqrt(h * (2.0 - h)) * (std::cos(phi) * tangent + std::sin(phi) * bitangent);
                weight = 2.0 * std::numbers::pi * v;
            }
            sum += weight * spotProfile(versineBetween(direction, geometry.spotAxis), geometry.spotVersineOuter,
                                        geometry.spotVersineInner);
        }
    return sum / (static_cast<double>(kCuts) * kCuts);
}

// The power a light states it sends into the domain its emitter samples.
Rgb statedPower(const LightDesc& light, const Box& region, bool wavefront) {
    const EmitterGeometry geometry = emitterGeometry(light, region);
    if (light.kind == LightDesc::Kind::Directional) {
        const double r = geometry.shape;
        return light.irradiance * ((wavefront ? 4.0 : std::numbers::pi) * r * r);
    }
    const double v = geometry.shape;
    const bool sphere = v >= 2.0 || (wavefront && v > 0.5);  // six faces about the light (WavefrontStage::emissionFaces)
    // The gnomonic square of half-angle α to its sides: Ω = 4 asin(sin²α).
    const double domain = sphere ? 4.0 * std::numbers::pi
                          : wavefront ? 4.0 * std::asin(v * (2.0 - v))
                                      : 2.0 * std::numbers::pi * v;
    if (light.kind == LightDesc::Kind::Point) return light.power * (domain / (4.0 * std::numbers::pi));
    // A spot: all of its power where the domain holds its whole cone.
    if (sphere || geometry.axis == geometry.spotAxis) return light.power;
    return spotPeakIntensity(light) * spotSolidAngleIn(geometry, wavefront);
}

}  // namespace

Rgb statedEmission(const std::vector<LightDesc>& lights, const Box& region, bool wavefront, const Rgb& glowPower) {
    Rgb total = glowPower;
    for (const LightDesc& light : lights) total += statedPower(light, region, wavefront);
    return total;
}

Box emissionRegion(const Scene& scene) {
    const Box gridBox{scene.grid.boundsMin, scene.grid.boundsMax};
    // Media that only the field grids know — an attenuating background, a
    // fluid, an imported volume — and objects whose extent the scene does not
    // state (meshes, water) may fill the whole grid.
    const bool extentUnknown = std::any_of(scene.objects.begin(), scene.objects.end(), [](const ObjectDesc& object) {
        return object.kind != ObjectDesc::Kind::Sphere && object.kind != ObjectDesc::Kind::Box;
    });
    if (positive(scene.medium.extinction) || positive(scene.medium.scattering) || scene.sim || scene.volume ||
        extentUnknown)
        return gridBox;
    Box region{glm::dvec3(INFINITY), glm::dvec3(-INFINITY)};
    auto includeClipped = [&](Box bounds) {
        bounds.min = glm::max(bounds.min, gridBox.min);
        bounds.max = glm::min(bounds.max, gridBox.max);
        if (glm::all(glm::lessThan(bounds.min, bounds.max))) {
            include(region, bounds.min);
            include(region, bounds.max);
        }
    };
    for (const auto& object : scene.objects)
        includeClipped(object.kind == ObjectDesc::Kind::Sphere
                           ? Box{object.sphere.center - object.sphere.radius, object.sphere.center + object.sphere.radius}
                           : Box{object.box.min, object.box.max});
    for (const auto& stroke : scene.paint)  // a stroke reaches 4σ = 2 radii from its path (VolumePainter.h)
        for (const glm::dvec3& point : stroke.path) includeClipped(Box{point - 2.0 * stroke.radius, point + 2.0 * stroke.radius});
    for (const auto& receiver : scene.receivers) {
        glm::dvec3 u, v;
        orthonormalBasis(receiver.normal, u, v);
        for (double su : {-0.5, 0.5})
            for (double sv : {-0.5, 0.5}) include(region, receiver.point + receiver.size * (su * u + sv * v));
    }
    return glm::all(glm::lessThanEqual(region.min, region.max)) ? region : gridBox;
}

std::vector<layout::GpuEmitter> buildEmitters(const std::vector<LightDesc>& lights, const Box& region,
                                              long long photons, const Rgb& glowPower) {
    std::vector<EmitterGeometry> geometries;
    double totalPower = 0.0;
    for (const auto& light : lights) {
        const EmitterGeometry geometry = emitterGeometry(light, region);
        if (channelSum(geometry.powerIntoRegion) <= 0.0) continue;
        totalPower += channelSum(geometry.powerIntoRegion);
        geometries.push_back(geometry);
    }
    if (channelSum(glowPower) > 0.0) {
        EmitterGeometry glow;  // sampled from its cells, not from this geometry
        glow.kind = 2.0f;
        glow.powerIntoRegion = glowPower;
        totalPower += channelSum(glowPower);
        geometries.push_back(glow);
    }
    std::vector<layout::GpuEmitter> emitters;
    long long first = 0;
    for (std::size_t i = 0; i < geometries.size(); ++i) {
        const EmitterGeometry& geometry = geometries[i];
        const bool last = i + 1 == geometries.size();
        const long long share = std::llround(static_cast<double>(photons) * channelSum(geometry.powerIntoRegion) / totalPower);
        const long long count = last ? std::max(1LL, photons - first) : std::max(1LL, share);
        glm::dvec3 tangent, bitangent;
        orthonormalBasis(geometry.axis, tangent, bitangent);
        const auto strataU = static_cast<unsigned>(std::floor(std::sqrt(static_cast<double>(count))));
        layout::GpuEmitter emitter{};
        emitter.origin = glm::vec4(glm::vec3(geometry.origin), geometry.kind);
        emitter.axis = glm::vec4(glm::vec3(geometry.axis), static_cast<float>(geometry.shape));
        emitter.tangent = glm::vec4(glm::vec3(tangent), 0.0f);
        emitter.bitangent = glm::vec4(glm::vec3(bitangent), 0.0f);
        // A glowing volume's photon carries the whole power in each channel,
        // times its cell's colour (ε_c / Σε): the power summed over channels.
        const Rgb photonPower = geometry.kind == 2.0f ? Rgb(channelSum(geometry.powerIntoRegion))
                                                      : geometry.powerIntoRegion;
        emitter.photonPower = glm::vec4(glm::vec3(photonPower / static_cast<double>(count)), 0.0f);
        emitter.spot = glm::vec4(glm::vec3(geometry.spotAxis), static_cast<float>(geometry.spotVersineOuter));
        emitter.spotEdge = glm::vec4(static_cast<float>(geometry.spotVersineInner), 0.0f, 0.0f, 0.0f);
        emitter.photons = glm::uvec4(static_cast<unsigned>(first), static_cast<unsigned>(count), strataU,
                                     static_cast<unsigned>(count / strataU));
        emitters.push_back(emitter);
        first += count;
    }
    return emitters;
}

}  // namespace eikon::render
