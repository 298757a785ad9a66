// Numbers as messages show them.
#pragma once

#include <glm/vec3.hpp>

#include <string>

namespace eikon {

// Shortest text that reads back as the same double ("0.25", "3", "inf"):
// integers below 1e15 without a point, other values in the shortest
// round-trip digits, fixed-point where the point falls within
// 10⁻⁴…10¹⁵ and in exponent form ("1e-05", "2.5e+20") elsewhere — the
// form JSON writers use, so a message quotes a number as the scene file
// could write it.
std::string formatNumber(double value);

// The same to 6 significant digits, for a computed value that no scene file
// wrote ("-0.168177" rather than "-0.16817700862884521").
std::string formatRounded(double value);

// A world position as a refusal names it, each coordinate formatRounded:
// "(0.25, 0.5, -0.125) m".
std::string formatPosition(const glm::dvec3& position);

}  // namespace eikon
