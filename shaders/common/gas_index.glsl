// The index an imported volume's (or a library caller's) cell gets from its
// temperature (sim/optics/VolumeOptics.h): the temperature in kelvin by its
// declared unit, and air's n − 1 at it by Gladstone–Dale with the ideal gas
// law, n − 1 = (n0 − 1)·(p/p0)·(T0/T) [Merzkirch87] (sim/optics/AirOptics.h).
// Shared by GLSL and C++: VolumeOptics.cpp maps host arrays through it, and
// shaders/caller_index.comp a caller's GL buffers, so that both paths form
// the same float64 and round the same δn to float32. Float64 throughout, no
// literals (GLSL spells a double's with `lf`): the constants come as arguments.

// volume.fields.temperature_unit (VolumeDesc::TemperatureUnit's order).
const uint kKelvinAboveAmbient = 0u;
const uint kKelvin = 1u;
const uint kCelsius = 2u;

// A temperature sample t in K: T = T_ambient + scale·t above ambient, t in
// kelvin, t + 273.15 K (`zero_celsius`) in celsius.
double sample_temperature(uint unit, double t, double ambient, double scale, double zero_celsius) {
    if (unit == kKelvin) return t;
    if (unit == kCelsius) return t + zero_celsius;
    precise double above = scale * t;
    precise double temperature = ambient + above;
    return temperature;
}

// Air's n − 1 at temperature T (K) and pressure p (Pa), from n0 − 1 at T0, p0.
double gas_refractivity(double refractivity, double reference_temperature, double reference_pressure,
                        double temperature, double pressure) {
    precise double r = refractivity * (pressure / reference_pressure) * (reference_temperature / temperature);
    return r;
}
