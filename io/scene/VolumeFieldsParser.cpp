#include "io/scene/VolumeFieldsParser.h"

#include "bridge/scene/GasSpecies.h"

#include <utility>

namespace eikon {

namespace {

// `fields.mass_fractions`: {GAS: ARRAY, …}, the gases of bridge/scene/GasSpecies.h.
void readMassFractions(const JsonReader& node, VolumeDesc& volume) {
    // The keys are GasSpecies' names; one missing here fails every read below.
    const auto keys = node.object({"air", "N2", "O2", "Ar", "CO2", "H2O", "H2", "He", "CH4", "CO"});
    if (volume.gasDensityGrid.empty())
        node.fail("no mass_fractions without a density array (n − 1 = ρ·Σ Y_i·K_i needs the mixture's "
                  "density: fields.density)",
                  "mass_fractions");
    for (const GasSpecies& gas : gasSpecies()) {
        const auto array = keys.optional(std::string(gas.name));
        if (!array) continue;
        const std::string name = array->string();
        if (name.empty()) array->fail("the name of the gas's mass fraction array (leave the gas out to read none)", "\"\"");
        volume.massFractions.push_back({std::string(gas.name), name, gas.gladstoneDale()});
    }
    if (volume.massFractions.empty())
        node.fail("at least one gas's mass fraction array (air, N2, O2, Ar, CO2, H2O, H2, He, CH4, CO)", "none");
}

}  // namespace

void readVolumeFields(const JsonReader& node, VolumeDesc& volume) {
    const auto keys = node.object({"temperature", "temperature_unit", "density", "pressure", "index", "delta_index",
                                   "extinction", "scattering", "mass_fractions"});
    for (std::string* grid : {&volume.densityGrid, &volume.temperatureGrid, &volume.flameGrid, &volume.velocityGrid})
        grid->clear();
    for (const auto& [key, name] :
         {std::pair{"temperature", &volume.temperatureGrid}, {"density", &volume.gasDensityGrid},
          {"pressure", &volume.pressureGrid}, {"index", &volume.indexGrid}, {"delta_index", &volume.deltaIndexGrid},
          {"extinction", &volume.extinctionGrid}, {"scattering", &volume.scatteringGrid}}) {
        const auto array = keys.optional(key);
        if (!array) continue;
        *name = array->string();
        if (name->empty()) array->fail("the name of an array in the file (leave the key out to read none)", "\"\"");
    }
    if (!volume.temperatureGrid.empty()) {
        const std::string unit = keys.member("temperature_unit").oneOf({"kelvin", "celsius", "kelvin_above_ambient"});
        volume.temperatureUnit = unit == "kelvin"    ? VolumeDesc::TemperatureUnit::Kelvin
                                 : unit == "celsius" ? VolumeDesc::TemperatureUnit::Celsius
                                                     : VolumeDesc::TemperatureUnit::KelvinAboveAmbient;
        volume.implicitTemperatureUnit = false;
    } else if (auto unit = keys.optional("temperature_unit")) {
        unit->fail("no temperature_unit without a temperature array", "\"" + unit->string() + "\"");
    }
    if (!volume.pressureGrid.empty() && volume.temperatureGrid.empty())
        keys.member("pressure").fail("a temperature array beside the pressure (the ideal-gas density needs both)",
                                     "no fields.temperature");
    if (!volume.pressureGrid.empty() && !volume.gasDensityGrid.empty())
        keys.member("pressure").fail("a pressure or a density, not both (each sets the gas's index)", "both");
    if (auto mixture = keys.optional("mass_fractions")) readMassFractions(*mixture, volume);
    if (!volume.indexGrid.empty() && !volume.deltaIndexGrid.empty())
        keys.member("delta_index").fail("an index or a delta_index array, not both (both would set the index)", "both");
    if (volume.temperatureGrid.empty() && volume.gasDensityGrid.empty() && volume.pressureGrid.empty() &&
        volume.indexGrid.empty() && volume.deltaIndexGrid.empty() && volume.extinctionGrid.empty() &&
        volume.scatteringGrid.empty())
        node.fail("at least one array named (temperature, density, pressure, index, delta_index, extinction, "
                  "scattering)",
                  "none");
}

void checkVolumeReaderKeys(const JsonObjectReader& keys, const VolumeDesc& volume) {
    const bool declared = keys.optional("fields").has_value();
    if (declared && keys.optional("grids"))
        keys.member("grids").fail("no `grids` beside `fields` (fields declares every array read)", "both");
    if (volume.format == VolumeDesc::Format::Vtk) {
        const JsonReader path = keys.member("path");
        if (!declared)
            keys.member("fields").fail(
                "an object declaring what the VTK file's arrays mean ({\"temperature\": NAME, \"temperature_unit\": "
                "…}, …): VTK data carry no convention to guess from");
        if (volume.sequence)
            path.fail("no '#' in a VTK path (a .pvd or .series file lists a time series)", "\"" + path.string() + "\"");
        for (const char* key : {"grids", "preset", "frame_start", "blender_domain"})
            if (auto value = keys.optional(key))
                value->fail(std::string("no `") + key + "` with VTK data (`fields` names their arrays; a time "
                            "series shows step k at rendered frame k)",
                            "a " + std::string(key));
    }
}

void checkVolumeFieldKeys(const JsonObjectReader& keys, const VolumeDesc& volume) {
    if (auto scale = keys.optional("temperature_scale"); scale && !volume.implicitTemperatureUnit &&
                                                         volume.temperatureUnit !=
                                                             VolumeDesc::TemperatureUnit::KelvinAboveAmbient)
        scale->fail("no temperature_scale with an absolute temperature_unit (it scales a temperature above ambient)",
                    "a temperature_scale");
    if (auto constant = keys.optional("gladstone_dale"); constant && volume.gasDensityGrid.empty())
        constant->fail("no gladstone_dale without a density array (fields.density)", "a gladstone_dale");
}

}  // namespace eikon
