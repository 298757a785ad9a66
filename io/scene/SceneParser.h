// Scene files (docs/scene-format.md) to validated Scene values.
//
// Every problem with the input throws InputError naming the file and the JSON
// path of the offending value, what was expected and what was found.
#pragma once

#include "bridge/scene/Scene.h"
#include "io/scene/SceneOverride.h"  // applyOverride, which loadSceneFile applies

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace eikon {

// Reads and validates a parsed scene document; sourceName is used in messages.
Scene parseScene(const nlohmann::json& root, const std::string& sourceName);

// The document of the file at path with each `--set` override applied in
// order, not yet validated.
nlohmann::json loadSceneDocument(const std::string& path, const std::vector<std::string>& overrides = {});

// Parses and validates scene text (JSON, with the file's checks) as if it
// were the file `sourceName`: relative paths start at its folder.
Scene parseSceneText(const std::string& text, const std::string& sourceName);

// Reads the file at path, applies each `--set` override in order, then parses.
Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace eikon
