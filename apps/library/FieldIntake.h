// The caller's fields of one frame (eikon::Field, include/eikon/eikon.h),
// checked against the scene's grid and viewed where they lie as a volume
// frame's samples (sim/optics/VolumeOptics.h), the form in which an
// OpenVDB file's grids reach the optics.
#pragma once

#include "eikon/eikon.h"

#include "bridge/grid/GridSpec.h"
#include "sim/optics/VolumeOptics.h"

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace eikon::library {

struct FieldIntake {
    sim::VolumeSamples samples;  // views of the caller's arrays, or of `expanded`
    // RGB fields given grey: their value copied into three channels (the
    // only copy a frame makes of the caller's fields).
    std::deque<std::vector<float>> expanded;
    std::uint64_t copiedBytes = 0;
    std::vector<std::string> names;  // the fields taken, in the caller's order
    // The temperature's declared unit (Field::unit); none: as the scene's volume reads it.
    std::optional<VolumeDesc::TemperatureUnit> temperatureUnit;
    // delta_index handed as a GL buffer (Field::buffer), 0 for none: not among `samples`.
    unsigned deltaIndexBuffer = 0;
};

// Checks every field before any is taken: a known name given once, values,
// shape (nz, ny, nx) and channels, the grid box, finite values, a unit
// (a temperature's only: kelvin, celsius, kelvin_above_ambient), a GL
// buffer (delta_index's only; its size is the renderer's to check). Throws
// eikon::Error naming the field, what was expected and what was found.
FieldIntake takeFields(const std::vector<Field>& fields, const GridSpec& grid);

}  // namespace eikon::library
