// The instruments of the diagnostics (docs/scene-format.md, `diagnostic`):
// what a ray's measurements — its optical path difference OPD (m), its
// deflection ε (rad, on the image's right and up axes) and its
// transmittance T = exp(−∫κ ds) per channel — make of the light at its
// pixel, as I/I₀ per channel, I₀ the light with neither a test object nor
// a cut-off. EIKON_INSTRUMENT picks one (DiagnosticStage.cpp's
// Instrument); each reads only its own uniforms. GLSL only.
// The shadowgraph's picture is made of where its rays land
// (shadowgraph_screen.comp), BOS's of the background its rays see
// (common/bos_background.glsl).
#ifndef EIKON_INSTRUMENT
#define EIKON_INSTRUMENT 0
#endif
#define EIKON_SHADOWGRAPH 4
#define EIKON_BOS 5

#if EIKON_INSTRUMENT == EIKON_BOS
#include "common/bos_background.glsl"
#elif EIKON_INSTRUMENT == EIKON_SHADOWGRAPH
#elif EIKON_INSTRUMENT == 0
// Mach–Zehnder interferometer: the test beam, delayed by OPD and dimmed to
// amplitude √T, meets an equal reference beam tilted by `fringe_tilt`
// fringes per image width (u the horizontal image coordinate in (0, 1)):
// I/I₀ = (1 + T + 2·√T·cos φ) / 4 with φ = 2π·OPD/λ + 2π·tilt·u, which is
// cos²(φ/2) where the medium is clear and 1/4 (the reference beam alone)
// behind an opaque object.
uniform float phase_per_metre;  // π/λ
uniform float tilt_phase;       // π·fringe_tilt

vec3 instrument_intensity(float opd, vec2 deflection, float u, vec3 transmittance) {
    float c = cos(2.0f * (phase_per_metre * opd + tilt_phase * u));
    return 0.25f * (1.0f + transmittance + 2.0f * sqrt(transmittance) * c);
}
#else
// Schlieren: an ideal head of focal length f images the source in its focal
// plane, moved by f·ε for a ray deflected by ε; the cut-off there passes a
// share of the moved image ([Settles01] ch. 3), dimmed by the ray's
// transmittance (an opaque object is a silhouette). `sensitivity` is f/a.
uniform float sensitivity;  // 1/rad

#if EIKON_INSTRUMENT == 1
// Knife edge across a uniform rectangular source image of height a (uncut),
// its edge through the image's middle: half of I₀ passes undeflected, and a
// shift f·ε⊥ across the edge passes (a/2 + f·ε⊥)/a of it until the image
// is wholly cut or wholly clear: I/I₀ = clamp(0.5 + f·ε⊥/a, 0, 1), the
// contrast ΔI/I₀ = f·ε⊥/a in the linear range (Settles' C = ΔE/E = f·ε⊥/a′
// with a′ = a/2 the unobstructed height, relative to the background E = I₀/2).
uniform vec2 knife_normal;  // unit, on the image axes: deflections toward it brighten

vec3 instrument_intensity(float opd, vec2 deflection, float u, vec3 transmittance) {
    return transmittance * clamp(0.5f + sensitivity * dot(deflection, knife_normal), 0.0f, 1.0f);
}
#elif EIKON_INSTRUMENT == 2
// A graded circular filter about a point source's image: its transmission
// rises linearly with the radius, clear from the radius a on, so
// I/I₀ = min(f·|ε|/a, 1): a dark field in which every gradient shows,
// whatever its direction.
vec3 instrument_intensity(float opd, vec2 deflection, float u, vec3 transmittance) {
    return transmittance * min(sensitivity * length(deflection), 1.0f);
}
#else
// A colour filter: a hue wheel about a point source's image, white at its
// centre and fully saturated from the radius a on. The hue is the direction
// of ε (red: toward the image's right, then counter-clockwise), the
// saturation min(f·|ε|/a, 1).
vec3 instrument_intensity(float opd, vec2 deflection, float u, vec3 transmittance) {
    float hue = atan(deflection.y, deflection.x) / 6.28318530717959f;
    vec3 pure = clamp(abs(mod(6.0f * hue + vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
    return transmittance * mix(vec3(1.0f), pure, min(sensitivity * length(deflection), 1.0f));
}
#endif
#endif
