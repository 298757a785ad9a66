#include "sim/volume/VolumeSequence.h"

#include "io/vdb/VdbVolumeFile.h"
#include "io/vdb/VolumeFramePath.h"

namespace eikon::sim {

VolumeSequence::VolumeSequence(const VolumeDesc& desc, const Material& medium, const GridSpec& renderGrid)
    : desc_(desc), medium_(medium), grid_(renderGrid) {
    load(0);
}

void VolumeSequence::advanceFrame() {
    if (desc_.sequence) load(frame_ + 1);
    else ++frame_;
}

void VolumeSequence::seekFrame(int frame) {
    if (desc_.sequence) load(frame);
    else frame_ = frame;
}

void VolumeSequence::load(int frame) {
    const std::string path = volumeFramePath(desc_, desc_.frameStart + frame);
    const io::VdbVolumeFile file(path);
    VolumeSamples samples;
    if (!desc_.densityGrid.empty()) samples.density = file.sample(desc_.densityGrid, 1, grid_, desc_.offset);
    if (!desc_.temperatureGrid.empty())
        samples.temperature = file.sample(desc_.temperatureGrid, 1, grid_, desc_.offset);
    if (!desc_.flameGrid.empty()) samples.flame = file.sample(desc_.flameGrid, 1, grid_, desc_.offset);
    std::vector<float> velocity;
    if (!desc_.velocityGrid.empty()) velocity = file.sample(desc_.velocityGrid, 3, grid_, desc_.offset);
    samples_ = std::move(samples);
    velocity_ = std::move(velocity);
    file_ = path;
    frame_ = frame;
}

void VolumeSequence::writeFields(FieldSet& fields) const {
    writeVolumeOptics(desc_, medium_, samples_, file_, fields);
}

std::vector<NamedArray> VolumeSequence::exportArrays() const {
    std::vector<NamedArray> arrays;
    if (!samples_.density.empty()) arrays.push_back({"density", 1, samples_.density});
    if (!samples_.temperature.empty() || !samples_.flame.empty()) {
        NamedArray temperature{"temperature", 1, std::vector<float>(grid_.cellCount())};
        for (std::size_t c = 0; c < temperature.values.size(); ++c)
            temperature.values[c] = static_cast<float>(volumeTemperature(desc_, samples_, c));
        arrays.push_back(std::move(temperature));
    }
    if (!samples_.flame.empty()) arrays.push_back({"flame", 1, samples_.flame});
    if (!velocity_.empty()) arrays.push_back({"velocity", 3, velocity_});
    return arrays;
}

}  // namespace eikon::sim
