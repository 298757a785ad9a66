// Optics of an imported volume (scene `volume`, VolumeDesc): its density,
// temperature and flame, sampled on the render grid, to δn, κ, σs and g.
//   κ = κ_medium + density_extinction · ρ,  σs = σs_medium + density_scattering · ρ
//   (Beer–Lambert coefficients linear in density; ρ < 0 from a solver's
//   undershoot is taken as 0), g the σs-weighted mean of the medium's and the volume's;
//   T = ambient_temperature + temperature_scale · t + flame_temperature · f
//   (t above ambient; an absolute temperature grid: t, or t + 273.15 in °C,
//   plus the flame term),
//   δn = (n_medium − n_ref) + [n_gas − n_air(T_ambient)]
//   with n_gas − 1 = K·ρ for a gas density grid (Gladstone–Dale, K in
//   m³/kg; a mixture of mass fractions Y_i: ρ·[Σ Y_i·K_i + (1 − Σ Y_i)·K],
//   bridge/scene/GasSpecies.h), else n_air(T) at the cell's pressure (a pressure grid, or
//   volume.pressure) by Gladstone–Dale (AirOptics.h): the volume perturbs
//   the medium by the index change its gas causes, so cold, empty regions
//   keep the medium's index. Cells the file's data do not cover (VTK data
//   resampled, VolumeSamples::covered) are the ambient medium.
// Optical grids made in other tools are taken as they are: an `index` grid
// (n) or a `delta_index` grid (n − n_ref) replaces the medium's index in
// the first term; `extinction` and `scattering` (1/m, grey or RGB) add to κ
// and σs; an `anisotropy` grid is the volume's g per cell.
// Emission ([Ihrke07] §3, L_e of eqs. 1–2), W/(m³·sr) per channel:
//   ε = emission_scale · (κ − σs) · B(T) + ε_grid   (emission "blackbody";
//   Kirchhoff's law: a cell emits as it absorbs, at its temperature), with
//   κ += flame_absorption · f, the soot of the flame; ε_grid an `emission`
//   grid (grey or RGB) as it is. Objects composited over the volume leave ε.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace eikon::sim {

// Grids of one volume frame on the render grid (one value per cell, x
// fastest), as views: of a file's samples (VolumeGrids below) or of a
// caller's own arrays (the library, include/eikon/eikon.h), read where they
// lie. A grid the scene does not read is empty.
struct VolumeSamples {
    std::span<const float> density;
    std::span<const float> temperature;
    std::span<const float> flame;
    std::span<const float> index;       // n
    std::span<const float> deltaIndex;  // n − n_ref
    std::span<const float> extinction;  // RGB per cell (a grey grid's value in each channel)
    std::span<const float> scattering;  // RGB per cell
    std::span<const float> anisotropy;
    std::span<const float> emission;    // RGB per cell, W/(m³·sr)
    std::span<const float> gasDensity;  // kg/m³
    std::span<const float> pressure;    // Pa
    // 1 where the file's data cover the cell; empty: every cell (OpenVDB
    // grids read their background outside their active voxels).
    std::span<const std::uint8_t> covered;
    // The mass fraction of each of VolumeDesc::massFractions' gases, one
    // grid after another (gas g's cell c at g·cells + c); empty: none.
    std::span<const float> massFractions;

    bool covers(std::size_t cell) const { return covered.empty() || covered[cell] != 0; }
};

// The grids of one volume frame held in memory (a file's samples), laid out
// as VolumeSamples views them.
struct VolumeGrids {
    std::vector<float> density, temperature, flame, index, deltaIndex, extinction, scattering, anisotropy, emission,
        gasDensity, pressure;
    std::vector<std::uint8_t> covered;
    std::vector<float> massFractions;

    VolumeSamples view() const {
        return {density,    temperature, flame,      index,    deltaIndex, extinction,   scattering,
                anisotropy, emission,    gasDensity, pressure, covered,    massFractions};
    }
};

// Temperature in K of a cell from the samples (ambient where absent or not covered).
double volumeTemperature(const VolumeDesc& volume, const VolumeSamples& samples, std::size_t cell);

// Where the samples came from, for a refusal: the scene file whose `volume`
// keys map them, and the OpenVDB or VTK file they were read from.
struct VolumeOrigin {
    std::string scene;
    std::string file;
};

// Fills fields.deltaIndex, .extinction, .scattering, .anisotropy, .emission
// (left empty where the scene makes them zero everywhere) on fields.grid, bumping the versions of what
// changed. InputError where a value is not finite or T <= 0, n <= 0, κ < 0,
// σs > κ, |g| >= 1 or ε < 0, naming the scene file and the `volume` keys it
// was computed from, the OpenVDB file and the world position; and where a
// temperature grid read as kelvin above ambient by default (Blender's
// convention, VolumeDesc::implicitTemperatureUnit) holds absolute
// temperatures: its smallest nonzero sample at least
// kAbsoluteTemperatureLooking K.
inline constexpr double kAbsoluteTemperatureLooking = 150.0;  // K

// The smallest nonzero temperature sample where the samples are read as
// kelvin above ambient by default and all their nonzero values are at least
// kAbsoluteTemperatureLooking (an absolute temperature, refused); none otherwise.
std::optional<float> absoluteLookingTemperature(const VolumeDesc& volume, const VolumeSamples& samples);

void writeVolumeOptics(const VolumeDesc& volume, const Material& medium, const VolumeSamples& samples,
                       const VolumeOrigin& origin, FieldSet& fields);

}  // namespace eikon::sim
