// The fingerprint of the scene a run rendered, recorded in its output
// folder's journal (io/files/RunJournal.h) so that `eikon paraview DIR
// SCENE` can tell whether SCENE is the run's.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace eikon {

// MD5 (VTK's kwsys), as 32 hex digits, of the scene document — the file with
// its --set assignments applied — written as compact JSON with its keys in
// order, leaving out `camera` and `export`: `eikon paraview` may show the
// run from another camera (--set camera.…), and the export settings say
// what was written, not what was rendered.
std::string sceneFingerprint(const nlohmann::json& document);

}  // namespace eikon
