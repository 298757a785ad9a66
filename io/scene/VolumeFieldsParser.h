// `volume.fields` and the keys that depend on the volume's reader
// (docs/scene-format.md, volume): what each array of the file means,
// declared, never guessed. Kept apart from ExportParser.cpp's readVolume,
// which calls these.
#pragma once

#include "io/scene/JsonReader.h"
#include "bridge/scene/VolumeDesc.h"

namespace eikon {

// `fields`: the file's array (or grid) names for temperature (with its
// temperature_unit), density (a gas density, kg/m³; with mass_fractions, a
// mixture's, each gas's Gladstone–Dale constant from bridge/scene/GasSpecies.h), pressure (Pa),
// index, delta_index, extinction and scattering. Replaces the grid names a
// preset or the defaults set: only the declared arrays are read.
void readVolumeFields(const JsonReader& node, VolumeDesc& volume);

// The rules between `fields`, `grids` and the reader, once `path` is read:
// VTK data need `fields` and take no `grids`, `preset`, '#' sequence or
// `frame_start` (a time series steps itself); `grids` and `fields` not both.
void checkVolumeReaderKeys(const JsonObjectReader& keys, const VolumeDesc& volume);

// Once every key is read: `temperature_scale` only for a temperature above
// ambient; `gladstone_dale` only with a density array.
void checkVolumeFieldKeys(const JsonObjectReader& keys, const VolumeDesc& volume);

}  // namespace eikon
