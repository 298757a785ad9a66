// The caller's fields of one frame (eikon::Field, include/eikon/eikon.h),
// checked against the scene's grid and viewed where they lie as a volume
// frame's samples (sim/optics/VolumeOptics.h), the form in which an
// OpenVDB file's grids reach the optics.
#pragma once

#include "eikon/eikon.h"

#include "apps/library/BufferField.h"
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
    // The fields handed as GL buffers (Field::buffer), in the caller's
    // order: not among `samples` (apps/library/GpuFieldPass.h takes them).
    std::vector<BufferField> buffers;
};

// Checks every field before any is taken: a known name given once, values,
// shape (nz, ny, nx) and channels, the grid box, finite values, a unit
// (a temperature's only: kelvin, celsius, kelvin_above_ambient), a GL
// buffer for a field the GPU path takes (BufferField.h: its values and size
// are the renderer's to check) with the fields it is mapped with on the GPU
// too. Throws eikon::Error naming the field, what was expected and what was
// found.
FieldIntake takeFields(const std::vector<Field>& fields, const GridSpec& grid);

}  // namespace eikon::library
