// `--set key.path=value`: one assignment to a parsed scene document before
// it is validated (SceneParser.h's loadSceneFile applies them in order).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace eikon {

// Applies one `--set key.path=value` assignment: '.' separates keys, numeric
// keys index existing array elements, missing objects on the way are created.
// The value is JSON if it parses as JSON and a string otherwise. Throws
// InputError naming the assignment, what was expected and what was found.
void applyOverride(nlohmann::json& root, const std::string& assignment);

}  // namespace eikon
