#include "io/vtk/VtkXmlCommon.h"

#include "io/files/AtomicFile.h"

#include <vtkCallbackCommand.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

#include <algorithm>

namespace eikon::io {

// The writer only reads the data, but a copy keeps the caller's lifetime and
// constness out of VTK's reference counting; it costs a few ms at 128³, far
// below the compression pass.
vtkSmartPointer<vtkFloatArray> makeFloatArray(const std::string& name, int components,
                                              const std::vector<float>& values) {
    auto array = vtkSmartPointer<vtkFloatArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / static_cast<std::size_t>(components)));
    std::copy(values.begin(), values.end(), array->GetPointer(0));
    return array;
}

void addTimeValue(vtkDataObject& data, double time) {
    vtkNew<vtkDoubleArray> timeValue;
    timeValue->SetName("TimeValue");
    timeValue->SetNumberOfTuples(1);
    timeValue->SetValue(0, time);
    data.GetFieldData()->AddArray(timeValue);
}

void addUnits(vtkDataObject& data, const std::vector<NamedArray>& arrays) {
    for (const NamedArray& array : arrays) {
        if (array.meaning.unit.empty()) continue;
        vtkNew<vtkStringArray> unit;
        unit->SetName((array.name + "_unit").c_str());
        unit->InsertNextValue(array.meaning.unit);
        data.GetFieldData()->AddArray(unit);
    }
}

void writeVtkXmlAtomically(vtkXMLWriter& writer, VtkExportDesc::Compression compression,
                           const std::filesystem::path& path) {
    writer.SetDataModeToAppended();
    writer.EncodeAppendedDataOff();  // raw binary, not base64
    switch (compression) {
        case VtkExportDesc::Compression::Zlib:
            writer.SetCompressorTypeToZLib();
            // Float fields barely compress past level 1 (level 5, VTK's default:
            // 2.5% smaller at 128³, ~15% slower).
            writer.SetCompressionLevel(1);
            break;
        case VtkExportDesc::Compression::Lz4:
            writer.SetCompressorTypeToLZ4();
            writer.SetCompressionLevel(1);  // VTK: acceleration 10 − level, so 1 is LZ4 at its fastest
            break;
        case VtkExportDesc::Compression::None:
            writer.SetCompressorTypeToNone();
            break;
    }
    // VTK streams straight to a temporary beside the target, which is then
    // fsync'ed and renamed. (Encoding into a string for writeFileAtomically
    // instead took ~745 ms instead of ~100 ms for an uncompressed 128³ frame.)
    const std::filesystem::path temporary = temporaryPathFor(path);
    writer.SetFileName(temporary.c_str());
    // A failed write (a full disk, say) is eikon's to report, in one line:
    // VTK's own error reports, the writer's and its pipeline's, are taken
    // by an observer instead of going to stderr.
    vtkNew<vtkCallbackCommand> swallow;
    const unsigned long onWriter = writer.AddObserver(vtkCommand::ErrorEvent, swallow);
    const unsigned long onPipeline = writer.GetExecutive()->AddObserver(vtkCommand::ErrorEvent, swallow);
    const bool written = writer.Write() == 1 && writer.GetErrorCode() == 0;
    writer.GetExecutive()->RemoveObserver(onPipeline);
    writer.RemoveObserver(onWriter);
    commitTemporary(temporary, path, written,
                    written ? "" : vtkErrorCode::GetStringFromErrorCode(static_cast<int>(writer.GetErrorCode())));
}

}  // namespace eikon::io
