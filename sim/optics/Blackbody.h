// Thermal emission: Planck's law and the colour of a blackbody in eikon's
// RGB channels.
//
// eikon's three channels are linear sRGB / Rec. 709 primaries with the D65
// white ([IEC61966] §5.2, the XYZ → RGB matrix), in radiometric units
// weighted like luminance: a spectrum L_λ (W/(m²·sr·m)) has
//   (X, Y, Z) = ∫ L_λ · (x̄, ȳ, z̄)(λ) dλ   in W/(m²·sr),
// Y = luminance / 683 lm/W, and RGB = M · XYZ. The colour-matching functions
// are the CIE 1931 2° observer in the multi-lobe Gaussian fit of [Wyman13]
// §2, eq. 2 (within the spread of the CIE tables themselves), integrated over
// 360–830 nm. A blackbody's chromaticity is outside the sRGB gamut below
// about 1900 K (blue < 0): such a channel is clipped to 0, the colour a
// display shows anyway.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace eikon::sim {

// Planck's spectral radiance B_λ(T) in W/(m²·sr·m) at wavelength λ (m) and
// temperature T (K) ([Born99] §1.1 uses it; CODATA 2018 h, c, k, exact).
double planckSpectralRadiance(double wavelength, double temperature);

// CIE 1931 2° colour-matching functions x̄, ȳ, z̄ at λ (m), [Wyman13] eq. 2.
glm::dvec3 cieColourMatching(double wavelength);

// ∫ B_λ(T)·(x̄, ȳ, z̄) dλ over 360–830 nm, W/(m²·sr) (1 nm trapezoids).
glm::dvec3 blackbodyXyz(double temperature);

// Linear Rec. 709 RGB of XYZ (negative channels kept).
glm::dvec3 rec709FromXyz(const glm::dvec3& xyz);

// A blackbody's radiance in eikon's RGB channels, W/(m²·sr), each >= 0.
glm::dvec3 blackbodyRgb(double temperature);

// blackbodyRgb by table, for every cell of a frame: ln of each channel
// against ln T, tabulated from 250 K to 50 000 K and interpolated linearly;
// error < 1e-4 of the brightest channel in range
// (tests/unit/test_blackbody.cpp), extrapolated along the end segments
// outside it; 0 at T <= 0.
class BlackbodyTable {
public:
    BlackbodyTable();
    glm::dvec3 rgb(double temperature) const;

private:
    std::vector<glm::dvec3> logRadiance_;  // ln max(channel, tiny) at ln T_i = logMin_ + i·logStep_
    double logMin_ = 0.0, logStep_ = 0.0;
};

}  // namespace eikon::sim
