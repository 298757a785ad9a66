#include "sim/optics/VolumeOptics.h"

#include "bridge/core/Error.h"
#include "sim/optics/AirOptics.h"

#include <algorithm>

namespace eikon::sim {

namespace {

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }


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
    const bool absorbs = positive(medium.extinction) || (dense && positive(volume.densityExtinction));
    const bool scatters = positive(medium.scattering) || (dense && positive(volume.densityScattering));
    const bool anisotropic = scatters && (medium.anisotropy != 0.0 || volume.anisotropy != 0.0);

    std::vector<float> deltaIndex(cells);
    std::vector<float> extinction(absorbs ? 3 * cells : 0), scattering(scatters ? 3 * cells : 0);
    std::vector<float> anisotropy(anisotropic ? cells : 0);
    for (std::size_t c = 0; c < cells; ++c) {
        const double t = volumeTemperature(volume, samples, c);
        if (!(t > 0.0))
            throw InputError(source + ": cell " + std::to_string(c), "a temperature > 0 K (ambient_temperature + "
                                                                     "temperature_scale·t + flame_temperature·f)",
                             std::to_string(t) + " K");
        deltaIndex[c] = static_cast<float>(mediumDelta + air.refractivityAt(t, volume.pressure) - ambient);
        const double rho = dense ? std::max(0.0, static_cast<double>(samples.density[c])) : 0.0;
        double sigmaSum = 0.0, volumeSigmaSum = 0.0;
        for (int ch = 0; ch < 3; ++ch) {
            if (absorbs) extinction[3 * c + ch] = static_cast<float>(medium.extinction[ch] + volume.densityExtinction[ch] * rho);
            if (scatters) {
                scattering[3 * c + ch] = static_cast<float>(medium.scattering[ch] + volume.densityScattering[ch] * rho);
                sigmaSum += medium.scattering[ch] + volume.densityScattering[ch] * rho;
                volumeSigmaSum += volume.densityScattering[ch] * rho;
            }
        }
        if (anisotropic && sigmaSum > 0.0)
            anisotropy[c] = static_cast<float>(
                (medium.anisotropy * (sigmaSum - volumeSigmaSum) + volume.anisotropy * volumeSigmaSum) / sigmaSum);
    }
    publishField(fields.deltaIndex, std::move(deltaIndex), fields.indexVersion);
    publishField(fields.extinction, std::move(extinction), fields.extinctionVersion);
    const std::uint64_t before = fields.scatteringVersion;
    publishField(fields.scattering, std::move(scattering), fields.scatteringVersion);
    std::uint64_t gVersion = before;
    publishField(fields.anisotropy, std::move(anisotropy), gVersion);
    if (gVersion != before && fields.scatteringVersion == before) ++fields.scatteringVersion;  // σs and g share a version
}

}  // namespace eikon::sim
