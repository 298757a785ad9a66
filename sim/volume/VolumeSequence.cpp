#include "sim/volume/VolumeSequence.h"

#include "io/vdb/VdbVolumeFile.h"
#include "io/vdb/VolumeFramePath.h"
#include "io/vdb/VolumePlacement.h"
#include "io/vtk/VtkVolumeSource.h"

#include "bridge/core/Error.h"

#include <glm/mat3x3.hpp>

#include <algorithm>
#include <filesystem>

namespace eikon::sim {

namespace {

constexpr int kRgb = 0;  // κ, σs, ε: RGB from a vec3s grid, grey from a float grid

// Where each scalar grid the scene may read goes, sampled as how many
// components (the velocity, turned with the volume, apart), and the key
// under volume.grids or volume.fields that names it.
struct GridSlot {
    std::string VolumeDesc::*name;
    std::vector<float> VolumeGrids::*samples;
    int components;  // 1 or kRgb
    const char* key;
};
constexpr GridSlot kGridSlots[] = {
    {&VolumeDesc::densityGrid, &VolumeGrids::density, 1, "density"},
    {&VolumeDesc::temperatureGrid, &VolumeGrids::temperature, 1, "temperature"},
    {&VolumeDesc::flameGrid, &VolumeGrids::flame, 1, "flame"},
    {&VolumeDesc::indexGrid, &VolumeGrids::index, 1, "index"},
    {&VolumeDesc::deltaIndexGrid, &VolumeGrids::deltaIndex, 1, "delta_index"},
    {&VolumeDesc::anisotropyGrid, &VolumeGrids::anisotropy, 1, "anisotropy"},
    {&VolumeDesc::extinctionGrid, &VolumeGrids::extinction, kRgb, "extinction"},
    {&VolumeDesc::scatteringGrid, &VolumeGrids::scattering, kRgb, "scattering"},
    {&VolumeDesc::emissionGrid, &VolumeGrids::emission, kRgb, "emission"},
    {&VolumeDesc::gasDensityGrid, &VolumeGrids::gasDensity, 1, "density"},
    {&VolumeDesc::pressureGrid, &VolumeGrids::pressure, 1, "pressure"},
};

// A grey grid's values as RGB: the same value in each channel.
std::vector<float> greyToRgb(const std::vector<float>& values) {
    std::vector<float> channels(3 * values.size());
    for (std::size_t c = 0; c < values.size(); ++c) channels[3 * c] = channels[3 * c + 1] = channels[3 * c + 2] = values[c];
    return channels;
}

// The VTK step rendered frame `frame` shows: step k for frame k of a time
// series; a single data set for every frame.
int vtkStepOf(const io::VtkVolumeSource& source, int frame) { return source.stepCount() == 1 ? 0 : frame; }

// A time series too short for the frames asked.
void checkVtkSteps(const io::VtkVolumeSource& source, const std::string& path, int frames) {
    if (source.stepCount() > 1 && frames > source.stepCount())
        throw InputError(path,
                         "a time step for each of the " + std::to_string(frames) +
                             " rendered frames (rendered frame k shows step k)",
                         std::to_string(source.stepCount()) + " steps");
}

// The slots whose arrays volume.fields declares, and the requests for them.
std::vector<const GridSlot*> vtkSlots(const VolumeDesc& desc) {
    std::vector<const GridSlot*> slots;
    for (const GridSlot& slot : kGridSlots)
        if (!(desc.*slot.name).empty()) slots.push_back(&slot);
    return slots;
}
// The slots' arrays, then each mixture gas's mass fraction.
std::vector<io::VtkArrayRequest> vtkRequests(const VolumeDesc& desc, const std::vector<const GridSlot*>& slots) {
    std::vector<io::VtkArrayRequest> requests;
    for (const GridSlot* slot : slots) requests.push_back({desc.*slot->name, std::string("volume.fields.") + slot->key});
    for (const VolumeDesc::MassFraction& gas : desc.massFractions)
        requests.push_back({gas.grid, "volume.fields.mass_fractions." + gas.species});
    return requests;
}

// The arrays volume.fields declares, read from a VTK step onto the render grid.
VolumeGrids sampleVtkStep(const VolumeDesc& desc, const io::VtkVolumeSource& source, int step,
                            const GridSpec& grid) {
    const std::vector<const GridSlot*> slots = vtkSlots(desc);
    const std::vector<io::VtkArrayRequest> requests = vtkRequests(desc, slots);
    io::VtkResampled resampled = source.resample(step, requests, grid, desc.placement);
    VolumeGrids samples;
    for (std::size_t r = 0; r < slots.size(); ++r) {
        io::VtkResampled::Array& array = resampled.arrays[r];
        const bool rgb = slots[r]->components == kRgb;
        if (array.components == 3 && !rgb)
            throw InputError(source.stepName(step) + ": array \"" + requests[r].name + "\" (" + requests[r].key + ")",
                             "a scalar array (1 component)", "3 components");
        samples.*slots[r]->samples = rgb && array.components == 1 ? greyToRgb(array.values) : std::move(array.values);
    }
    for (std::size_t r = slots.size(); r < requests.size(); ++r) {
        const io::VtkResampled::Array& array = resampled.arrays[r];
        if (array.components != 1)
            throw InputError(source.stepName(step) + ": array \"" + requests[r].name + "\" (" + requests[r].key + ")",
                             "a scalar array (1 component)", std::to_string(array.components) + " components");
        samples.massFractions.insert(samples.massFractions.end(), array.values.begin(), array.values.end());
    }
    samples.covered = std::move(resampled.covered);
    return samples;
}

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
    if (desc.format == VolumeDesc::Format::Vtk) {
        readNamedByScene(scenePath, [&] {
            const io::VtkVolumeSource source(desc.path);
            checkVtkSteps(source, desc.path, frames);
            const std::vector<io::VtkArrayRequest> requests = vtkRequests(desc, vtkSlots(desc));
            for (int frame = 0; frame < std::min(frames, source.stepCount()); ++frame) source.check(frame, requests);
        });
        return;
    }
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
            for (const VolumeDesc::MassFraction& gas : desc.massFractions) file.check(gas.grid, 1, renderGrid, placement);
            if (!desc.velocityGrid.empty()) file.check(desc.velocityGrid, 3, renderGrid, placement);
        });
}

