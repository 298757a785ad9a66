// Optical mapping against tabulated values.
#include "sim/optics/AirOptics.h"
#include "sim/optics/LiquidOptics.h"
#include "sim/optics/OpticalMapping.h"

#include <gtest/gtest.h>

namespace eikon::sim {
namespace {

// Air at 1 atm: n − 1 ≈ 2.78e-4 at 15 °C and ≈ 2.40e-4 at 60 °C in the
// visible (Gladstone–Dale from 2.93e-4 at 0 °C; the 15 °C value agrees with
// [Ciddor96] for standard air near 550 nm, 2.77e-4 to 2.78e-4). Tolerance 0.5%.
TEST(Optics, AirIndexByGladstoneDale) {
    const GladstoneDale air;
    EXPECT_NEAR(air.refractivityAt(288.15, 101325.0), 2.78e-4, 0.005 * 2.78e-4);
    EXPECT_NEAR(air.refractivityAt(333.15, 101325.0), 2.40e-4, 0.005 * 2.40e-4);
    EXPECT_DOUBLE_EQ(air.refractivityAt(273.15, 101325.0), 2.93e-4);
    EXPECT_NEAR(air.refractivityAt(273.15, 2 * 101325.0), 2 * 2.93e-4, 1e-18);  // n − 1 ∝ density ∝ p
    SimDesc desc;
    desc.ambientPressure = 101325.0;
    EXPECT_NEAR(OpticalModel(desc).index(288.15, 0.0), 1.000278, 2e-6);
}

// Sucrose solutions at 20 °C ([ICUMSA] / [CRC] tables): index and
// density of 20%, 40% and 60% w/w. With water (1.3330, 998.2 kg/m³) as
// liquid A and 60% syrup (1.4418, 1286.5 kg/m³) as liquid B, a w% solution is
// the volume fraction φ = (w·ρ_w) / (60·ρ_60) of syrup (sucrose per volume
// over that of the syrup). The linear rule in φ matches within 5e-4;
// Lorentz–Lorenz within 2e-3.
TEST(Optics, SucroseSolutionsByMixingWaterAndSyrup) {
    const double water = 1.3330, syrup = 1.4418, syrupDensity = 1286.5;
    EXPECT_DOUBLE_EQ(mixedIndex(water, syrup, 0.0, SimDesc::Mixing::Linear), 1.333);
    EXPECT_DOUBLE_EQ(mixedIndex(water, syrup, 1.0, SimDesc::Mixing::Linear), 1.4418);
    struct Row {
        double percent, density, index;
    };
    for (const Row row : {Row{20.0, 1081.0, 1.3638}, Row{40.0, 1176.4, 1.3997}}) {
        const double phi = (row.percent * row.density) / (60.0 * syrupDensity);
        EXPECT_NEAR(mixedIndex(water, syrup, phi, SimDesc::Mixing::Linear), row.index, 5e-4) << row.percent << "%";
        EXPECT_NEAR(mixedIndex(water, syrup, phi, SimDesc::Mixing::LorentzLorenz), row.index, 2e-3)
            << row.percent << "%";
    }
}

// Lorentz–Lorenz: R = (n² − 1)/(n² + 2) mixes linearly. By hand: water
// R = 0.776889/3.776889 = 0.205695; n = 1.5 gives R = 1.25/4.25 = 0.294118;
// half and half R = 0.249907, n² = (1 + 2R)/(1 − R) = 1.999501, n = 1.414037.
TEST(Optics, LorentzLorenzMixing) {
    EXPECT_NEAR(lorentzLorenzRefraction(1.333), 0.776889 / 3.776889, 1e-9);
    EXPECT_NEAR(indexFromLorentzLorenz(lorentzLorenzRefraction(1.47)), 1.47, 1e-12);
    EXPECT_NEAR(mixedIndex(1.333, 1.5, 0.5, SimDesc::Mixing::LorentzLorenz), 1.414037, 1e-6);
    EXPECT_DOUBLE_EQ(mixedIndex(1.333, 1.5, 1.7, SimDesc::Mixing::Linear), 1.5);  // clamped to [0, 1]
}

// Liquids: the index follows concentration, not temperature; dye gives κ and σs per unit.
TEST(Optics, LiquidAndDyeModel) {
    SimDesc desc;
    desc.fluid = SimDesc::Fluid::Liquid;
    desc.dyeExtinction = Rgb(4.0, 2.0, 1.0);
    desc.dyeScattering = Rgb(1.0, 1.0, 0.5);
    const OpticalModel model(desc);
    EXPECT_DOUBLE_EQ(model.index(280.0, 0.0), 1.333);
    EXPECT_DOUBLE_EQ(model.index(350.0, 0.0), 1.333);
    EXPECT_NEAR(model.index(293.15, 0.5), 0.5 * (1.333 + 1.4418), 1e-15);
    EXPECT_EQ(model.extinction(0.5), Rgb(2.0, 1.0, 0.5));
    EXPECT_EQ(model.scattering(2.0), Rgb(2.0, 2.0, 1.0));
    EXPECT_TRUE(model.absorbs());
    EXPECT_TRUE(model.scatters());
}

}  // namespace
}  // namespace eikon::sim
