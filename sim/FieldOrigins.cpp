#include "sim/FieldOrigins.h"

#include "sim/voxelize/VolumePainter.h"

#include <algorithm>
#include <vector>

namespace eikon::sim {

namespace {

constexpr std::size_t kMostKeys = 6;  // a message stays one line's worth

// The strokes that set a property (index Δn, κ or σs) and reach `at`.
void addStrokes(const Scene& scene, const glm::dvec3* at, const char* key, bool (*sets)(const PaintStroke&),
                std::vector<std::string>& keys) {
    for (std::size_t s = 0; s < scene.paint.size(); ++s)
        if (sets(scene.paint[s]) && (!at || strokeReaches(scene.paint[s], *at)))
            keys.push_back("paint[" + std::to_string(s) + "]." + key);
}

void addVolumeGrid(const std::string& grid, const char* key, std::vector<std::string>& keys) {
    if (!grid.empty()) keys.push_back(std::string("volume.grids.") + key);
}

std::vector<std::string> keysOf(const Scene& scene, std::string_view field, const glm::dvec3* at) {
    std::vector<std::string> keys;
    const SimDesc* sim = scene.sim ? &*scene.sim : nullptr;
    const VolumeDesc* volume = scene.volume ? &*scene.volume : nullptr;
    if (field == "index") {
        addStrokes(scene, at, "index", [](const PaintStroke& s) { return s.index != 0.0; }, keys);
        if (sim && sim->fluid == SimDesc::Fluid::Air)
            keys.insert(keys.end(), {"sim.optics.refractivity", "sim.optics.reference_temperature",
                                     "sim.optics.reference_pressure", "sim.ambient_pressure"});
        if (sim && sim->fluid == SimDesc::Fluid::Liquid)
            keys.insert(keys.end(), {"sim.optics.index_a", "sim.optics.index_b"});
        if (volume) {
            addVolumeGrid(volume->indexGrid, "index", keys);
            addVolumeGrid(volume->deltaIndexGrid, "delta_index", keys);
            if (!volume->gasDensityGrid.empty()) keys.insert(keys.end(), {"volume.fields.density", "volume.gladstone_dale"});
            if (!volume->massFractions.empty()) keys.push_back("volume.fields.mass_fractions");
            if (!volume->pressureGrid.empty()) keys.push_back("volume.fields.pressure");
            keys.insert(keys.end(), {"volume.refractivity", "volume.pressure", "volume.reference_temperature"});
        }
        if (scene.airProfile) keys.push_back("medium.air_temperature_profile");
        keys.push_back("medium.index");
    } else if (field == "extinction") {
        addStrokes(scene, at, "extinction", [](const PaintStroke& s) { return s.extinction != Rgb(0.0); }, keys);
        if (sim) keys.push_back("sim.optics.dye_extinction");
        if (volume) {
            addVolumeGrid(volume->extinctionGrid, "extinction", keys);
            keys.insert(keys.end(), {"volume.density_extinction", "volume.flame_absorption"});
        }
        keys.push_back("medium.extinction");
    } else if (field == "scattering") {
        addStrokes(scene, at, "scattering", [](const PaintStroke& s) { return s.scattering != Rgb(0.0); }, keys);
        if (sim) keys.push_back("sim.optics.dye_scattering");
        if (volume) {
            addVolumeGrid(volume->scatteringGrid, "scattering", keys);
            keys.push_back("volume.density_scattering");
        }
        keys.push_back("medium.scattering");
    } else if (field == "anisotropy") {
        if (volume) {
            addVolumeGrid(volume->anisotropyGrid, "anisotropy", keys);
            keys.push_back("volume.anisotropy");
        }
        keys.push_back("medium.anisotropy");
    } else if (field == "emission") {
        if (volume) {
            addVolumeGrid(volume->emissionGrid, "emission", keys);
            keys.push_back("volume.emission_scale");
        }
    } else {
        keys.push_back("objects");  // the sharp surfaces: the meshes' vertices and their motion
    }
    return keys;
}

}  // namespace

FieldOrigin sceneFieldOrigin(const Scene& scene, const std::string& volumeFile) {
    return [&scene, volumeFile](std::string_view field, const glm::dvec3* at) {
        const std::vector<std::string> keys = keysOf(scene, field, at);
        std::string text = scene.sourcePath + ": ";
        for (std::size_t k = 0; k < keys.size() && k < kMostKeys; ++k) text += (k ? ", " : "") + keys[k];
        if (keys.size() > kMostKeys) text += " and " + std::to_string(keys.size() - kMostKeys) + " more";
        const bool namesVolume = std::any_of(keys.begin(), keys.end(), [](const std::string& key) {
            return key.rfind("volume.", 0) == 0;
        });
        if (namesVolume && !volumeFile.empty()) text += " with " + volumeFile;
        return text;
    };
}

}  // namespace eikon::sim