VolumeSequence::VolumeSequence(const VolumeDesc& desc, const Material& medium, const GridSpec& renderGrid,
                               const std::string& scenePath)
    : desc_(desc), medium_(medium), grid_(renderGrid), scenePath_(scenePath) {
    if (desc_.format == VolumeDesc::Format::Vtk)
        readNamedByScene(scenePath_, [&] { vtk_ = std::make_unique<io::VtkVolumeSource>(desc_.path, desc_.follow.has_value()); });
    if (!desc_.follow) {
        load(0);
        return;
    }
    EIKON_CHECK_MSG(vtk_ != nullptr, "following a volume that is not VTK data");
    follower_ = std::make_unique<VolumeFollower>(*vtk_, vtkRequests(desc_, vtkSlots(desc_)), [this](int step) {
        VolumeGrids samples = sampleVtkStep(desc_, *vtk_, step, grid_);
        // Values the optics refuse (a temperature of 0 K or less, …) make the
        // step damaged too, rather than ending a followed run.
        FieldSet scratch;
        scratch.grid = grid_;
        scratch.referenceIndex = medium_.index;
        writeVolumeOptics(desc_, medium_, samples.view(), {scenePath_, vtk_->stepName(step)}, scratch);
        return samples;
    });
    if (!followNext(true)) {
        std::string skipped;
        for (const SkippedStep& step : finishFollowing()) skipped += "; skipped " + step.step + ": " + step.reason;
        throw InputError(scenePath_ + ": volume.path (followed)",
                         "a complete step of \"" + desc_.path + "\" before following ended",
                         "none before the " + followEnd() + skipped);
    }
    advanceFrame();
    frame_ = 0;  // the first step taken is frame 0
}

bool VolumeSequence::followNext(bool wait) {
    EIKON_CHECK_MSG(follower_ != nullptr, "followNext without following");
    if (!wait) return follower_->poll();
    followOutcome_ = follower_->wait(*desc_.follow);
    return *followOutcome_ == VolumeFollower::Outcome::Ready;
}

