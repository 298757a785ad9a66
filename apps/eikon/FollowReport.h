// What report.jsonl says of a run that follows a simulation (`eikon run
// --follow`, docs/scene-format.md): each frame's line names the step it
// shows and the damaged steps skipped before it; a last line says why
// following ended and which steps were left unread. Skipped steps are also
// warned about on stderr as they are found.
#pragma once

#include "sim/volume/VolumeFollower.h"

#include <string>
#include <vector>

namespace eikon::app {

// `reportLine` (a frame's JSON) with "follow": {"step": name, "skipped": [{"step", "reason"}, …]}.
std::string withFollowedStep(const std::string& reportLine, const std::string& step,
                             const std::vector<sim::SkippedStep>& skipped);

// The last line: {"follow_end": {"why": …, "frames": N, "skipped": [{"step", "reason"}, …]}}.
std::string followEndLine(const std::string& why, int frames, const std::vector<sim::SkippedStep>& skipped);

// One warning per skipped step, on stderr.
void warnSkipped(const std::vector<sim::SkippedStep>& skipped);

}  // namespace eikon::app
