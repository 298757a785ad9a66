#include "sim/optics/VolumeOptics.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"
#include "sim/optics/AirOptics.h"
#include "sim/optics/Blackbody.h"

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

// Built on first use (4097 Planck integrals), by scenes that glow only.
const BlackbodyTable& planckTable() {
    static const BlackbodyTable table;
    return table;
}

}  // namespace

double volumeTemperature(const VolumeDesc& volume, const VolumeSamples& samples, std::size_t cell) {
    double t = volume.ambientTemperature;
    if (!samples.temperature.empty()) t += volume.temperatureScale * samples.temperature[cell];
    if (!samples.flame.empty()) t += volume.flameTemperature * samples.flame[cell];
    return t;
}

void writeVolumeOptics(const VolumeDesc& volume, const Material& medium, const VolumeSamples& samples,
                       const std::string& source, FieldSet& fields) {
    const std::size_t cells = fields.grid.cellCount();
    const GladstoneDale air{volume.refractivity, volume.referenceTemperature, 101325.0};
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
    const auto refuse = [&](std::size_t cell, const std::string& expected, double found) {
        throw InputError(source + ": cell " + std::to_string(cell), expected, formatNumber(found));
    };

    std::vector<float> deltaIndex(cells);
    std::vector<float> extinction(absorbs ? 3 * cells : 0), scattering(scatters ? 3 * cells : 0);
    std::vector<float> anisotropy(anisotropic ? cells : 0);
    std::vector<float> emission(emits ? 3 * cells : 0);
    for (std::size_t c = 0; c < cells; ++c) {
        const double t = volumeTemperature(volume, samples, c);
        if (!(t > 0.0))
            throw InputError(source + ": cell " + std::to_string(c), "a temperature > 0 K (ambient_temperature + "
                                                                     "temperature_scale·t + flame_temperature·f)",
                             std::to_string(t) + " K");
        // The index where the volume is: the medium's, or the file's own.
        double baseDelta = mediumDelta;
        if (!samples.index.empty()) {
            if (!(samples.index[c] > 0.0f))
                refuse(c, "an index > 0 in the index grid (outside its active voxels a grid reads its background)",
                       samples.index[c]);
            baseDelta = static_cast<double>(samples.index[c]) - fields.referenceIndex;
        } else if (!samples.deltaIndex.empty()) {
            baseDelta = samples.deltaIndex[c];
        }
        deltaIndex[c] = static_cast<float>(baseDelta + air.refractivityAt(t, volume.pressure) - ambient);
        const double rho = dense ? std::max(0.0, static_cast<double>(samples.density[c])) : 0.0;
        const double flameKappa = soot ? volume.flameAbsorption * std::max(0.0, static_cast<double>(samples.flame[c])) : 0.0;
        const glm::dvec3 radiance = blackbody ? volume.emissionScale * planckTable().rgb(t) : glm::dvec3(0.0);
        double sigmaSum = 0.0, volumeSigmaSum = 0.0;
        for (int ch = 0; ch < 3; ++ch) {
            const std::size_t k = 3 * c + static_cast<std::size_t>(ch);
            const double kappaGrid = samples.extinction.empty() ? 0.0 : samples.extinction[k];
            const double sigmaGrid = scatteringGrid ? samples.scattering[k] : 0.0;
            if (kappaGrid < 0.0) refuse(c, "an extinction >= 0 in the extinction grid", kappaGrid);
            if (sigmaGrid < 0.0) refuse(c, "a scattering >= 0 in the scattering grid", sigmaGrid);
            const double kappa = medium.extinction[ch] + volume.densityExtinction[ch] * rho + kappaGrid + flameKappa;
            const double volumeSigma = volume.densityScattering[ch] * rho + sigmaGrid;
            if (absorbs) extinction[k] = static_cast<float>(kappa);
            if (emits) {
                const double epsilonGrid = samples.emission.empty() ? 0.0 : samples.emission[k];
                if (!(epsilonGrid >= 0.0)) refuse(c, "an emission >= 0 in the emission grid", epsilonGrid);
                const double absorption = std::max(0.0, kappa - medium.scattering[ch] - volumeSigma);
                emission[k] = static_cast<float>(absorption * radiance[ch] + epsilonGrid);
            }
            if (scatters) {
                if (medium.scattering[ch] + volumeSigma > kappa)
                    refuse(c, "scattering <= extinction (the scattering grid's σs within the extinction it adds to)",
                           medium.scattering[ch] + volumeSigma);
                scattering[k] = static_cast<float>(medium.scattering[ch] + volumeSigma);
                sigmaSum += medium.scattering[ch] + volumeSigma;
                volumeSigmaSum += volumeSigma;
            }
        }
        const double volumeG = samples.anisotropy.empty() ? volume.anisotropy : samples.anisotropy[c];
        if (!(std::abs(volumeG) < 1.0)) refuse(c, "an anisotropy g in (−1, 1) in the anisotropy grid", volumeG);
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
