#include "bridge/scene/GasSpecies.h"

#include <array>

namespace eikon {

namespace {

constexpr double kGasConstant = 8.314462618;  // J/(mol·K), CODATA 2018 (exact)
constexpr double kT0 = 273.15;                // K
constexpr double kP0 = 101325.0;              // Pa

// n0 − 1 at 0 °C, 1 atm, 589 nm ([CRC], "Index of refraction of gases");
// air's is eikon's default volume.refractivity, so that "air" here is the
// air of the rest of the scene. Molar masses from the standard atomic weights.
constexpr std::array kSpecies{
    GasSpecies{"air", 2.93e-4, 28.9647e-3},  GasSpecies{"N2", 2.98e-4, 28.0134e-3},
    GasSpecies{"O2", 2.71e-4, 31.9988e-3},   GasSpecies{"Ar", 2.81e-4, 39.948e-3},
    GasSpecies{"CO2", 4.49e-4, 44.0095e-3},  GasSpecies{"H2O", 2.56e-4, 18.0153e-3},
    GasSpecies{"H2", 1.32e-4, 2.01588e-3},   GasSpecies{"He", 3.5e-5, 4.002602e-3},
    GasSpecies{"CH4", 4.44e-4, 16.0425e-3},  GasSpecies{"CO", 3.38e-4, 28.0101e-3},
};

}  // namespace

double GasSpecies::gladstoneDale() const { return refractivity * kGasConstant * kT0 / (kP0 * molarMass); }

std::span<const GasSpecies> gasSpecies() { return kSpecies; }

const GasSpecies* findGasSpecies(std::string_view name) {
    for (const GasSpecies& species : kSpecies)
        if (species.name == name) return &species;
    return nullptr;
}

}  // namespace eikon
