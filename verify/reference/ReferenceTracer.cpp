#include "verify/reference/ReferenceTracer.h"

#include "bridge/core/Error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::reference {

namespace {

// Dormand–Prince 5(4) tableau ([Hairer93] Table 5.2).
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
// b − b̂: fifth-order weights minus the embedded fourth-order ones (b̂7 = 1/40).
constexpr double e1 = b1 - 5179.0 / 57600, e3 = b3 - 7571.0 / 16695, e4 = b4 - 393.0 / 640,
                 e5 = b5 + 92097.0 / 339200, e6 = b6 - 187.0 / 2100, e7 = -1.0 / 40;

double componentNorm(const glm::dvec3& error, const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    double worst = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double scale = tolerance * (1.0 + std::max(std::abs(a[i]), std::abs(b[i])));
        worst = std::max(worst, std::abs(error[i]) / scale);
    }
    return worst;
}

}  // namespace

ReferenceTracer::ReferenceTracer(const IndexField& field, ReferenceOptions options) : field_(field), options_(options) {}

RayState ReferenceTracer::start(const glm::dvec3& x, const glm::dvec3& direction) const {
    return {x, field_.index(x) * glm::normalize(direction)};
}

ReferenceTracer::Derivative ReferenceTracer::derivative(const RayState& s) const {
    return {s.v / field_.index(s.x), field_.gradient(s.x)};
}

RayState ReferenceTracer::step(const RayState& s, const Derivative& k1, double h, double& errorNorm) const {
    auto at = [&](glm::dvec3 dx, glm::dvec3 dv) { return derivative({s.x + h * dx, s.v + h * dv}); };
    const Derivative k2 = at(a21 * k1.dx, a21 * k1.dv);
    const Derivative k3 = at(a31 * k1.dx + a32 * k2.dx, a31 * k1.dv + a32 * k2.dv);
    const Derivative k4 = at(a41 * k1.dx + a42 * k2.dx + a43 * k3.dx, a41 * k1.dv + a42 * k2.dv + a43 * k3.dv);
    const Derivative k5 = at(a51 * k1.dx + a52 * k2.dx + a53 * k3.dx + a54 * k4.dx,
                             a51 * k1.dv + a52 * k2.dv + a53 * k3.dv + a54 * k4.dv);
    const Derivative k6 = at(a61 * k1.dx + a62 * k2.dx + a63 * k3.dx + a64 * k4.dx + a65 * k5.dx,
                             a61 * k1.dv + a62 * k2.dv + a63 * k3.dv + a64 * k4.dv + a65 * k5.dv);
    const RayState next{s.x + h * (b1 * k1.dx + b3 * k3.dx + b4 * k4.dx + b5 * k5.dx + b6 * k6.dx),
                        s.v + h * (b1 * k1.dv + b3 * k3.dv + b4 * k4.dv + b5 * k5.dv + b6 * k6.dv)};
    const Derivative k7 = derivative(next);
    const glm::dvec3 errorX = h * (e1 * k1.dx + e3 * k3.dx + e4 * k4.dx + e5 * k5.dx + e6 * k6.dx + e7 * k7.dx);
    const glm::dvec3 errorV = h * (e1 * k1.dv + e3 * k3.dv + e4 * k4.dv + e5 * k5.dv + e6 * k6.dv + e7 * k7.dv);
    errorNorm = std::max(componentNorm(errorX, s.x, next.x, options_.tolerance),
                         componentNorm(errorV, s.v, next.v, options_.tolerance));
    return next;
}

ReferenceResult ReferenceTracer::trace(RayState state, double maxArcLength, const RayEvent& event) const {
    EIKON_CHECK_MSG(maxArcLength > 0.0, "reference trace needs a positive arc length");
    ReferenceResult result;
    double h = std::min(options_.initialStep, options_.maxStep);
    double g = event ? event(state) : 0.0;
    while (result.arcLength < maxArcLength) {
        EIKON_CHECK_MSG(result.acceptedSteps + result.rejectedSteps < options_.maxSteps,
                    "reference trace exceeded its step budget");
        h = std::min({h, options_.maxStep, maxArcLength - result.arcLength});
        const Derivative k1 = derivative(state);
        double errorNorm = 0.0;
        const RayState next = step(state, k1, h, errorNorm);
        // Standard controller: safety 0.9, exponent 1/5, growth in [0.2, 5].
        const double factor = std::clamp(0.9 * std::pow(std::max(errorNorm, 1e-30), -0.2), 0.2, 5.0);
        if (errorNorm > 1.0 || !std::isfinite(errorNorm)) {
            ++result.rejectedSteps;
            h *= std::isfinite(errorNorm) ? factor : 0.2;
            EIKON_CHECK_MSG(h > 1e-16, "reference step size underflow");
            continue;
        }
        const double gNext = event ? event(next) : 0.0;
        if (event && (gNext == 0.0 || (g < 0.0) != (gNext < 0.0))) {
            // Bisect the step length: a single Dormand–Prince step of any
            // length up to h is as accurate as the accepted one.
            double lo = 0.0, hi = h;
            for (int i = 0; i < 200 && hi - lo > 1e-14 * std::max(1.0, h); ++i) {
                const double mid = 0.5 * (lo + hi);
                double ignored = 0.0;
                const RayState trial = step(state, k1, mid, ignored);
                const double gMid = event(trial);
                if (gMid == 0.0 || (g < 0.0) != (gMid < 0.0)) hi = mid;
                else lo = mid;
            }
            double ignored = 0.0;
            result.state = step(state, k1, hi, ignored);
            result.arcLength += hi;
            result.eventHit = true;
            ++result.acceptedSteps;
            return result;
        }
        state = next;
        g = gNext;
        result.arcLength += h;
        ++result.acceptedSteps;
        const double n = field_.index(state.x);
        result.maxInvariantError = std::max(result.maxInvariantError, std::abs(glm::length(state.v) - n) / n);
        h *= factor;
    }
    result.state = state;
    return result;
}

}  // namespace eikon::reference
