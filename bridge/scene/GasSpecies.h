// Gladstone–Dale constants of the gases a mixture's mass fractions name
// (scene volume.fields.mass_fractions, docs/scene-format.md).
// Each gas's refractivity n0 − 1 at T0 = 273.15 K, p0 = 101 325 Pa and the
// sodium D line (589 nm), as handbooks tabulate it ([CRC] "Index of
// refraction of gases"), and its molar mass M give its constant through the
// ideal-gas density at that state, ρ0 = p0·M/(R·T0):
//   K = (n0 − 1)/ρ0 = (n0 − 1)·R·T0/(p0·M)   (m³/kg),
// and a mixture of mass fractions Y_i at density ρ has
//   n − 1 = Σ ρ_i·K_i = ρ·Σ Y_i·K_i   ([Merzkirch87] ch. 3: the
// refractivities of the components add by their partial densities).
#pragma once

#include <span>
#include <string_view>

namespace eikon {

struct GasSpecies {
    std::string_view name;   // as volume.fields.mass_fractions names it: "CO2", "H2O", …
    double refractivity;     // n0 − 1 at 273.15 K, 101 325 Pa, 589 nm
    double molarMass;        // kg/mol

    // Gladstone–Dale's K, m³/kg.
    double gladstoneDale() const;
};

// Every gas a mixture may name, in the order the documentation lists them.
std::span<const GasSpecies> gasSpecies();

// The gas called `name` (exact, case-sensitive, as chemists write it), or null.
const GasSpecies* findGasSpecies(std::string_view name);

}  // namespace eikon
