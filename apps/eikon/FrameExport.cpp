#include "apps/eikon/FrameExport.h"

#include "apps/eikon/DiagnosticExport.h"
#include "bridge/core/PrimeStride.h"

#include "io/vtk/ExportGeometry.h"
#include "sim/optics/OpticalMapping.h"

#include <algorithm>

namespace eikon::app {

ExportFrame gatherExportArrays(const ExportInputs& inputs, const render::FrameRenderer& renderer,
                               double outsideDeltaIndex) {
    ExportFrame frame{inputs.fields.grid, io::fieldArrays(inputs.fields, outsideDeltaIndex)};
    if (const render::PhotonStage* photons = renderer.photonStage(); photons && photons->storesFluence()) {
        frame.arrays.push_back({"fluence", 3, photons->downloadFluence(), {"W/m^2", ArrayRole::Density}});
        frame.arrays.push_back({"photon_direction", 3, photons->downloadFluenceDirection(), {"W/m^2", ArrayRole::Direction}});
    }
    for (const NamedArray& array : inputs.simulation) frame.arrays.push_back(array);
    return frame;
}

namespace {

// All meshes of a frame in one PolyData, float32 points, with the point
// array `object` numbering the meshes in scene order.
io::PolyData meshPolyData(const std::vector<TriangleMesh>& meshes) {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    NamedArray object{"object", 1, {}};
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const auto base = static_cast<std::uint32_t>(vertices.size());
        for (const glm::dvec3& v : meshes[m].vertices) {
            vertices.emplace_back(v);
            object.values.push_back(static_cast<float>(m));
        }
        for (const glm::ivec3& t : meshes[m].triangles)
            triangles.push_back({base + static_cast<std::uint32_t>(t.x), base + static_cast<std::uint32_t>(t.y),
                                 base + static_cast<std::uint32_t>(t.z)});
    }
    return io::triangleMesh(vertices, triangles, {std::move(object)});
}

}  // namespace

render::RendererOptions rendererOptionsFor(const Scene& scene) {
    render::RendererOptions options;
    options.estimateErrors = scene.render.errorEstimate;
    const VtkExportDesc& vtk = scene.exports.vtk;
    if (vtk.enabled && vtk.photonPaths > 0) {
        options.photons.recordPathVertices = vtk.pathVertices;
        options.photons.recordedPhotons = vtk.photonPaths;
        options.photons.recordStride = static_cast<int>(largestPrimeAtMost(scene.render.photons / vtk.photonPaths));
    }
    return options;
}

FrameExporter::FrameExporter(const Scene& scene, const std::filesystem::path& outputFolder, bool deferIndexes)
    : exports_(scene.exports), camera_(scene.camera), receiverDescs_(scene.receivers),
      paraview_(io::paraViewStateOf(scene)),
      deferIndexes_(deferIndexes),
      outsideDeltaIndex_(scene.sim ? sim::ambientDeltaIndex(*scene.sim, scene.medium.index) : 0.0) {
    if (exports_.vtk.enabled) {
        vtk_.emplace(outputFolder, "fields", exports_.vtk.compression);
        if (exports_.vtk.receivers && !scene.receivers.empty())
            receivers_.emplace(outputFolder, "receivers", exports_.vtk.compression);
        const bool hasMeshes = std::any_of(scene.objects.begin(), scene.objects.end(), [](const ObjectDesc& object) {
            return object.kind == ObjectDesc::Kind::Mesh || object.kind == ObjectDesc::Kind::Water;
        });
        if (exports_.vtk.meshes && hasMeshes) meshes_.emplace(outputFolder, "meshes", exports_.vtk.compression);
        if (exports_.vtk.photonPaths > 0) paths_.emplace(outputFolder, "photon_paths", exports_.vtk.compression);
        if (scene.diagnostic) diagnostic_.emplace(outputFolder, "diagnostic", exports_.vtk.compression);
    }
    if (exports_.vdb.enabled)
        vdb_.emplace(outputFolder, "fields", std::filesystem::path(scene.sourcePath).stem().string(),
                     exports_.vdb.upAxis == VdbExportDesc::UpAxis::Z);
    for (io::VtkSeriesIndex* index : seriesIndexes()) index->setDeferred(deferIndexes);
}

std::vector<io::VtkSeriesIndex*> FrameExporter::seriesIndexes() {
    std::vector<io::VtkSeriesIndex*> indexes;
    if (vtk_) indexes.push_back(&vtk_->index());
    for (auto* series : {&receivers_, &meshes_, &paths_})
        if (*series) indexes.push_back(&(*series)->index());
    if (diagnostic_) indexes.push_back(&diagnostic_->index());
    return indexes;
}

void FrameExporter::writeIndexes(const std::map<int, double>& frameTimes) {
    for (io::VtkSeriesIndex* index : seriesIndexes()) {
        for (const auto& [frame, time] : frameTimes)
            if (exports_.vtk.exportsFrame(frame)) index->record(frame, time);
        if (!index->empty()) index->write();
    }
    writeParaViewState();
}

void FrameExporter::writeParaViewState() {
    if (!vtk_ || paraviewWritten_) return;
    io::writeParaViewState(vtk_->directory(), paraview_);
    paraviewWritten_ = true;
}

bool FrameExporter::wantsFrame(int frame) const {
    return exports_.vtk.exportsFrame(frame) || exports_.vdb.exportsFrame(frame);
}

void FrameExporter::write(int frame, const ExportInputs& inputs, const render::FrameRenderer& renderer) {
    const double time = inputs.time;
    const ExportFrame arrays = gatherExportArrays(inputs, renderer, outsideDeltaIndex_);
    if (vtk_ && exports_.vtk.exportsFrame(frame)) {
        vtk_->writeFrame(frame, time, io::selectCells(arrays, exports_.vtk, "export.vtk"));
        if (receivers_) {
            std::vector<std::vector<float>> irradiance;
            for (unsigned r = 0; r < renderer.receivers().count(); ++r)
                irradiance.push_back(renderer.receivers().download(r));
            receivers_->writeFrame(frame, time, io::receiverQuads(receiverDescs_, irradiance));
        }
        if (meshes_) meshes_->writeFrame(frame, time, meshPolyData(inputs.meshes));
        if (const render::PhotonStage* photons = renderer.photonStage(); paths_ && photons) {
            paths_->writeFrame(frame, time,
                               io::photonPolylines(photons->downloadPaths(), photons->downloadPathPower(),
                                                   exports_.vtk.pathVertices));
        }
        if (const render::DiagnosticStage* diagnostic = renderer.diagnosticStage(); diagnostic_ && diagnostic)
            diagnostic_->writeFrame(frame, time, diagnosticExportFrame(diagnostic->downloadMeasurements(), camera_));
        if (!deferIndexes_) writeParaViewState();
    }
    if (vdb_ && exports_.vdb.exportsFrame(frame))
        vdb_->writeFrame(frame, time, io::selectCells(arrays, exports_.vdb, "export.vdb"));
}

}  // namespace eikon::app
