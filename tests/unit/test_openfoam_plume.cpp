// A plume OpenFOAM computed: tests/data/openfoam_plume_coarse, the heated
// plume of examples/openfoam/heated_plume.sh (buoyantPimpleFoam over a 600 K
// heater, a graded 20 × 10 × 20 mesh, written by
// tests/data/make_openfoam_plume_coarse.sh), T and p at 1 s and 2 s as the
// solver wrote them (gzip). Read through the scene's `volume`, its δn must
// be Gladstone–Dale of T and p as VTK's own reader and probe filter sample
// the case at the render cell centres, to 1e-6 of the plume's δn change, in
// both time steps — the acceptance of issue 55 on a real solver's output,
// whose cells the render grid's centres do not line up with.
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"
#include "sim/optics/AirOptics.h"
#include "tests/unit/OpenFoamProbe.h"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace eikon::sim {
namespace {

namespace fs = std::filesystem;

TEST(OpenFoamPlume, ImportsAsGladstoneDaleOfItsTemperatureAndPressure) {
    const fs::path foam = fs::path(EIKON_SOURCE_DIR) / "tests/data/openfoam_plume_coarse/case.foam";
    // The room, 1 m × 0.5 m × 1 m, on 2.5 cm render cells; the mesh is graded.
    nlohmann::json root = nlohmann::json::parse(R"({
        "grid": {"resolution": [40, 20, 40], "bounds": {"min": [0, 0, 0], "max": [1, 0.5, 1]}},
        "medium": {"index": 1.000273},
        "lights": [{"type": "point", "position": [0.5, 2, 0.5], "power": 1}]})");
    root["volume"] = {{"path", foam.string()},
                      {"ambient_temperature", 300.0},
                      {"pressure", 1e5},  // the room's, OpenFOAM's pRef
                      {"fields", {{"temperature", "T"}, {"temperature_unit", "kelvin"}, {"pressure", "p"}}}};
    const Scene s = parseScene(root, "openfoam_plume.json");
    SceneFields fields(s);
    const GridSpec spec = s.grid.spec();

    test::OpenFoamProbe probe(foam, spec);  // the independent sampling, as ParaView reads the case

    const GladstoneDale air;  // the volume's defaults
    const double ambient = air.refractivityAt(300.0, 1e5);
    for (int step = 0; step < 2; ++step) {
        SCOPED_TRACE("time " + std::to_string(step + 1) + " s");
        if (step > 0) fields.advanceFrame();
        const vtkSmartPointer<vtkDataSet> sampled = probe.at(step + 1.0);
        vtkDataArray* t = sampled->GetPointData()->GetArray("T");
        vtkDataArray* p = sampled->GetPointData()->GetArray("p");
        ASSERT_TRUE(t && p);
        const FieldSet& set = fields.fields();
        const double medium = s.medium.index - set.referenceIndex;
        double error = 0.0, signal = 0.0, hottest = 0.0;
        for (std::size_t c = 0; c < spec.cellCount(); ++c) {
            const double tc = t->GetComponent(static_cast<vtkIdType>(c), 0);
            const double pc = p->GetComponent(static_cast<vtkIdType>(c), 0);
            const double expected = medium + air.refractivityAt(tc, pc) - ambient;
            error = std::max(error, std::abs(set.deltaIndex[c] - expected));
            signal = std::max(signal, std::abs(expected - medium));
            hottest = std::max(hottest, tc);
        }
        EXPECT_GT(hottest, 330.0);  // the plume is in the samples: 30 K and more over the 300 K room
        EXPECT_GT(signal, 3e-5);
        EXPECT_LT(error / signal, 1e-6);
        std::printf("[ measured ] OpenFOAM plume at %d s: hottest sample %.1f K, largest |δn error| / largest δn "
                    "change = %.3g\n",
                    step + 1, hottest, error / signal);
    }
}

}  // namespace
}  // namespace eikon::sim
