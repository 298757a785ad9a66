#include "bridge/core/NumberFormat.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace eikon {

namespace {

// Exponent as JSON writers print it: a sign and at least two digits.
std::string exponentText(int exponent) {
    std::string digits = std::to_string(std::abs(exponent));
    if (digits.size() < 2) digits.insert(0, "0");
    return std::string("e") + (exponent < 0 ? "-" : "+") + digits;
}

}  // namespace

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == std::floor(value) && std::abs(value) < 1e15) return std::to_string(static_cast<long long>(value));
    // Shortest round-trip digits d.ddd·10^e, then placed as in RFC 8259 writers.
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
    const std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
    const std::size_t exponentAt = text.find('e');
    const bool negative = text.front() == '-';
    std::string digits;
    for (char c : text.substr(negative ? 1 : 0, exponentAt - (negative ? 1 : 0)))
        if (c != '.') digits += c;
    const int exponent = std::atoi(std::string(text.substr(exponentAt + 1)).c_str());
    const int k = static_cast<int>(digits.size());  // significant digits
    const int n = exponent + 1;                     // digits before the point
    std::string out;
    if (k <= n && n <= 15) out = digits + std::string(static_cast<std::size_t>(n - k), '0') + ".0";
    else if (0 < n && n <= 15) out = digits.substr(0, static_cast<std::size_t>(n)) + "." + digits.substr(static_cast<std::size_t>(n));
    else if (-4 < n && n <= 0) out = "0." + std::string(static_cast<std::size_t>(-n), '0') + digits;
    else if (k == 1) out = digits + exponentText(n - 1);
    else out = digits.substr(0, 1) + "." + digits.substr(1) + exponentText(n - 1);
    return negative ? "-" + out : out;
}

std::string formatRounded(double value) {
    if (!std::isfinite(value)) return formatNumber(value);
    char rounded[32];
    std::snprintf(rounded, sizeof rounded, "%.6g", value);
    return formatNumber(std::strtod(rounded, nullptr));
}

std::string formatPosition(const glm::dvec3& position) {
    return "(" + formatRounded(position.x) + ", " + formatRounded(position.y) + ", " + formatRounded(position.z) + ") m";
}

}  // namespace eikon
