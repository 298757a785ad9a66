#include "apps/eikon/FrameExport.h"

namespace eikon::app {

io::ExportFrame gatherExportArrays(const sim::SceneFields& fields, const render::FrameRenderer& renderer) {
    io::ExportFrame frame{fields.fields().grid, io::fieldArrays(fields.fields())};
    const render::PhotonStage& photons = renderer.photonStage();
    if (photons.storesFluence()) {
        frame.arrays.push_back({"fluence", 3, photons.downloadFluence()});
        frame.arrays.push_back({"photon_direction", 3, photons.downloadFluenceDirection()});
    }
    for (io::NamedArray& array : fields.exportArrays()) frame.arrays.push_back(std::move(array));
    return frame;
}

FrameExporter::FrameExporter(const ExportDesc& exports, const std::filesystem::path& outputFolder)
    : exports_(exports) {
    if (exports_.vtk.enabled) vtk_.emplace(outputFolder, "fields", exports_.vtk.compression);
    if (exports_.vdb.enabled) vdb_.emplace(outputFolder, "fields");
}

bool FrameExporter::wantsFrame(int frame) const {
    return exports_.vtk.exportsFrame(frame) || exports_.vdb.exportsFrame(frame);
}

void FrameExporter::write(int frame, const sim::SceneFields& fields, const render::FrameRenderer& renderer) {
    const io::ExportFrame arrays = gatherExportArrays(fields, renderer);
    if (vtk_ && exports_.vtk.exportsFrame(frame))
        vtk_->writeFrame(frame, fields.time(), io::selectCells(arrays, exports_.vtk, "export.vtk"));
    if (vdb_ && exports_.vdb.exportsFrame(frame))
        vdb_->writeFrame(frame, fields.time(), io::selectCells(arrays, exports_.vdb, "export.vdb"));
}

}  // namespace eikon::app
