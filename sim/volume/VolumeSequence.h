// An imported volume (scene `volume`) as a source of fields: one OpenVDB
// file, or a numbered sequence of which rendered frame f shows file number
// frame_start + f; or VTK data (io/vtk/VtkVolumeSource), a time series or an
// OpenFOAM case of which rendered frame f shows step f. Each frame's grids
// are sampled onto the render grid (io/vdb, sparse until sampled; VTK's
// probe filter) and mapped to δn, κ, σs, g by sim/optics/VolumeOptics.h.
// Following (VolumeDesc::follow), frame f shows the f-th step that completed
// while a simulation writes the series (sim/volume/VolumeFollower.h).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/NamedArrays.h"
#include "bridge/scene/Scene.h"
#include "sim/optics/VolumeOptics.h"
#include "sim/volume/VolumeFollower.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon::io {
class VtkVolumeSource;
}

namespace eikon::sim {

// Checks the files of rendered frames 0 … frames − 1 of a sequence as
// loading them would, up to their voxel values: each file present, its
// header, grid table and the trees of the grids read whole and within the
// file (a truncated or damaged file), each grid present with its type, its
// metadata and a transform that places it (io/vdb/VdbVolumeFile::check).
// Run before anything is written, so that a damaged later file stops the
// run before frame 0 (docs/scene-format.md, volume). InputError as the
// constructor's. A single file is left to the constructor. VTK data: the
// series' file list (each present), a step per frame, and each step read
// whole with the declared arrays in it (io/vtk/VtkVolumeSource::check).
void checkVolumeFrames(const VolumeDesc& desc, const GridSpec& renderGrid, int frames, const std::string& scenePath);

class VolumeSequence {
public:
    // Loads the file for rendered frame 0. InputError naming the scene file
    // and volume.path, then the OpenVDB file (and grid, byte) and what was
    // expected and found, for a missing file or grid or a bad file.
    // Following, waits for the first complete step (VolumeFollower::wait);
    // InputError when following ends before one, with the steps skipped.
    VolumeSequence(const VolumeDesc& desc, const Material& medium, const GridSpec& renderGrid,
                   const std::string& scenePath);
    ~VolumeSequence();
    VolumeSequence(const VolumeSequence&) = delete;
    VolumeSequence& operator=(const VolumeSequence&) = delete;

    // Frames show different files (or VTK steps).
    bool isSequence() const;
    int frame() const { return frame_; }
    double time() const { return frame_ * desc_.frameTime; }
    const std::string& currentFile() const { return file_; }

    // Loads the next file of the sequence (a single file stays loaded).
    // Following: takes the step followNext found ready.
    void advanceFrame();

    // Whether the volume follows a simulation as it writes.
    bool following() const { return follower_ != nullptr; }
    // Following: whether the next step is ready for advanceFrame. `wait`:
    // looks until it is or following ends (VolumeFollower::wait, the outcome
    // kept for followEnd()); otherwise one look.
    bool followNext(bool wait);
    // The damaged steps skipped before the current one.
    const std::vector<SkippedStep>& skippedBefore() const { return skippedBefore_; }
    // When following ends: why ("stop file", "timeout", or "" when the
    // frames asked for were rendered) and the steps left unread, skipped.
    std::string followEnd() const;
    std::vector<SkippedStep> finishFollowing();
    // Loads the file of rendered frame `frame` directly (frames of a volume
    // do not depend on each other).
    void seekFrame(int frame);

    // Writes δn, κ, σs, g of the current file into `fields` (on its grid),
    // bumping the versions of what changed.
    void writeFields(FieldSet& fields) const;

    // density, temperature (K), flame, velocity on the render grid, for
    // those grids the scene reads.
    std::vector<NamedArray> exportArrays() const;

private:
    void load(int frame);

    VolumeDesc desc_;
    Material medium_;
    GridSpec grid_;
    std::string scenePath_;
    int frame_ = 0;
    std::string file_;
    std::unique_ptr<io::VtkVolumeSource> vtk_;  // VTK data; OpenVDB files are opened per frame
    std::unique_ptr<VolumeFollower> follower_;  // following a simulation as it writes
    std::vector<SkippedStep> skippedBefore_;
    std::optional<VolumeFollower::Outcome> followOutcome_;
    VolumeGrids samples_;
    std::vector<float> velocity_;
};

}  // namespace eikon::sim
