// Milliseconds to import one step of VTK volume data and resample it onto
// the render grid (io/vtk/VtkVolumeSource: VTK's reader, then vtkProbeFilter
// at every render cell centre), as `volume` with a VTK path does per frame:
//   ImageData64    a 64³ .vti plume (one float32 point array, temperature in
//                  K, appended raw, VTK's default zlib compression) onto a
//                  64³ render grid whose cell centres are its points;
//   OpenFoamTiny   tests/data/openfoam_tiny (12 hexahedra, T and p) onto a
//                  6×4×4 grid: the fixed cost of vtkOpenFOAMReader's step;
//   OpenFoamPlumeCoarse  tests/data/openfoam_plume_coarse (4 000 cells of a
//                  plume OpenFOAM computed, T and p gzipped) onto the 80×40×80
//                  grid of scenes/openfoam_plume.json;
//   OpenFoamPlume  that scene's case (32 000 cells), where
//                  examples/openfoam/heated_plume.sh wrote it to
//                  out/openfoam_plume under the source folder; skipped if not.
// Each iteration reads the file anew (from the page cache). Not run by ctest.
#include "io/vtk/VtkVolumeSource.h"

#include <benchmark/benchmark.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <filesystem>

namespace {

namespace fs = std::filesystem;
using eikon::GridSpec;
using eikon::io::VtkVolumeSource;

constexpr int kN = 64;

const fs::path& plumeFile() {
    static const fs::path path = [] {
        vtkNew<vtkImageData> image;
        image->SetDimensions(kN, kN, kN);
        image->SetSpacing(1.0 / kN, 1.0 / kN, 1.0 / kN);
        image->SetOrigin(0.5 / kN, 0.5 / kN, 0.5 / kN);
        vtkNew<vtkFloatArray> t;
        t->SetName("T");
        for (int k = 0; k < kN; ++k)
            for (int j = 0; j < kN; ++j)
                for (int i = 0; i < kN; ++i) {
                    const double x = (i + 0.5) / kN - 0.5, z = (k + 0.5) / kN - 0.5;
                    t->InsertNextValue(static_cast<float>(293.15 + 450.0 * std::exp(-(x * x + z * z) / 0.02)));
                }
        image->GetPointData()->AddArray(t);
        const fs::path file = fs::temp_directory_path() / "eikon_vtk_volume_bench.vti";
        vtkNew<vtkXMLImageDataWriter> writer;
        writer->SetFileName(file.c_str());
        writer->SetInputData(image);
        writer->Write();
        return file;
    }();
    return path;
}

void BM_ImageData64(benchmark::State& state) {
    const GridSpec grid{glm::ivec3(kN), glm::dvec3(0.0), glm::dvec3(1.0)};
    for (auto _ : state)
        benchmark::DoNotOptimize(VtkVolumeSource(plumeFile()).resample(0, {{"T", "T"}}, grid, glm::dmat4(1.0)));
    state.counters["file_MB"] = static_cast<double>(fs::file_size(plumeFile())) / 1e6;
}
BENCHMARK(BM_ImageData64)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_OpenFoamTiny(benchmark::State& state) {
    const fs::path foam = fs::path(EIKON_SOURCE_DIR) / "tests/data/openfoam_tiny/case.foam";
    const GridSpec grid{glm::ivec3(6, 4, 4), glm::dvec3(0.0), glm::dvec3(0.3, 0.2, 0.2)};
    for (auto _ : state)
        benchmark::DoNotOptimize(VtkVolumeSource(foam).resample(1, {{"T", "T"}, {"p", "p"}}, grid, glm::dmat4(1.0)));
}
BENCHMARK(BM_OpenFoamTiny)->Unit(benchmark::kMillisecond)->UseRealTime();

// One step (the last) of an OpenFOAM case onto scenes/openfoam_plume.json's grid.
void resampleFoamStep(benchmark::State& state, const fs::path& foam) {
    if (!fs::exists(foam)) {
        state.SkipWithError(("no " + foam.string() + ": run examples/openfoam/heated_plume.sh first").c_str());
        return;
    }
    const GridSpec grid{glm::ivec3(80, 40, 80), glm::dvec3(0.0), glm::dvec3(1.0, 0.5, 1.0)};
    for (auto _ : state) {
        const VtkVolumeSource source(foam);
        benchmark::DoNotOptimize(source.resample(source.stepCount() - 1, {{"T", "T"}, {"p", "p"}}, grid, glm::dmat4(1.0)));
    }
}
void BM_OpenFoamPlumeCoarse(benchmark::State& state) {
    resampleFoamStep(state, fs::path(EIKON_SOURCE_DIR) / "tests/data/openfoam_plume_coarse/case.foam");
}
BENCHMARK(BM_OpenFoamPlumeCoarse)->Unit(benchmark::kMillisecond)->UseRealTime();
void BM_OpenFoamPlume(benchmark::State& state) {
    resampleFoamStep(state, fs::path(EIKON_SOURCE_DIR) / "out/openfoam_plume/case.foam");
}
BENCHMARK(BM_OpenFoamPlume)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
