#include "sim/optics/VolumeOptics.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"
#include "sim/optics/AirOptics.h"
#include "sim/optics/Blackbody.h"
#include "shaders/common/cpp_shim.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace eikon::shader {
namespace {
#include "shaders/common/gas_index.glsl"
#include "shaders/common/volume_coefficient.glsl"
}  // namespace
}  // namespace eikon::shader
// The shared file numbers the units in VolumeDesc::TemperatureUnit's order.
static_assert(eikon::shader::kKelvinAboveAmbient ==
                  static_cast<unsigned>(eikon::VolumeDesc::TemperatureUnit::KelvinAboveAmbient) &&
              eikon::shader::kKelvin == static_cast<unsigned>(eikon::VolumeDesc::TemperatureUnit::Kelvin) &&
              eikon::shader::kCelsius == static_cast<unsigned>(eikon::VolumeDesc::TemperatureUnit::Celsius));

namespace eikon::sim {

namespace {

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

constexpr double kZeroCelsius = 273.15;  // K
// How far a solver's mass fraction may stray outside [0, 1], and their sum
// past 1, by its own rounding and transport error.
constexpr double kMassFractionSlack = 1e-3;

// A volume file's temperature grid that looks absolute under the default
// unit (absoluteLookingTemperature): refused, naming the file's keys.
void refuseAbsoluteLookingTemperature(const VolumeDesc& volume, const VolumeSamples& samples,
                                      const VolumeOrigin& origin) {
    const std::optional<float> smallest = absoluteLookingTemperature(volume, samples);
    if (!smallest) return;
    throw InputError(origin.scene + ": volume.grids.temperature (grid \"" + volume.temperatureGrid + "\" in " +
                         origin.file + ")",
                     "a temperature above ambient (the default for Blender's and Houdini's caches), within " +
                         formatRounded(kAbsoluteTemperatureLooking) +
                         " K of 0 somewhere; for an absolute temperature declare volume.fields with "
                         "temperature_unit \"kelvin\" or \"celsius\"",
                     "every nonzero sample at least " + formatRounded(*smallest) + " (an absolute temperature?)");
}

// Built on first use (4097 Planck integrals), by scenes that glow only.
const BlackbodyTable& planckTable() {
    static const BlackbodyTable table;
    return table;
}

}  // namespace

std::optional<float> absoluteLookingTemperature(const VolumeDesc& volume, const VolumeSamples& samples) {
    if (!volume.implicitTemperatureUnit || volume.temperatureUnit != VolumeDesc::TemperatureUnit::KelvinAboveAmbient ||
        samples.temperature.empty())
        return std::nullopt;
    // Most grids read so hold small values: the first below the bound ends the scan.
    float smallest = std::numeric_limits<float>::infinity();
    for (const float t : samples.temperature) {
        if (t != 0.0f && t < kAbsoluteTemperatureLooking) return std::nullopt;
        if (t != 0.0f) smallest = std::min(smallest, t);
    }
    if (!std::isfinite(smallest)) return std::nullopt;
    return smallest;
}

double volumeTemperature(const VolumeDesc& volume, const VolumeSamples& samples, std::size_t cell) {
    if (!samples.covers(cell)) return volume.ambientTemperature;
    double t = volume.ambientTemperature;
    if (!samples.temperature.empty())
        t = shader::sample_temperature(static_cast<unsigned>(volume.temperatureUnit), samples.temperature[cell],
                                       volume.ambientTemperature, volume.temperatureScale, kZeroCelsius);
    if (!samples.flame.empty()) t += volume.flameTemperature * samples.flame[cell];
    return t;
}

void writeVolumeOptics(const VolumeDesc& volume, const Material& medium, const VolumeSamples& samples,
                       const VolumeOrigin& origin, FieldSet& fields) {
    refuseAbsoluteLookingTemperature(volume, samples, origin);
    const std::size_t cells = fields.grid.cellCount();
    if (samples.massFractions.size() != volume.massFractions.size() * cells)
        throw std::invalid_argument("writeVolumeOptics: a mass fraction grid for each of volume.massFractions");
    const GladstoneDale air{volume.refractivity, volume.referenceTemperature, 101325.0};
    const double gladstoneDale = volume.gladstoneDale.value_or(air.airConstant());
    const double ambient = air.refractivityAt(volume.ambientTemperature, volume.pressure);
    const double mediumDelta = medium.index - fields.referenceIndex;
    const bool dense = !samples.density.empty();
    const bool scatteringGrid = !samples.scattering.empty();
    const bool soot = !samples.flame.empty() && volume.flameAbsorption > 0.0;
    const bool absorbs = positive(medium.extinction) || (dense && positive(volume.densityExtinction)) ||
                         !samples.extinction.empty() || scatteringGrid || soot;
    const bool blackbody = volume.emission == VolumeDesc::Emission::Blackbody;
    const bool emits = blackbody || !samples.emission.empty();
    const bool scatters = positive(medium.scattering) || (dense && positive(volume.densityScattering)) || scatteringGrid;
    const bool anisotropic =
        scatters && (medium.anisotropy != 0.0 || volume.anisotropy != 0.0 || !samples.anisotropy.empty());

    // The keys each refused quantity is computed from, as a user edits them.
    const bool aboveAmbient = volume.temperatureUnit == VolumeDesc::TemperatureUnit::KelvinAboveAmbient;
    const std::string temperatureKeys =
        std::string(samples.temperature.empty() ? ""
                    : aboveAmbient          ? "volume.temperature_scale, "
                                            : "volume.fields.temperature, volume.fields.temperature_unit, ") +
        (samples.flame.empty() ? "" : "volume.flame_temperature, ") + "volume.ambient_temperature";
    const std::string indexKeys =
        std::string(!samples.index.empty() ? "volume.grids.index" : !samples.deltaIndex.empty() ? "volume.grids.delta_index"
                                                                                                  : "medium.index") +
        (!samples.gasDensity.empty() ? std::string(", volume.fields.density, volume.gladstone_dale") +
                                           (volume.massFractions.empty() ? "" : ", volume.fields.mass_fractions")
                                     : !samples.pressure.empty() ? ", volume.fields.pressure" : "") +
        ", volume.refractivity, volume.pressure, volume.reference_temperature";
    const std::string extinctionKeys = std::string(samples.extinction.empty() ? "" : "volume.grids.extinction, ") +
                                       (dense ? "volume.density_extinction, " : "") +
                                       (soot ? "volume.flame_absorption, " : "") + "medium.extinction";
    const std::string scatteringKeys = std::string(scatteringGrid ? "volume.grids.scattering, " : "") +
                                       (dense ? "volume.density_scattering, " : "") + "medium.scattering";
    // "scene.json: KEYS (QUANTITY at (x, y, z) m in FILE): expected …, found …"
    const auto refuse = [&](std::size_t cell, const std::string& keys, const std::string& quantity,
                            const std::string& expected, double found, const char* unit = "") {
        const auto nx = static_cast<std::size_t>(fields.grid.resolution.x);
        const auto ny = static_cast<std::size_t>(fields.grid.resolution.y);
        const glm::dvec3 at = fields.grid.cellCentre(static_cast<int>(cell % nx), static_cast<int>(cell / nx % ny),
                                                     static_cast<int>(cell / (nx * ny)));
        throw InputError(origin.scene + ": " + keys + " (" + quantity + " at " + formatPosition(at) + " in " +
                             origin.file + ")",
                         expected, formatRounded(found) + unit);
    };
    const auto finiteFloat = [](double value) {  // the fields hold float32
        return std::abs(value) <= static_cast<double>(std::numeric_limits<float>::max());
    };

    // Gladstone–Dale's K of the gas in cell c: the volume's, or the mixture's
    // Σ Y_i·K_i + (1 − Σ Y_i)·K, the rest of the mass the volume's gas.
    const auto mixtureConstant = [&](std::size_t c) {
        double constant = gladstoneDale, total = 0.0;
        for (std::size_t g = 0; g < volume.massFractions.size(); ++g) {
            const VolumeDesc::MassFraction& gas = volume.massFractions[g];
            const double y = samples.massFractions[g * cells + c];
            if (!(y >= -kMassFractionSlack && y <= 1.0 + kMassFractionSlack))
                refuse(c, "volume.fields.mass_fractions." + gas.species, "array \"" + gas.grid + "\"",
                       "a mass fraction in [0, 1] (to " + formatRounded(kMassFractionSlack) + ")", y);
            constant += y * (gas.gladstoneDale - gladstoneDale);
            total += y;
        }
        if (total > 1.0 + kMassFractionSlack)
            refuse(c, "volume.fields.mass_fractions", "the mass fractions' sum",
                   "mass fractions that sum to at most 1 (to " + formatRounded(kMassFractionSlack) +
                       "; the rest of the mass is the gas of volume.gladstone_dale)",
                   total);
        return constant;
    };

    std::vector<float> deltaIndex(cells);
    std::vector<float> extinction(absorbs ? 3 * cells : 0), scattering(scatters ? 3 * cells : 0);
    std::vector<float> anisotropy(anisotropic ? cells : 0);
    std::vector<float> emission(emits ? 3 * cells : 0);
    for (std::size_t c = 0; c < cells; ++c) {
        const double t = volumeTemperature(volume, samples, c);
        if (!(t > 0.0) || !std::isfinite(t))
            refuse(c, temperatureKeys, "the temperature",
                   aboveAmbient ? "a finite temperature > 0 K (ambient_temperature + temperature_scale·t + "
                                  "flame_temperature·f, t and f the file's temperature and flame)"
                                : "a finite temperature > 0 K (the file's temperature in its temperature_unit, plus "
                                  "flame_temperature·f)",
                   t, " K");
        // The index where the volume is: the medium's, or the file's own.
        const bool inData = samples.covers(c);
        double baseDelta = mediumDelta;
        if (inData && !samples.index.empty()) {
            if (!(samples.index[c] > 0.0f))
                refuse(c, "volume.grids.index", "grid \"" + volume.indexGrid + "\"",
                       "an index > 0 in the index grid (outside its active voxels a grid reads its background)",
                       samples.index[c]);
            baseDelta = static_cast<double>(samples.index[c]) - fields.referenceIndex;
        } else if (inData && !samples.deltaIndex.empty()) {
            baseDelta = samples.deltaIndex[c];
        }
        // The gas's n − 1: Gladstone–Dale of its density, or of T at its pressure.
        double gas = ambient;
        if (inData && !samples.gasDensity.empty()) {
            if (!(samples.gasDensity[c] >= 0.0f))
                refuse(c, "volume.fields.density", "array \"" + volume.gasDensityGrid + "\"",
                       "a gas density >= 0 kg/m³", samples.gasDensity[c], " kg/m³");
            gas = mixtureConstant(c) * samples.gasDensity[c];
        } else if (inData) {
            const double p = samples.pressure.empty() ? volume.pressure : samples.pressure[c];
            if (!(p > 0.0))
                refuse(c, "volume.fields.pressure", "array \"" + volume.pressureGrid + "\"",
                       "a pressure > 0 Pa (an absolute pressure)", p, " Pa");
            gas = shader::gas_refractivity(air.refractivity, air.referenceTemperature, air.referencePressure, t, p);
        }
        const double delta = baseDelta + gas - ambient;
        if (!finiteFloat(delta) || !(fields.referenceIndex + delta > 0.0))
            refuse(c, indexKeys, "the refractive index",
                   "a finite index n > 0 (the medium's or the index grid's, plus n_air(T) − "
                   "n_air(ambient_temperature) by Gladstone–Dale, here at T = " + formatRounded(t) + " K)",
                   fields.referenceIndex + delta);
        deltaIndex[c] = static_cast<float>(delta);
        const double rho = dense ? static_cast<double>(samples.density[c]) : 0.0;
        const double flameKappa = soot ? volume.flameAbsorption * std::max(0.0, static_cast<double>(samples.flame[c])) : 0.0;
        const glm::dvec3 radiance = blackbody ? volume.emissionScale * planckTable().rgb(t) : glm::dvec3(0.0);
        double sigmaSum = 0.0, volumeSigmaSum = 0.0;
        for (int ch = 0; ch < 3; ++ch) {
            const std::size_t k = 3 * c + static_cast<std::size_t>(ch);
            const double kappaGrid = samples.extinction.empty() ? 0.0 : samples.extinction[k];
            const double sigmaGrid = scatteringGrid ? samples.scattering[k] : 0.0;
            if (kappaGrid < 0.0)
                refuse(c, "volume.grids.extinction", "grid \"" + volume.extinctionGrid + "\"",
                       "an extinction >= 0 in the extinction grid", kappaGrid, " /m");
            if (sigmaGrid < 0.0)
                refuse(c, "volume.grids.scattering", "grid \"" + volume.scatteringGrid + "\"",
                       "a scattering >= 0 in the scattering grid", sigmaGrid, " /m");
            const double kappa = shader::volume_coefficient(medium.extinction[ch], volume.densityExtinction[ch], rho,
                                                            kappaGrid, flameKappa);
            const double volumeSigma = shader::volume_coefficient(0.0, volume.densityScattering[ch], rho, sigmaGrid, 0.0);
            if (absorbs && !finiteFloat(kappa))
                refuse(c, extinctionKeys, "the extinction κ",
                       "a finite extinction (medium.extinction + density_extinction·ρ + the extinction grid + "
                       "flame_absorption·f, ρ and f the file's density and flame)",
                       kappa, " /m");
            if (absorbs) extinction[k] = static_cast<float>(kappa);
            if (emits) {
                const double epsilonGrid = samples.emission.empty() ? 0.0 : samples.emission[k];
                if (!(epsilonGrid >= 0.0))
                    refuse(c, "volume.grids.emission", "grid \"" + volume.emissionGrid + "\"",
                           "an emission >= 0 in the emission grid", epsilonGrid, " W/(m³·sr)");
                const double absorption = std::max(0.0, kappa - medium.scattering[ch] - volumeSigma);
                const double epsilon = absorption * radiance[ch] + epsilonGrid;
                if (!finiteFloat(epsilon))
                    refuse(c, "volume.emission_scale, " + temperatureKeys + ", " + extinctionKeys, "the emission ε",
                           "a finite emission (emission_scale·(κ − σs)·B(T) + the emission grid, here at T = " +
                               formatRounded(t) + " K)",
                           epsilon, " W/(m³·sr)");
                emission[k] = static_cast<float>(epsilon);
            }
            if (scatters) {
                const double sigma = medium.scattering[ch] + volumeSigma;
                if (!finiteFloat(sigma))
                    refuse(c, scatteringKeys, "the scattering σs",
                           "a finite scattering (medium.scattering + density_scattering·ρ + the scattering grid)",
                           sigma, " /m");
                if (sigma > kappa)
                    refuse(c, scatteringKeys + ", " + extinctionKeys, "the scattering σs",
                           "scattering <= extinction = " + formatRounded(kappa) +
                               " /m (the scattering grid's σs within the extinction it adds to)",
                           sigma, " /m");
                scattering[k] = static_cast<float>(sigma);
                sigmaSum += sigma;
                volumeSigmaSum += volumeSigma;
            }
        }
        const double volumeG = samples.anisotropy.empty() ? volume.anisotropy : samples.anisotropy[c];
        if (!(std::abs(volumeG) < 1.0))
            refuse(c, "volume.grids.anisotropy", "grid \"" + volume.anisotropyGrid + "\"",
                   "an anisotropy g in (−1, 1) in the anisotropy grid", volumeG);
        if (anisotropic && sigmaSum > 0.0)
            anisotropy[c] = static_cast<float>(
                (medium.anisotropy * (sigmaSum - volumeSigmaSum) + volumeG * volumeSigmaSum) / sigmaSum);
    }
    publishField(fields.deltaIndex, std::move(deltaIndex), fields.indexVersion);
    publishField(fields.extinction, std::move(extinction), fields.extinctionVersion);
    std::uint64_t emissionVersion = fields.extinctionVersion;
    publishField(fields.emission, std::move(emission), emissionVersion);
    fields.extinctionVersion = std::max(fields.extinctionVersion, emissionVersion);  // κ and ε share a version
    const std::uint64_t before = fields.scatteringVersion;
    publishField(fields.scattering, std::move(scattering), fields.scatteringVersion);
    std::uint64_t gVersion = before;
    publishField(fields.anisotropy, std::move(anisotropy), gVersion);
    if (gVersion != before && fields.scatteringVersion == before) ++fields.scatteringVersion;  // σs and g share a version
}

}  // namespace eikon::sim
