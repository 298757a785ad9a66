#include "sim/volume/VolumeSequence.h"

#include "io/vdb/VdbVolumeFile.h"
#include "io/vdb/VolumeFramePath.h"

#include "bridge/core/Error.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vector_relational.hpp>

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

namespace {

// The first grid the scene reads from the file.
std::string firstGrid(const VolumeDesc& desc) {
    for (const std::string* name : {&desc.densityGrid, &desc.temperatureGrid, &desc.flameGrid, &desc.velocityGrid,
                                    &desc.indexGrid, &desc.deltaIndexGrid, &desc.extinctionGrid, &desc.scatteringGrid,
                                    &desc.anisotropyGrid, &desc.emissionGrid})
        if (!name->empty()) return *name;
    return {};
}

// A Blender (Mantaflow) cache's index frame in its domain's, centred: voxel
// (i,j,k) at (i,j,k)·dx in the file is the cell covering
// [i, i+1]·D/res from the domain's corner (VolumeDesc::blenderDomainDimensions).
glm::dmat4 blenderCellFrame(const io::VdbVolumeFile& file, const std::string& grid, const glm::dvec3& dimensions) {
    const io::VdbVolumeFile::GridFrame frame = file.gridFrame(grid);
    if (!frame.baseResolution || glm::any(glm::lessThan(*frame.baseResolution, glm::ivec3(1))))
        throw InputError(file.path().string() + ": grid \"" + grid + "\"",
                         "Mantaflow's file_base_resolution metadata (volume.preset \"blender\" reads a Blender cache)",
                         frame.baseResolution ? "a resolution below 1" : "none");
    const double dx = frame.voxelSize.x;
    const glm::dvec3 cell = dimensions / glm::dvec3(*frame.baseResolution);
    return glm::translate(glm::dmat4(1.0), -0.5 * dimensions) * glm::scale(glm::dmat4(1.0), cell / dx) *
           glm::translate(glm::dmat4(1.0), glm::dvec3(0.5 * dx));
}

}  // namespace

void VolumeSequence::load(int frame) {
    const std::string path = volumeFramePath(desc_, desc_.frameStart + frame);
    const io::VdbVolumeFile file(path);
    const glm::dmat4 placement =
        desc_.blenderDomainDimensions
            ? desc_.placement * blenderCellFrame(file, firstGrid(desc_), *desc_.blenderDomainDimensions)
            : desc_.placement;
    VolumeSamples samples;
    if (!desc_.densityGrid.empty()) samples.density = file.sample(desc_.densityGrid, 1, grid_, placement);
    if (!desc_.temperatureGrid.empty())
        samples.temperature = file.sample(desc_.temperatureGrid, 1, grid_, placement);
    if (!desc_.flameGrid.empty()) samples.flame = file.sample(desc_.flameGrid, 1, grid_, placement);
    if (!desc_.indexGrid.empty()) samples.index = file.sample(desc_.indexGrid, 1, grid_, placement);
    if (!desc_.deltaIndexGrid.empty()) samples.deltaIndex = file.sample(desc_.deltaIndexGrid, 1, grid_, placement);
    if (!desc_.anisotropyGrid.empty()) samples.anisotropy = file.sample(desc_.anisotropyGrid, 1, grid_, placement);
    // κ, σs and ε grids: RGB as a vec3s grid, or grey as a float grid.
    const auto rgb = [&](const std::string& name) {
        if (file.componentsOf(name) == 3) return file.sample(name, 3, grid_, placement);
        const std::vector<float> grey = file.sample(name, 1, grid_, placement);
        std::vector<float> channels(3 * grey.size());
        for (std::size_t c = 0; c < grey.size(); ++c) channels[3 * c] = channels[3 * c + 1] = channels[3 * c + 2] = grey[c];
        return channels;
    };
    if (!desc_.extinctionGrid.empty()) samples.extinction = rgb(desc_.extinctionGrid);
    if (!desc_.scatteringGrid.empty()) samples.scattering = rgb(desc_.scatteringGrid);
    if (!desc_.emissionGrid.empty()) samples.emission = rgb(desc_.emissionGrid);
    std::vector<float> velocity;
    if (!desc_.velocityGrid.empty()) {
        velocity = file.sample(desc_.velocityGrid, 3, grid_, placement);
        const glm::dmat3 turn(placement);  // a velocity turns and scales with the volume
        for (std::size_t c = 0; c < velocity.size(); c += 3) {
            const glm::dvec3 v = turn * glm::dvec3(velocity[c], velocity[c + 1], velocity[c + 2]);
            for (int a = 0; a < 3; ++a) velocity[c + static_cast<std::size_t>(a)] = static_cast<float>(v[a]);
        }
    }
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
