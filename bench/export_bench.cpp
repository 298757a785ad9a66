// Milliseconds and megabytes per exported 128³ frame: VTK ImageData with
// zlib (level 1), LZ4 and no compression, and OpenVDB, all in one run on the
// same frame. The frame is real data, not noise: the heat-shimmer plume
// (scenes/hot_plate_plume.json, 48³ solver) advanced 12 frames and mapped onto
// a 128³ render grid, with the default field set of such a scene — index,
// delta_index, velocity (3), temperature, concentration, dye: 8 floats per
// cell, 67 MB raw. Each iteration writes one frame file (temporary, fsync,
// rename); the counters give the file size. Not run by ctest.
#include "io/vdb/VdbFrameWriter.h"
#include "io/vtk/VtkSeriesWriter.h"
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

namespace {

namespace fs = std::filesystem;
using namespace eikon;

const ExportFrame& plumeFrame() {
    static const ExportFrame frame = [] {
        const Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/hot_plate_plume.json",
                                          {"grid.resolution=[128,128,128]"});
        sim::SceneFields fields(scene);
        for (int f = 0; f < 12; ++f) fields.advanceFrame();
        ExportFrame result{fields.fields().grid, io::fieldArrays(viewsOf(fields.fields()))};
        for (auto& array : fields.exportArrays()) result.arrays.push_back(std::move(array));
        return result;
    }();
    return frame;
}

fs::path benchFolder() {
    const fs::path folder = fs::temp_directory_path() / "eikon_export_bench";
    fs::remove_all(folder);
    return folder;
}

void reportSize(benchmark::State& state, const fs::path& file) {
    state.counters["MB"] = static_cast<double>(fs::file_size(file)) / 1e6;
    state.counters["raw_MB"] = 0.0;
    for (const auto& array : plumeFrame().arrays)
        state.counters["raw_MB"] += static_cast<double>(array.values.size() * sizeof(float)) / 1e6;
}

void BM_VtkFrame(benchmark::State& state) {
    const auto compression = static_cast<io::VtkSeriesWriter::Compression>(state.range(0));
    const ExportFrame& frame = plumeFrame();
    const fs::path folder = benchFolder();
    io::VtkSeriesWriter writer(folder, "fields", compression);
    int n = 0;
    for (auto _ : state) {
        writer.writeFrame(n, 0.04 * n, frame);
        ++n;
    }
    reportSize(state, writer.framePath(0));
    state.SetLabel(compression == io::VtkSeriesWriter::Compression::Zlib  ? "zlib"
                   : compression == io::VtkSeriesWriter::Compression::Lz4 ? "lz4"
                                                                          : "none");
    fs::remove_all(folder);
}

void BM_VdbFrame(benchmark::State& state) {
    const ExportFrame& frame = plumeFrame();
    const fs::path folder = benchFolder();
    io::VdbFrameWriter writer(folder, "fields");
    int n = 0;
    for (auto _ : state) {
        writer.writeFrame(n, 0.04 * n, frame);
        ++n;
    }
    reportSize(state, writer.framePath(0));
    fs::remove_all(folder);
}

BENCHMARK(BM_VtkFrame)
    ->Arg(static_cast<int>(io::VtkSeriesWriter::Compression::Zlib))
    ->Arg(static_cast<int>(io::VtkSeriesWriter::Compression::Lz4))
    ->Arg(static_cast<int>(io::VtkSeriesWriter::Compression::None))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);
BENCHMARK(BM_VdbFrame)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
