// Index fields with closed-form n and ∇n, each the ground truth of an
// accuracy case (docs/accuracy.md): straight lines, the catenary, the mirage
// turning height, the Luneburg focus, Maxwell's fish-eye imaging, the glass
// sphere's paraxial focus and heat-shimmer deflection.
#pragma once

#include "verify/reference/IndexField.h"

namespace eikon::reference {

// n = n0 everywhere.
class UniformField final : public IndexField {
public:
    explicit UniformField(double n0) : n0_(n0) {}
    double index(const glm::dvec3&) const override { return n0_; }
    glm::dvec3 gradient(const glm::dvec3&) const override { return glm::dvec3(0.0); }

private:
    double n0_;
};

// n = a + b·y: rays are catenaries, n·cosθ (the horizontal part of v) is invariant.
class LinearSlabField final : public IndexField {
public:
    LinearSlabField(double a, double b) : a_(a), b_(b) {}
    double index(const glm::dvec3& x) const override { return a_ + b_ * x.y; }
    glm::dvec3 gradient(const glm::dvec3&) const override { return {0.0, b_, 0.0}; }

private:
    double a_, b_;
};

// Hot air over a road: n = n∞ − δ·exp(−y/L), lowest at the ground. A ray with
// invariant C = n·cosθ turns where n(y_t) = C: y_t = −L·ln((n∞ − C)/δ).
class MirageField final : public IndexField {
public:
    MirageField(double nInfinity, double delta, double scaleHeight)
        : nInfinity_(nInfinity), delta_(delta), scale_(scaleHeight) {}
    double index(const glm::dvec3& x) const override;
    glm::dvec3 gradient(const glm::dvec3& x) const override;
    // Height where n equals `invariant`; negative when the ray reaches y = 0 first.
    double turningHeight(double invariant) const;

private:
    double nInfinity_, delta_, scale_;
};

// Luneburg lens of radius R about c: n = √(2 − (r/R)²) inside, 1 outside. A
// parallel beam focuses on the far surface.
class LuneburgField final : public IndexField {
public:
    LuneburgField(glm::dvec3 centre, double radius) : centre_(centre), radius_(radius) {}
    double index(const glm::dvec3& x) const override;
    glm::dvec3 gradient(const glm::dvec3& x) const override;

private:
    glm::dvec3 centre_;
    double radius_;
};

// Maxwell's fish-eye about the origin: n = n0/(1 + (r/R)²). Every ray from P
// passes through its image −R²P/|P|².
class FishEyeField final : public IndexField {
public:
    FishEyeField(double n0, double radius) : n0_(n0), radius_(radius) {}
    double index(const glm::dvec3& x) const override;
    glm::dvec3 gradient(const glm::dvec3& x) const override;
    glm::dvec3 image(const glm::dvec3& point) const;

private:
    double n0_, radius_;
};

// A glass sphere with its surface smoothed by a Gaussian of width w across
// it: n = 1 + (n1 − 1)·½·erfc((r − R)/(√2·w)); w → 0 is the sharp sphere,
// whose paraxial focus lies nR/(2(n − 1)) from the centre.
class GlassSphereField final : public IndexField {
public:
    GlassSphereField(glm::dvec3 centre, double radius, double glassIndex, double smoothingWidth)
        : centre_(centre), radius_(radius), glass_(glassIndex), width_(smoothingWidth) {}
    double index(const glm::dvec3& x) const override;
    glm::dvec3 gradient(const glm::dvec3& x) const override;
    double paraxialFocusFromCentre() const { return glass_ * radius_ / (2.0 * (glass_ - 1.0)); }

private:
    glm::dvec3 centre_;
    double radius_, glass_, width_;
};

// A rising plume of hot air: a vertical Gaussian column about (cx, cz) whose
// index deficit fades with height, n = n_ref − A·exp(−ρ²/(2s²))·exp(−(y − y0)/H)
// with ρ the distance from the axis.
class HeatPlumeField final : public IndexField {
public:
    HeatPlumeField(double referenceIndex, double amplitude, double width, double baseHeight, double fadeHeight,
                   glm::dvec3 axisPoint)
        : reference_(referenceIndex), amplitude_(amplitude), width_(width), base_(baseHeight), fade_(fadeHeight),
          axis_(axisPoint) {}
    double index(const glm::dvec3& x) const override;
    glm::dvec3 gradient(const glm::dvec3& x) const override;

private:
    double reference_, amplitude_, width_, base_, fade_;
    glm::dvec3 axis_;
};

}  // namespace eikon::reference
