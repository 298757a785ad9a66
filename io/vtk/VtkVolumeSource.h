// Volume data through VTK's own readers, resampled onto the render grid
// (scene `volume` with a VTK path, docs/scene-format.md):
//   .vti                 image data (vtkXMLImageDataReader, through
//   .vtu, .vts, .vtr     vtkXMLGenericDataObjectReader, which reads the type
//                        the file declares)
//   .vtk                 a legacy data set (vtkDataSetReader)
//   .pvd                 a VTK "Collection": its DataSet files, by timestep
//   .series              ParaView's JSON file series: its files, by time
//   .foam, controlDict,  an OpenFOAM case (vtkOpenFOAMReader, its internal
//   a case folder        mesh, cell data, every time directory a step)
// Polygonal data (.vtp, or a legacy file holding polydata) is a surface, not
// a volume, and refused. Each render cell centre x is probed at
// placement⁻¹·x by vtkProbeFilter: point data interpolated within the cell
// that holds it (trilinear in a voxel, linear in a tetrahedron), cell data
// constant per cell; centres outside every cell are marked not covered.
//
// The header keeps VTK out of its includes; only the .cpp sees it.
#pragma once

#include "bridge/grid/GridSpec.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace eikon::io {

// True when `path` is one VTK's readers open as a volume here, or polygonal
// data that VtkVolumeSource refuses by name: by extension, or a folder (an
// OpenFOAM case).
bool isVtkVolumePath(const std::filesystem::path& path);
// True for VTK data that a simulation adds steps to as it runs: a .pvd or
// .series time series, or an OpenFOAM case.
bool isVtkTimeSeriesPath(const std::filesystem::path& path);

// One array to resample: its name in the file and the scene key that names
// it (for a refusal).
struct VtkArrayRequest {
    std::string name;
    std::string key;
};

// The requested arrays on the render grid (x fastest; `components` values
// per cell, 1 or 3) and which cells the data cover (1) or not (0, values 0).
struct VtkResampled {
    struct Array {
        int components = 1;
        std::vector<float> values;
    };
    std::vector<Array> arrays;  // in request order
    std::vector<std::uint8_t> covered;
};

class VtkVolumeSource {
public:
    // Opens the file or case and, for a series, its list of steps; reads no
    // data set yet. InputError naming the path for polygonal data, an
    // unknown extension, a missing file or folder, an unreadable index, a
    // series file that is missing, or an OpenFOAM case without time steps.
    //
    // `following` (a run that follows a simulation as it writes, sim/volume/
    // VolumeFollower.h): a series index that is missing or does not parse yet,
    // a listed file not yet there and an OpenFOAM case without time
    // directories are no error — the steps are what refresh() finds.
    explicit VtkVolumeSource(const std::filesystem::path& path, bool following = false);
    ~VtkVolumeSource();
    VtkVolumeSource(VtkVolumeSource&&) noexcept;
    VtkVolumeSource& operator=(VtkVolumeSource&&) noexcept;

    int stepCount() const;
    // Lists the steps again, as a simulation adds them: the series index read
    // anew, or the OpenFOAM case's time directories scanned anew. An index
    // that does not parse (being rewritten) keeps the last list. Only for a
    // source opened `following`.
    void refresh();
    // The files step `step` is read from, whose sizes tell whether a writer
    // is still at work: the data set's file; for an OpenFOAM time, the
    // requested arrays' field files in its directory (NAME or NAME.gz,
    // whichever exists; NAME where neither does).
    std::vector<std::filesystem::path> stepFiles(int step, const std::vector<VtkArrayRequest>& requests) const;
    // What step `step` is read from, for messages: a file, or the case and its time.
    std::string stepName(int step) const;

    // Reads step `step` and resamples the requested arrays. InputError
    // naming the file (or case and time) when it cannot be read, holds
    // polygonal data, lacks a requested array (listing the arrays it has),
    // has an array with other than 1 or 3 components, or a sample is not
    // finite (with its world position).
    VtkResampled resample(int step, const std::vector<VtkArrayRequest>& requests, const GridSpec& grid,
                          const glm::dmat4& placement) const;
    // What resample refuses before it probes: reads step `step` whole and
    // checks each requested array is there with 1 or 3 components. The same
    // InputErrors.
    void check(int step, const std::vector<VtkArrayRequest>& requests) const;

private:
    struct Steps;
    void listSteps();
    std::filesystem::path path_;
    bool following_ = false;
    std::unique_ptr<Steps> steps_;
};

}  // namespace eikon::io
