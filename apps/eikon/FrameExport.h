// Per-frame export of a run for analysis, as the scene's `export` section
// asks: the arrays of a frame (optical fields, fluence and mean photon
// direction, the simulation's or volume's own fields) are gathered once,
// then each enabled writer takes its selection of fields and cells. A
// diagnostic's measurements go whole into a series of their own
// (DiagnosticExport.h) on the frames the VTK export writes.
#pragma once

#include "bridge/grid/FieldViews.h"
#include "io/export/ExportArrays.h"
#include "io/vdb/VdbFrameWriter.h"
#include "io/vtk/ParaViewState.h"
#include "io/vtk/PolyDataWriter.h"
#include "io/vtk/VtkSeriesWriter.h"
#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"

#include <filesystem>
#include <map>
#include <optional>
#include <vector>

namespace eikon::app {

// What a frame exports besides the renderer's own: its time, its optical
// fields (host memory or the GPU ring's current slot) and the simulation's
// or volume's own fields (SceneFields::exportArrays, taken with the frame).
struct ExportInputs {
    double time = 0.0;
    ConstFieldViews fields;
    std::vector<NamedArray> simulation;
    std::vector<TriangleMesh> meshes;  // this frame's mesh and water objects (SceneFields::deformedMeshes)
};

// The arrays a frame offers: fieldArrays, fluence and photon_direction when
// the photon stage stores them, and the simulation's.
// `outsideDeltaIndex`: δn outside the grid (io::fieldArrays).
ExportFrame gatherExportArrays(const ExportInputs& inputs, const render::FrameRenderer& renderer,
                               double outsideDeltaIndex);

// Renderer options the export needs: photon-path recording (every k-th
// photon, k the largest prime <= photons / photon_paths) when
// export.vtk.photon_paths > 0;
// otherwise none, so the photon program is the default one.
render::RendererOptions rendererOptionsFor(const Scene& scene);

class FrameExporter {
public:
    // `deferIndexes`: the .pvd and .series files wait for writeIndexes
    // (the processes of a run that share its frames).
    FrameExporter(const Scene& scene, const std::filesystem::path& outputFolder, bool deferIndexes = false);

    bool wantsFrame(int frame) const;
    // Writes what frame `frame` exports; call only when wantsFrame(frame).
    void write(int frame, const ExportInputs& inputs, const render::FrameRenderer& renderer);
    // Writes every series index with these frames (number, time), of which
    // it lists those the scene exports: the whole run's, once all exist.
    void writeIndexes(const std::map<int, double>& frameTimes);

private:
    std::vector<io::VtkSeriesIndex*> seriesIndexes();  // of the .vti and .vtp series written
    void writeParaViewState();  // once, after the first indexes, so it names only collections that exist

    ExportDesc exports_;
    CameraDesc camera_;
    std::vector<ReceiverDesc> receiverDescs_;  // the quads the receivers' maps are exported on
    io::ParaViewState paraview_;
    bool paraviewWritten_ = false;  // every collection has its index from the first exported frame on
    bool deferIndexes_;
    double outsideDeltaIndex_;  // a simulated scene's ambient δn, else 0
    std::optional<io::VtkSeriesWriter> vtk_;
    std::optional<io::VdbFrameWriter> vdb_;
    std::optional<io::PolyDataSeries> receivers_;
    std::optional<io::PolyDataSeries> meshes_;
    std::optional<io::PolyDataSeries> paths_;
    std::optional<io::VtkSeriesWriter> diagnostic_;
};

}  // namespace eikon::app
