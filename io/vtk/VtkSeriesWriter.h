// Per-frame export of a FieldSet as VTK ImageData (.vti) for ParaView time
// series. Each frame becomes DIR/vtk/NAME_NNNNN.vti; after every frame both
// DIR/vtk/NAME.pvd (a VTK "Collection") and DIR/vtk/NAME.vti.series
// (ParaView's JSON file-series sidecar) are rewritten, so ParaView can open a
// run that is still going. Arrays marked constant (NamedArray::constant: the
// run never changes them) go once into DIR/vtk/NAME_static.vti, with no
// TimeValue, instead of into every frame; ParaView merges it with the series
// (Append Attributes, series first; open_in_paraview.py does). A frame whose
// arrays are all constant is written whole: the series must hold an array
// for Append Attributes to follow its time. Every file is written
// atomically (temporary name, fsync, rename): a reader never sees a
// truncated frame or index.
//
// The header keeps VTK out of its includes; only VtkSeriesWriter.cpp sees it.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "io/export/ExportArrays.h"
#include "io/vtk/VtkSeriesIndex.h"
#include "bridge/scene/ExportDesc.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace eikon::io {

class VtkSeriesWriter {
public:
    // Creates DIR/vtk/. `baseName` may hold only letters, digits, '_', '-'
    // and '.' (it lands unescaped in XML and JSON); InputError otherwise.
    // `compression` selects the compressor of the appended binary data.
    using Compression = VtkExportDesc::Compression;
    VtkSeriesWriter(const std::filesystem::path& outputFolder, std::string baseName,
                    Compression compression = Compression::Zlib);

    // Writes DIR/vtk/NAME_NNNNN.vti with the arrays of `frame` that are not
    // constant as cell data (the constant ones into NAME_static.vti, the
    // first time; all of them when none varies), then rewrites NAME.pvd and
    // NAME.vti.series. Writing a frame number
    // again replaces that entry. Throws std::runtime_error naming the path
    // when a file cannot be written; InternalError (EIKON_CHECK) for a
    // negative frame, a time that is not finite, or arrays whose size does
    // not match the grid or whose names repeat.
    void writeFrame(int frame, double time, const ExportFrame& arrays);
    // The field set's arrays (fieldArrays) and `extra` ones, e.g. fluence.
    void writeFrame(int frame, double time, const FieldSet& fields, const std::vector<NamedArray>& extra = {});

    const std::filesystem::path& directory() const { return directory_; }
    std::filesystem::path framePath(int frame) const { return index_.framePath(frame); }
    std::filesystem::path staticPath() const { return directory_ / (baseName_ + "_static.vti"); }
    std::filesystem::path collectionPath() const { return index_.collectionPath(); }  // NAME.pvd
    std::filesystem::path seriesPath() const { return index_.seriesPath(); }          // NAME.vti.series
    VtkSeriesIndex& index() { return index_; }

private:
    // One ImageData file of `arrays` on `grid`, with its TimeValue where given.
    void writeImage(const std::filesystem::path& path, const GridSpec& grid, const std::vector<const NamedArray*>& arrays,
                    std::optional<double> time) const;

    std::filesystem::path directory_;
    std::string baseName_;
    Compression compression_;
    VtkSeriesIndex index_;
    bool staticWritten_ = false;
};

}  // namespace eikon::io
