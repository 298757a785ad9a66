// An optical instrument that looks through the scene in place of the
// camera's picture (docs/scene-format.md, `diagnostic`): light crosses the
// test volume along the camera's rays — parallel ones of an orthographic
// camera, or a perspective camera's for background-oriented schlieren — and
// the instrument turns what each ray measured — its optical path
// difference, its deflection, where it lands behind the volume — into the
// picture.
#pragma once

#include "bridge/scene/FloatImage.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace eikon {

struct DiagnosticDesc {
    enum class Type {
        Interferometry,  // Mach–Zehnder: fringes of the optical path difference
        Schlieren,       // an ideal schlieren head and a cut-off in its focal plane
        Shadowgraph,     // the irradiance on a screen behind the volume
        Bos,             // background-oriented schlieren: a random-dot or image background seen through the volume
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

    // Shadowgraph and BOS: the screen or the background is a plane across
    // the camera's axis this far behind the grid's farthest corner along it.
    double screenDistance = 1.0;      // shadowgraph, m, > 0
    double backgroundDistance = 1.0;  // BOS, m, > 0

    // BOS's background: seeded random dark dots on white, one a cell of a
    // square lattice at a random place in it; a dot's darkness
    // exp(−8·r²/d²), d its 1/e² diameter. Or an image file's luminance,
    // centred on the camera's axis and repeated across the plane.
    std::string patternPath;                         // the image file; empty: the dots
    std::shared_ptr<const FloatImage> patternImage;  // its linear RGBA, read with the scene
    std::optional<double> patternWidth;              // m, > 0; none: the background's width as the camera sees it
    std::uint32_t seed = 1;
    std::optional<double> dotDiameter;  // d, m, > 0; none: three pixels' width on the background
    double dotDensity = 0.3;            // π·d²/4 over the cell's area, in (0, 0.5]
};

}  // namespace eikon