std::string VolumeSequence::followEnd() const {
    if (!followOutcome_ || *followOutcome_ == VolumeFollower::Outcome::Ready) return "";
    return *followOutcome_ == VolumeFollower::Outcome::Stopped ? "stop file" : "timeout";
}

std::vector<SkippedStep> VolumeSequence::finishFollowing() {
    EIKON_CHECK_MSG(follower_ != nullptr, "finishFollowing without following");
    return follower_->finish();
}

VolumeSequence::~VolumeSequence() = default;

bool VolumeSequence::isSequence() const {
    return desc_.sequence || follower_ || (vtk_ && vtk_->stepCount() > 1);
}

void VolumeSequence::advanceFrame() {
    if (follower_) {
        VolumeFollower::Step step = follower_->take();
        samples_ = std::move(step.samples);
        file_ = step.name;
        skippedBefore_ = std::move(step.skipped);
        ++frame_;
        return;
    }
    if (isSequence()) load(frame_ + 1);
    else ++frame_;
}

void VolumeSequence::seekFrame(int frame) {
    EIKON_CHECK_MSG(!follower_, "seekFrame on a followed volume: its steps come as a simulation writes them");
    if (isSequence()) load(frame);
    else frame_ = frame;
}

void VolumeSequence::load(int frame) {
    if (vtk_) {
        VolumeGrids samples;
        const int step = vtkStepOf(*vtk_, frame);
        readNamedByScene(scenePath_, [&] {
            checkVtkSteps(*vtk_, desc_.path, frame + 1);
            samples = sampleVtkStep(desc_, *vtk_, step, grid_);
        });
        samples_ = std::move(samples);
        file_ = vtk_->stepName(step);
        frame_ = frame;
        return;
    }
    const std::string path = volumeFramePath(desc_, desc_.frameStart + frame);
    VolumeGrids samples;
    std::vector<float> velocity;
    readNamedByScene(scenePath_, [&] {
        const io::VdbVolumeFile file(path);
        const glm::dmat4 placement = io::volumePlacement(desc_, file);
        for (const GridSlot& slot : kGridSlots) {
            const std::string& grid = desc_.*slot.name;
            if (grid.empty()) continue;
            const int components = componentsOf(slot, grid, file);
            std::vector<float> values = file.sample(grid, components, grid_, placement);
            samples.*slot.samples = slot.components == kRgb && components == 1 ? greyToRgb(values) : std::move(values);
        }
        for (const VolumeDesc::MassFraction& gas : desc_.massFractions) {
            const std::vector<float> values = file.sample(gas.grid, 1, grid_, placement);
            samples.massFractions.insert(samples.massFractions.end(), values.begin(), values.end());
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
    writeVolumeOptics(desc_, medium_, samples_.view(), {scenePath_, file_}, fields);
}

std::vector<NamedArray> VolumeSequence::exportArrays() const {
    std::vector<NamedArray> arrays;
    // The cache's density, flame and velocity keep its own units (Blender's
    // velocity is in domain cells per frame unless the cache says otherwise).
    if (!samples_.density.empty()) arrays.push_back({"density", 1, samples_.density, {"cache units", ArrayRole::Density}});
    if (!samples_.temperature.empty() || !samples_.flame.empty()) {
        const auto ambient = static_cast<float>(desc_.ambientTemperature);
        NamedArray temperature{"temperature", 1, std::vector<float>(grid_.cellCount()), {"K", ArrayRole::Scalar, ambient}};
        const VolumeSamples samples = samples_.view();
        for (std::size_t c = 0; c < temperature.values.size(); ++c)
            temperature.values[c] = static_cast<float>(volumeTemperature(desc_, samples, c));
        arrays.push_back(std::move(temperature));
    }
    if (!samples_.flame.empty()) arrays.push_back({"flame", 1, samples_.flame, {"cache units", ArrayRole::Density}});
    if (!velocity_.empty()) arrays.push_back({"velocity", 3, velocity_, {"cache units", ArrayRole::Velocity}});
    return arrays;
}

}  // namespace eikon::sim
