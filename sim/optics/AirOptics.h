// Refractive index of air from temperature and pressure by the Gladstone–Dale
// relation, n − 1 = K·ρ, with ρ from the ideal gas law:
//   n − 1 = (n0 − 1) · (p / p0) · (T0 / T).
// Reference state (SimDesc defaults): n0 − 1 = 2.93e-4 for dry air at
// T0 = 273.15 K and p0 = 101325 Pa in visible light (≈ 2.926e-4 at 589 nm,
// [Ciddor96] eqs. 1–2 evaluated at 0 °C). The pressure is the ambient one:
// the dynamic pressure of the flow is far too small (≈ ρu²/2 ≈ 0.1 Pa) to
// matter beside the temperature term.
#pragma once

namespace eikon::sim {

// R/M of dry air, J/(kg·K) (M = 28.9647 g/mol, R = 8.314462 J/(mol·K)).
inline constexpr double kAirSpecificGasConstant = 287.05;

struct GladstoneDale {
    double refractivity = 2.93e-4;          // n0 − 1
    double referenceTemperature = 273.15;   // T0, K
    double referencePressure = 101325.0;    // p0, Pa

    // n − 1 at temperature T (K) and pressure p (Pa).
    double refractivityAt(double temperature, double pressure) const {
        return refractivity * (pressure / referencePressure) * (referenceTemperature / temperature);
    }
    // Gladstone–Dale's K = (n0 − 1)/ρ0 in m³/kg, ρ0 = p0/(R_air·T0) air's
    // ideal-gas density at the reference state: 2.267e-4 by default.
    double airConstant() const {
        return refractivity * kAirSpecificGasConstant * referenceTemperature / referencePressure;
    }
};

}  // namespace eikon::sim
