// Following a simulation while it writes (`eikon run --follow`,
// `eikon-view --follow`; docs/scene-format.md, following a running case):
// the steps of a VTK time series (.pvd, .series) or an OpenFOAM case are
// listed anew at each look, and each is read once it is complete, in the
// order the series lists them.
//
// Complete means: every file the step is read from (io::VtkVolumeSource::
// stepFiles — the data set's file, or the OpenFOAM time directory's field
// files of the declared arrays) is there with the same size and
// modification time as at the previous look, and the step then reads and
// resamples without a refusal (the Read given: VolumeSequence's also maps
// the samples to optics, whose refusals count too). A step whose read fails is tried again when
// its files change (a writer that paused longer than two looks); it is
// skipped as damaged, with the reader's reason, once a later step reads
// whole (the writer has moved on) or when following ends. A step not yet
// complete holds back the steps after it, so steps are taken in order.
#pragma once

#include "bridge/scene/VolumeDesc.h"
#include "io/vtk/VtkVolumeSource.h"
#include "sim/optics/VolumeOptics.h"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace eikon::sim {

struct SkippedStep {
    std::string step;    // what it was read from: a file, or an OpenFOAM case and time
    std::string reason;  // the reader's refusal, or that it never completed
};

class VolumeFollower {
public:
    // Reads and resamples step `step` of the source; InputError when it cannot.
    using Read = std::function<VolumeGrids(int step)>;

    // `source` opened following (VtkVolumeSource's constructor); it must
    // outlive the follower.
    VolumeFollower(io::VtkVolumeSource& source, std::vector<io::VtkArrayRequest> requests, Read read);

    // One look, without waiting: lists the steps again, notes each one's
    // file sizes and times, and reads the next steps in order that are
    // complete until one reads whole. Returns whether a step is ready (see
    // take()); once one is, looks read nothing more until it is taken.
    bool poll();

    // Why wait() returned.
    enum class Outcome { Ready, Stopped, TimedOut };
    // Looks every follow.pollSeconds until a step is ready; or until the stop
    // file exists and every step listed is taken or has failed to read
    // (Stopped); or until follow.timeoutSeconds pass without a step ready
    // (TimedOut).
    Outcome wait(const VolumeDesc::Follow& follow);

    struct Step {
        int index = 0;
        std::string name;
        VolumeGrids samples;
        std::vector<SkippedStep> skipped;  // the damaged steps passed over before it, in order
    };
    // The ready step. Only after poll() or wait() said one is ready.
    Step take();

    // When following ends: the steps listed and neither taken nor skipped —
    // those that failed to read (with the reader's reason) and those that
    // never completed — now counted as skipped, in order.
    std::vector<SkippedStep> finish();

private:
    // Per step, by name: its files' signature at the last look, and the
    // signature at which its read last failed, with the refusal.
    struct Watched {
        std::optional<std::string> signature;
        std::optional<std::string> failedAt;
        std::string reason;
    };
    std::optional<std::string> signatureOf(int step) const;
    bool waitingForCompletion();

    io::VtkVolumeSource& source_;
    std::vector<io::VtkArrayRequest> requests_;
    Read read_;
    std::set<std::string> done_;  // steps taken or skipped
    std::map<std::string, Watched> watched_;
    std::optional<Step> ready_;
};

}  // namespace eikon::sim
