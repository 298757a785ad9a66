#include "io/vtk/VtkSeriesWriter.h"

#include "bridge/core/Error.h"
#include "io/vtk/VtkXmlCommon.h"

#include <vtkCellData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <set>
#include <system_error>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

const std::string& checkedBaseName(const std::string& name) {
    if (!isSafeVtkBaseName(name))
        throw InputError("VTK export base name", "letters, digits, '_', '-' or '.'", "\"" + name + "\"");
    return name;
}

}  // namespace

VtkSeriesWriter::VtkSeriesWriter(const fs::path& outputFolder, std::string baseName, Compression compression)
    : directory_(outputFolder / "vtk"), baseName_(checkedBaseName(baseName)), compression_(compression),
      index_(directory_, baseName_, "vti") {
    std::error_code error;
    fs::create_directories(directory_, error);
    if (error || !fs::is_directory(directory_))
        throw InputError(directory_.string() + ": cannot create the VTK export folder (" + error.message() + ")");
}

void VtkSeriesWriter::writeFrame(int frame, double time, const FieldSet& fields, const std::vector<NamedArray>& extra) {
    ExportFrame arrays{fields.grid, fieldArrays(viewsOf(fields))};
    arrays.arrays.insert(arrays.arrays.end(), extra.begin(), extra.end());
    writeFrame(frame, time, arrays);
}

void VtkSeriesWriter::writeFrame(int frame, double time, const ExportFrame& arrays) {
    EIKON_CHECK_MSG(frame >= 0, "frame " + std::to_string(frame));
    EIKON_CHECK_MSG(std::isfinite(time), "time of frame " + std::to_string(frame));
    std::set<std::string> names;
    std::vector<const NamedArray*> varying, constant;
    for (const NamedArray& array : arrays.arrays) {
        EIKON_CHECK_MSG(!array.name.empty() && names.insert(array.name).second,
                        "VTK array name \"" + array.name + "\" empty or repeated");
        EIKON_CHECK_MSG(array.components >= 1 &&
                            array.values.size() == static_cast<std::size_t>(array.components) * arrays.grid.cellCount(),
                        "VTK array \"" + array.name + "\" size");
        (array.constant ? constant : varying).push_back(&array);
    }
    // A frame of constant arrays only (nothing moves) stays whole: ParaView's
    // Append Attributes takes its time from the series, which then needs an
    // array of its own.
    if (varying.empty()) {
        varying = constant;
    } else if (!constant.empty() && !staticWritten_) {
        writeImage(staticPath(), arrays.grid, constant, std::nullopt);
        staticWritten_ = true;
    }
    writeImage(framePath(frame), arrays.grid, varying, time);
    index_.add(frame, time);
}

void VtkSeriesWriter::writeImage(const fs::path& path, const GridSpec& grid, const std::vector<const NamedArray*>& arrays,
                                 std::optional<double> time) const {
    // Cell data, not point data: eikon's samples are cell-centred (GridSpec:
    // cell (i,j,k) is the box boundsMin + [i, i+1]·voxelSize, its value
    // belongs to the whole voxel). ImageData points sit on the voxel corners,
    // so the extent counts corners (resolution + 1 points per axis), the
    // origin is boundsMin and the spacing the voxel size; the bounds ParaView
    // shows are then exactly [boundsMin, boundsMax]. Point data would either
    // shift every sample by half a voxel or shrink the box by one voxel.
    // VTK orders cells x fastest, then y, then z, as GridSpec::linearIndex.
    vtkNew<vtkImageData> image;
    image->SetDimensions(grid.resolution.x + 1, grid.resolution.y + 1, grid.resolution.z + 1);
    image->SetOrigin(grid.boundsMin.x, grid.boundsMin.y, grid.boundsMin.z);
    const glm::dvec3 voxel = grid.voxelSize();
    image->SetSpacing(voxel.x, voxel.y, voxel.z);
    EIKON_CHECK_EQ(static_cast<std::size_t>(image->GetNumberOfCells()), grid.cellCount());
    std::vector<NamedArray> described;  // for the units field data
    for (const NamedArray* array : arrays) {
        image->GetCellData()->AddArray(makeFloatArray(array->name, array->components, array->values));
        described.push_back({array->name, array->components, {}, array->meaning});
    }
    if (time) addTimeValue(*image, *time);
    addUnits(*image, described);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writeVtkXmlAtomically(*writer, compression_, path);
}

}  // namespace eikon::io
