#include "apps/library/FieldIntake.h"

#include "bridge/core/NumberFormat.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

namespace eikon::library {

namespace {

// The fields a caller may hand, the samples each becomes, and whether it
// is RGB (one or three channels) or a scalar.
struct FieldSlot {
    const char* name;
    std::span<const float> sim::VolumeSamples::*samples;
    bool rgb;
};
constexpr FieldSlot kSlots[] = {
    {"delta_index", &sim::VolumeSamples::deltaIndex, false},
    {"index", &sim::VolumeSamples::index, false},
    {"temperature", &sim::VolumeSamples::temperature, false},
    {"density", &sim::VolumeSamples::density, false},
    {"flame", &sim::VolumeSamples::flame, false},
    {"extinction", &sim::VolumeSamples::extinction, true},
    {"scattering", &sim::VolumeSamples::scattering, true},
    {"anisotropy", &sim::VolumeSamples::anisotropy, false},
    {"emission", &sim::VolumeSamples::emission, true},
};

std::string knownNames() {
    std::string names;
    for (const FieldSlot& slot : kSlots) names += std::string(names.empty() ? "" : ", ") + slot.name;
    return names;
}

[[noreturn]] void refuse(const std::string& field, const std::string& expected, const std::string& found) {
    throw Error("eikon::Renderer::setFields: field \"" + field + "\": expected " + expected + ", found " + found);
}

std::string triple(std::size_t a, std::size_t b, std::size_t c) {
    return "(" + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + ")";
}

std::string box(const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    return "[" + formatPosition({lo[0], lo[1], lo[2]}) + ", " + formatPosition({hi[0], hi[1], hi[2]}) + "] m";
}

// The grid box within a millionth of a voxel: the same placement, whatever
// rounding the caller's arithmetic made of the scene's numbers.
bool sameBox(const Field& field, const GridSpec& grid) {
    const glm::dvec3 tolerance = 1e-6 * grid.voxelSize();
    for (int a = 0; a < 3; ++a)
        if (std::abs(field.boundsMin[a] - grid.boundsMin[a]) > tolerance[a] ||
            std::abs(field.boundsMax[a] - grid.boundsMax[a]) > tolerance[a])
            return false;
    return true;
}

// Whether a block of values holds a NaN or an infinity: an IEEE 754 float
// is neither where its exponent bits are not all ones. Branch-free, so that
// the compiler vectorizes it; the search for the cell runs only on a find.
bool anyNotFinite(const float* values, std::size_t count) {
    constexpr std::uint32_t kExponent = 0x7f800000u;
    std::uint32_t found = 0;
    for (std::size_t i = 0; i < count; ++i)
        found |= static_cast<std::uint32_t>((std::bit_cast<std::uint32_t>(values[i]) & kExponent) == kExponent);
    return found != 0;
}

void checkFinite(const Field& field, const GridSpec& grid, std::size_t count) {
    if (!anyNotFinite(field.values, count)) return;
    const float* end = field.values + count;
    const float* bad = std::find_if(field.values, end, [](float v) { return !std::isfinite(v); });
    const auto at = static_cast<std::size_t>(bad - field.values);
    const std::size_t cell = at / static_cast<std::size_t>(field.channels);
    const auto nx = static_cast<std::size_t>(grid.resolution.x), ny = static_cast<std::size_t>(grid.resolution.y);
    const int i = static_cast<int>(cell % nx), j = static_cast<int>(cell / nx % ny),
              k = static_cast<int>(cell / (nx * ny));
    refuse(field.name, "finite values",
           std::string(std::isnan(*bad) ? "NaN" : "an infinity") + " at cell (i, j, k) = " +
               triple(static_cast<std::size_t>(i), static_cast<std::size_t>(j), static_cast<std::size_t>(k)) + ", " +
               formatPosition(grid.cellCentre(i, j, k)) + " m");
}

template <std::size_t N>
bool isOneOf(const std::string& name, const char* const (&names)[N]) {
    return std::find_if(std::begin(names), std::end(names), [&](const char* n) { return name == n; }) !=
           std::end(names);
}

std::string bufferFieldNames() {
    std::string names;
    for (const char* name : kIndexBufferFields) names += std::string(names.empty() ? "" : ", ") + name;
    for (const char* name : kCoefficientBufferFields) names += std::string(", ") + name;
    return names;
}

// Fields mapped together are taken on one side: the index's inputs
// (temperature, index, δn; a flame heats the gas) all in GL buffers or all
// in host memory, and likewise κ's and σs's (density, extinction,
// scattering; a flame adds soot on the host), scattering beside extinction
// or a density (σs ≤ κ is checked where both lie) and without an
// anisotropy (g is weighted by σs).
void refuseSplitMappings(const std::vector<Field>& fields) {
    const Field* indexBuffer = nullptr;
    const Field* indexHost = nullptr;
    const Field* coefficientBuffer = nullptr;
    const Field* coefficientHost = nullptr;
    const Field* flame = nullptr;
    const Field* scattering = nullptr;
    const Field* anisotropy = nullptr;
    bool extinctionBuffer = false;
    for (const Field& field : fields) {
        if (isOneOf(field.name, kIndexBufferFields)) (field.buffer ? indexBuffer : indexHost) = &field;
        if (isOneOf(field.name, kCoefficientBufferFields)) (field.buffer ? coefficientBuffer : coefficientHost) = &field;
        if (field.buffer && (field.name == "extinction" || field.name == "density")) extinctionBuffer = true;
        if (field.name == "scattering") scattering = &field;
        if (field.name == "anisotropy") anisotropy = &field;
        if (field.name == "flame") flame = &field;
    }
    if (indexBuffer && indexHost)
        refuse(indexHost->name,
               "a GL buffer as \"" + indexBuffer->name + "\" is (the index's fields are mapped together, on one side)",
               "values in host memory");
    if (indexBuffer && flame)
        refuse(indexBuffer->name, "values in host memory beside a flame (which heats the gas, on the host)",
               "GL buffer " + std::to_string(indexBuffer->buffer));
    if (coefficientBuffer && coefficientHost)
        refuse(coefficientHost->name,
               "a GL buffer as \"" + coefficientBuffer->name +
                   "\" is (density, extinction and scattering are mapped together, on one side)",
               "values in host memory");
    if (coefficientBuffer && flame)
        refuse(coefficientBuffer->name,
               "values in host memory beside \"flame\" (which adds to extinction on the host)",
               "GL buffer " + std::to_string(coefficientBuffer->buffer));
    if (scattering && scattering->buffer && !extinctionBuffer)
        refuse("scattering",
               "an extinction or density GL buffer beside a scattering one (σs ≤ κ is checked where both lie)",
               "none");
    if (coefficientBuffer && anisotropy)
        refuse(coefficientBuffer->name, "values in host memory beside an anisotropy (g is σs-weighted on the host)",
               "GL buffer " + std::to_string(coefficientBuffer->buffer));
}

// A temperature's unit, as volume.fields.temperature_unit names it.
VolumeDesc::TemperatureUnit temperatureUnit(const std::string& unit) {
    if (unit == "kelvin") return VolumeDesc::TemperatureUnit::Kelvin;
    if (unit == "celsius") return VolumeDesc::TemperatureUnit::Celsius;
    if (unit == "kelvin_above_ambient") return VolumeDesc::TemperatureUnit::KelvinAboveAmbient;
    refuse("temperature", "the unit \"kelvin\", \"celsius\" or \"kelvin_above_ambient\"", "\"" + unit + "\"");
}

}  // namespace

FieldIntake takeFields(const std::vector<Field>& fields, const GridSpec& grid) {
    const auto nx = static_cast<std::size_t>(grid.resolution.x), ny = static_cast<std::size_t>(grid.resolution.y),
               nz = static_cast<std::size_t>(grid.resolution.z);
    const std::size_t cells = grid.cellCount();
    FieldIntake intake;
    for (const Field& field : fields) {
        const FieldSlot* slot = std::find_if(std::begin(kSlots), std::end(kSlots),
                                             [&](const FieldSlot& s) { return field.name == s.name; });
        if (slot == std::end(kSlots)) refuse(field.name, "one of " + knownNames(), "an unknown name");
        if (std::find(intake.names.begin(), intake.names.end(), field.name) != intake.names.end())
            refuse(field.name, "each field named once", "it twice");
        if (field.buffer && !isOneOf(field.name, kIndexBufferFields) && !isOneOf(field.name, kCoefficientBufferFields))
            refuse(field.name, "values in host memory (a GL buffer is taken for " + bufferFieldNames() +
                                   "; the others are mapped with the scene's medium on the host)",
                   "GL buffer " + std::to_string(field.buffer));
        if (field.buffer && field.values)
            refuse(field.name, "values or a GL buffer, not both", "both");
        if (!field.values && !field.buffer) refuse(field.name, "values", "a null pointer");
        if (field.shape != std::array<std::size_t, 3>{nz, ny, nx})
            refuse(field.name, "shape (nz, ny, nx) = " + triple(nz, ny, nx) + ", the scene's grid",
                   triple(field.shape[0], field.shape[1], field.shape[2]));
        if (field.channels != 1 && !(slot->rgb && field.channels == 3))
            refuse(field.name, slot->rgb ? "1 (grey) or 3 (RGB) channels" : "1 channel",
                   std::to_string(field.channels));
        if (!sameBox(field, grid))
            refuse(field.name, "the scene's grid box " + box({grid.boundsMin.x, grid.boundsMin.y, grid.boundsMin.z},
                                                              {grid.boundsMax.x, grid.boundsMax.y, grid.boundsMax.z}),
                   box(field.boundsMin, field.boundsMax));
        if (!field.unit.empty() && field.name != "temperature")
            refuse(field.name, "no unit (a temperature's only: its unit is declared)", "\"" + field.unit + "\"");
        if (!field.unit.empty()) intake.temperatureUnit = temperatureUnit(field.unit);
        if (field.values) checkFinite(field, grid, cells * static_cast<std::size_t>(field.channels));
        intake.names.push_back(field.name);
    }
    if (std::find(intake.names.begin(), intake.names.end(), "index") != intake.names.end() &&
        std::find(intake.names.begin(), intake.names.end(), "delta_index") != intake.names.end())
        refuse("index", "index or delta_index, not both (each sets the index)", "both");
    refuseSplitMappings(fields);
    // Every field passed: take them.
    for (const Field& field : fields) {
        const FieldSlot& slot = *std::find_if(std::begin(kSlots), std::end(kSlots),
                                              [&](const FieldSlot& s) { return field.name == s.name; });
        if (field.buffer) {  // read on the GPU, by the renderer
            intake.buffers.push_back({field.name, field.buffer, field.channels});
            continue;
        }
        std::span<const float> values(field.values, cells * static_cast<std::size_t>(field.channels));
        if (slot.rgb && field.channels == 1) {  // grey: the same value in each channel, as a grey grid of a file
            std::vector<float>& channels = intake.expanded.emplace_back(3 * cells);
            for (std::size_t c = 0; c < cells; ++c)
                channels[3 * c] = channels[3 * c + 1] = channels[3 * c + 2] = values[c];
            intake.copiedBytes += channels.size() * sizeof(float);
            values = channels;
        }
        intake.samples.*slot.samples = values;
    }
    return intake;
}

}  // namespace eikon::library
