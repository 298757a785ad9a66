// An optical instrument that looks through the scene in place of the
// camera's picture (docs/scene-format.md, `diagnostic`): parallel light
// crosses the test volume along the orthographic camera's rays, and the
// instrument turns what each ray measured — its optical path difference and
// its deflection — into the picture.
#pragma once

namespace eikon {

struct DiagnosticDesc {
    enum class Type {
        Interferometry,  // Mach–Zehnder: fringes of the optical path difference
        Schlieren,       // an ideal schlieren head and a cut-off in its focal plane
    } type = Type::Interferometry;

    // Interferometry: I = I₀·cos²(π·OPD/λ + π·fringeTilt·u), u the
    // horizontal image coordinate in [0, 1).
    double wavelengthNm = 532.0;  // λ, > 0
    double fringeTilt = 0.0;      // fringes per image width of a tilted reference beam

    // Schlieren: the cut-off in the focal plane of the head, f·ε from the
    // source image's rest position.
    enum class Cutoff {
        KnifeEdge,  // I/I₀ = clamp(0.5 + f·ε⊥/a, 0, 1), ε⊥ across the edge
        Circular,   // a graded circular filter: I/I₀ = min(f·|ε|/a, 1)
        Colour,     // a colour filter: hue by the direction of ε, saturation min(f·|ε|/a, 1)
    } cutoff = Cutoff::KnifeEdge;
    double focalLength = 1.0;    // f of the schlieren head, m, > 0
    double sourceHeight = 1e-3;  // a: the source image's uncut height (knife edge), or the filter's clear radius, m, > 0
    double knifeAngleDeg = 0.0;  // knife edge: its angle from the image's horizontal axis, counter-clockwise
};

}  // namespace eikon
