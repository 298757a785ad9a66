// What every eikon VTK XML file shares: Float32 arrays copied from named
// arrays, a Float64 field-data array TimeValue (ParaView takes a dataset's
// time from it), appended raw binary with the chosen compressor, and an
// atomic write (temporary name, fsync, rename). Included only by the
// writers' .cpp files.
#pragma once

#include "bridge/grid/NamedArrays.h"
#include "bridge/scene/ExportDesc.h"

#include <vtkDataObject.h>
#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>
#include <vtkXMLWriter.h>

#include <filesystem>
#include <string>
#include <vector>

namespace eikon::io {

vtkSmartPointer<vtkFloatArray> makeFloatArray(const std::string& name, int components, const std::vector<float>& values);

void addTimeValue(vtkDataObject& data, double time);
// Field data NAME_unit (one string) for every array that states its unit:
// ParaView lists it beside the arrays.
void addUnits(vtkDataObject& data, const std::vector<NamedArray>& arrays);

// Appended raw binary, compressed as asked, written to a temporary beside
// `path` and renamed over it; std::runtime_error naming `path` on failure.
void writeVtkXmlAtomically(vtkXMLWriter& writer, VtkExportDesc::Compression compression,
                           const std::filesystem::path& path);

}  // namespace eikon::io
