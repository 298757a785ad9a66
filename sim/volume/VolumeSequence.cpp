#include "sim/volume/VolumeSequence.h"

#include "io/vdb/VdbVolumeFile.h"
#include "io/vdb/VolumeFramePath.h"
#include "io/vdb/VolumePlacement.h"

#include "bridge/core/Error.h"

#include <glm/mat3x3.hpp>

#include <filesystem>

namespace eikon::sim {

namespace {

constexpr int kRgb = 0;  // κ, σs, ε: RGB from a vec3s grid, grey from a float grid

// Where each scalar grid the scene may read goes, sampled as how many
// components (the velocity, turned with the volume, apart).
struct GridSlot {
    std::string VolumeDesc::*name;
    std::vector<float> VolumeSamples::*samples;
    int components;  // 1 or kRgb
};
constexpr GridSlot kGridSlots[] = {
    {&VolumeDesc::densityGrid, &VolumeSamples::density, 1},
    {&VolumeDesc::temperatureGrid, &VolumeSamples::temperature, 1},
    {&VolumeDesc::flameGrid, &VolumeSamples::flame, 1},
    {&VolumeDesc::indexGrid, &VolumeSamples::index, 1},
    {&VolumeDesc::deltaIndexGrid, &VolumeSamples::deltaIndex, 1},
    {&VolumeDesc::anisotropyGrid, &VolumeSamples::anisotropy, 1},
    {&VolumeDesc::extinctionGrid, &VolumeSamples::extinction, kRgb},
    {&VolumeDesc::scatteringGrid, &VolumeSamples::scattering, kRgb},
    {&VolumeDesc::emissionGrid, &VolumeSamples::emission, kRgb},
};

int componentsOf(const GridSlot& slot, const std::string& grid, const io::VdbVolumeFile& file) {
    return slot.components == kRgb ? file.componentsOf(grid) : slot.components;
}

// Runs `read`; a file's own refusal (io/vdb names the file, grid or byte) is
// told where the scene names the file.
template <typename Read>
void readNamedByScene(const std::string& scenePath, Read&& read) {
    try {
        read();
    } catch (const InputError& error) {
        throw InputError(scenePath + ": volume.path: " + error.what());
    }
}

}  // namespace

void checkVolumeFrames(const VolumeDesc& desc, const GridSpec& renderGrid, int frames, const std::string& scenePath) {
    if (!desc.sequence) return;
    for (int frame = 0; frame < frames; ++frame) {  // a missing file first: the cheapest to find
        const std::string path = volumeFramePath(desc, desc.frameStart + frame);
        if (!std::filesystem::is_regular_file(path))
            throw InputError(scenePath + ": volume.path: " + path,
                             "the volume sequence's file for rendered frame " + std::to_string(frame), "no such file");
    }
    for (int frame = 0; frame < frames; ++frame)
        readNamedByScene(scenePath, [&] {
            const io::VdbVolumeFile file(volumeFramePath(desc, desc.frameStart + frame));
            const glm::dmat4 placement = io::volumePlacement(desc, file);
            for (const GridSlot& slot : kGridSlots) {
                const std::string& grid = desc.*slot.name;
                if (!grid.empty()) file.check(grid, componentsOf(slot, grid, file), renderGrid, placement);
            }
            if (!desc.velocityGrid.empty()) file.check(desc.velocityGrid, 3, renderGrid, placement);
        });
}

VolumeSequence::VolumeSequence(const VolumeDesc& desc, const Material& medium, const GridSpec& renderGrid,
                               const std::string& scenePath)
    : desc_(desc), medium_(medium), grid_(renderGrid), scenePath_(scenePath) {
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
    VolumeSamples samples;
    std::vector<float> velocity;
    readNamedByScene(scenePath_, [&] {
        const io::VdbVolumeFile file(path);
        const glm::dmat4 placement = io::volumePlacement(desc_, file);
        for (const GridSlot& slot : kGridSlots) {
            const std::string& grid = desc_.*slot.name;
            if (grid.empty()) continue;
            const int components = componentsOf(slot, grid, file);
            std::vector<float> values = file.sample(grid, components, grid_, placement);
            if (slot.components == kRgb && components == 1) {  // grey: the same value in each channel
                std::vector<float> channels(3 * values.size());
                for (std::size_t c = 0; c < values.size(); ++c)
                    channels[3 * c] = channels[3 * c + 1] = channels[3 * c + 2] = values[c];
                values = std::move(channels);
            }
            samples.*slot.samples = std::move(values);
        }
        if (desc_.velocityGrid.empty()) return;
        velocity = file.sample(desc_.velocityGrid, 3, grid_, placement);
        const glm::dmat3 turn(placement);  // a velocity turns and scales with the volume
        for (std::size_t c = 0; c < velocity.size(); c += 3) {
            const glm::dvec3 v = turn * glm::dvec3(velocity[c], velocity[c + 1], velocity[c + 2]);
            for (int a = 0; a < 3; ++a) velocity[c + static_cast<std::size_t>(a)] = static_cast<float>(v[a]);
        }
    });
    samples_ = std::move(samples);
    velocity_ = std::move(velocity);
    file_ = path;
    frame_ = frame;
}

void VolumeSequence::writeFields(FieldSet& fields) const {
    writeVolumeOptics(desc_, medium_, samples_, {scenePath_, file_}, fields);
}

std::vector<NamedArray> VolumeSequence::exportArrays() const {
    std::vector<NamedArray> arrays;
    // The cache's density, flame and velocity keep its own units (Blender's
    // velocity is in domain cells per frame unless the cache says otherwise).
    if (!samples_.density.empty()) arrays.push_back({"density", 1, samples_.density, {"cache units", ArrayRole::Density}});
    if (!samples_.temperature.empty() || !samples_.flame.empty()) {
        const auto ambient = static_cast<float>(desc_.ambientTemperature);
        NamedArray temperature{"temperature", 1, std::vector<float>(grid_.cellCount()), {"K", ArrayRole::Scalar, ambient}};
        for (std::size_t c = 0; c < temperature.values.size(); ++c)
            temperature.values[c] = static_cast<float>(volumeTemperature(desc_, samples_, c));
        arrays.push_back(std::move(temperature));
    }
    if (!samples_.flame.empty()) arrays.push_back({"flame", 1, samples_.flame, {"cache units", ArrayRole::Density}});
    if (!velocity_.empty()) arrays.push_back({"velocity", 3, velocity_, {"cache units", ArrayRole::Velocity}});
    return arrays;
}

}  // namespace eikon::sim
