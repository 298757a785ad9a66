// Scene files (docs/scene-format.md) to validated Scene values.
//
// Every problem with the input throws InputError naming the file and the JSON
// path of the offending value, what was expected and what was found.
#pragma once

#include "bridge/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace eikon {

// Reads and validates a parsed scene document; sourceName is used in messages.
Scene parseScene(const nlohmann::json& root, const std::string& sourceName);

// Reads the file at path, applies each `--set` override in order, then parses.
Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});

// Applies one `--set key.path=value` assignment: '.' separates keys, numeric
// keys index existing array elements, missing objects on the way are created.
// The value is JSON if it parses as JSON and a string otherwise.
void applyOverride(nlohmann::json& root, const std::string& assignment);

}  // namespace eikon
