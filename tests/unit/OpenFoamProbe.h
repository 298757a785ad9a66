#pragma once
// The independent sampling the OpenFOAM import tests check eikon against:
// VTK's own OpenFOAM reader (cell data as written, no cell-to-point
// smoothing, 64-bit floats) and probe filter, as ParaView reads a case,
// sampled at the render grid's cell centres (point i of the output is cell
// GridSpec::linearIndex).
#include "bridge/grid/GridSpec.h"

#include <vtkDataSet.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOpenFOAMReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProbeFilter.h>
#include <vtkSmartPointer.h>

#include <filesystem>

namespace eikon::test {

class OpenFoamProbe {
public:
    OpenFoamProbe(const std::filesystem::path& foam, const GridSpec& grid) {
        reader_->SetFileName(foam.c_str());
        reader_->SetCreateCellToPoint(0);
        reader_->SetUse64BitFloats(true);
        reader_->UpdateInformation();
        vtkNew<vtkPoints> centres;
        for (int k = 0; k < grid.resolution.z; ++k)
            for (int j = 0; j < grid.resolution.y; ++j)
                for (int i = 0; i < grid.resolution.x; ++i) {
                    const glm::dvec3 x = grid.cellCentre(i, j, k);
                    centres->InsertNextPoint(x.x, x.y, x.z);
                }
        probes_->SetPoints(centres);
    }

    // The case's internal mesh at `time` (s), probed at the cell centres.
    vtkSmartPointer<vtkDataSet> at(double time) {
        reader_->UpdateTimeStep(time);
        vtkNew<vtkProbeFilter> probe;
        probe->SetInputData(probes_);
        probe->SetSourceData(vtkMultiBlockDataSet::SafeDownCast(reader_->GetOutput())->GetBlock(0));
        probe->Update();
        return probe->GetOutput();
    }

private:
    vtkNew<vtkOpenFOAMReader> reader_;
    vtkNew<vtkPolyData> probes_;
};

}  // namespace eikon::test
