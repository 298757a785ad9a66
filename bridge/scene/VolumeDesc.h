// A volume imported into the scene (docs/scene-format.md, `volume`): one
// .vdb file, or a numbered sequence stepped one file per frame, or VTK data
// (.vti, .vtu, .vtk, a .pvd or .series time series, an OpenFOAM case), whose
// grids or arrays are sampled onto the render grid and mapped to optics
// (sim/optics): density → κ, σs; temperature (and flame), gas density or
// pressure → index by Gladstone–Dale; and optical grids (index, κ, σs, g)
// taken as they are.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace eikon {

using VolumeRgb = glm::dvec3;

struct VolumeDesc {
    // Which reader opens `path`: OpenVDB, or VTK's readers (io/vtk/VtkVolumeSource).
    enum class Format { OpenVdb, Vtk };
    Format format = Format::OpenVdb;
    // A file, or a sequence pattern whose single run of '#' stands for the
    // zero-padded frame number (Blender: fluid_data_####.vdb). Resolved
    // against the scene file's folder.
    std::string path;
    bool sequence = false;   // path holds a '#' run
    int frameStart = 1;      // sequence number of rendered frame 0, >= 0
    double frameTime = 1.0 / 24.0;  // s of the volume's time per rendered frame, > 0

    // Grid names in the file; empty: not read. Names may hold spaces.
    std::string densityGrid = "density";
    std::string temperatureGrid = "temperature";
    std::string flameGrid;      // Blender: "flame"
    std::string velocityGrid;   // Blender: "velocity", Houdini: "vel"
    // Optical grids designed in other tools (lenses, media), added to the
    // physical mapping: n (absolute) or δn = n − n_ref, not both; κ and σs
    // in 1/m (a float grid: grey; vec3s: RGB); Henyey–Greenstein g.
    std::string indexGrid;
    std::string deltaIndexGrid;
    std::string extinctionGrid;
    std::string scatteringGrid;
    std::string anisotropyGrid;
    std::string emissionGrid;  // ε in W/(m³·sr), grey or RGB, added to the blackbody term
    // Declared by volume.fields (docs/scene-format.md): a gas density in
    // kg/m³ (index by Gladstone–Dale's constant) and a pressure in Pa (with
    // the temperature, the ideal-gas density), per cell.
    std::string gasDensityGrid;
    std::string pressureGrid;
    // volume.fields.mass_fractions: the gas is a mixture, each named gas
    // (bridge/scene/GasSpecies.h) of the mass fraction in its array, the
    // rest (1 − ΣY) the gas of gladstoneDale; with gasDensityGrid only.
    struct MassFraction {
        std::string species;    // "CO2", …
        std::string grid;       // the array (or grid) of its mass fraction Y
        double gladstoneDale;   // the species' K, m³/kg
    };
    std::vector<MassFraction> massFractions;

    // The file's world into the scene's, affine: translate(offset) · up axis
    // (Z-up files turned to eikon's Y-up) · transform (translate · rotate ·
    // scale, or a matrix); built by the scene parser (volume.offset,
    // up_axis, transform). Velocities turn and scale with its linear part.
    glm::dmat4 placement{1.0};
    // volume.preset "blender": a Mantaflow cache's grids lie in the domain
    // object's frame, index (i,j,k) at (i,j,k)·dx with dx = the longest
    // dimension / the resolution, cell (i,j,k) covering [i, i+1]·(D/res) from
    // the domain's corner (Blender's fluid.c: cell_size = size / base_res).
    // Each file's placement is then placement · T(−D/2) · S(D / (res·dx)) ·
    // T(dx/2), res from the grids' file_base_resolution metadata
    // (io/vdb/VolumePlacement). D: the domain's dimensions (m), as
    // Blender's N panel shows them; the location and rotation are in placement.
    std::optional<glm::dvec3> blenderDomainDimensions;

    // What the temperature grid holds. KelvinAboveAmbient is Blender's and
    // Houdini's unitless heat (volume.grids, the default there); declared by
    // volume.fields.temperature_unit otherwise. implicitTemperatureUnit: the
    // default was taken, so a grid that looks absolute is refused.
    enum class TemperatureUnit { KelvinAboveAmbient, Kelvin, Celsius };
    TemperatureUnit temperatureUnit = TemperatureUnit::KelvinAboveAmbient;
    bool implicitTemperatureUnit = true;

    // Optics: κ = densityExtinction·ρ, σs = densityScattering·ρ per channel;
    // T = ambientTemperature + temperatureScale·t + flameTemperature·f (above
    // ambient; t in K or t + 273.15 for the absolute units), and
    // δn += n_gas − n_air(T_ambient): n_gas − 1 = gladstoneDale·ρ_gas, or
    // Gladstone–Dale of T at the cell's pressure (sim/optics/AirOptics.h).
    VolumeRgb densityExtinction{0.0};  // 1/m per unit density, >= 0
    VolumeRgb densityScattering{0.0};  // <= densityExtinction per channel
    double anisotropy = 0.0;           // HG g of the scattering, in (−1, 1)
    double ambientTemperature = 293.15;  // K, > 0
    double temperatureScale = 1.0;       // K per unit of the temperature grid, >= 0
    double flameTemperature = 0.0;       // K per unit of the flame grid, >= 0
    double refractivity = 2.93e-4;       // n0 − 1 of air at T0, p0, > 0
    double referenceTemperature = 273.15;  // T0, K, > 0
    double pressure = 101325.0;            // Pa, > 0 (p0 = 101325 Pa)
    // n − 1 per kg/m³ of the gas density grid; absent: air's, the
    // refractivity over the ideal-gas density of air at T0 and p0.
    std::optional<double> gladstoneDale;  // m³/kg, > 0

    // Emission, the L_e of [Ihrke07] §3, eqs. 1–2. Blackbody: each cell glows
    // by Kirchhoff's law, ε = emissionScale · κa · B(T) per channel, κa = κ − σs
    // its absorption and B(T) the Planck radiance in eikon's RGB
    // (sim/optics/Blackbody.h); flameAbsorption is the soot a flame adds to κ
    // (grey, 1/m per unit flame), so a fire both glows and darkens what is
    // behind it. emissionScale 1 is the physical glow.
    enum class Emission { None, Blackbody };
    Emission emission = Emission::None;
    double emissionScale = 1.0;     // >= 0
    double flameAbsorption = 0.0;   // 1/m per unit flame, >= 0
    // The emission also lights the scene: photons leave the glowing cells
    // (render/stages/VolumeGlow.h, a volume emitter).
    bool emissionLights = false;

    // Not a scene key: set by `eikon run --follow` and `eikon-view --follow`
    // (docs/scene-format.md, following a running case). A VTK time series or
    // OpenFOAM case is watched as a simulation writes it, and each new step
    // is rendered once it is complete (sim/volume/VolumeFollower.h).
    struct Follow {
        double pollSeconds = 0.25;    // between looks at the series or case, > 0
        double timeoutSeconds = 60.0; // following ends after this long without a new step, > 0
        std::string stopFile;         // following ends once this file exists (empty: none)
    };
    std::optional<Follow> follow;
};

}  // namespace eikon
