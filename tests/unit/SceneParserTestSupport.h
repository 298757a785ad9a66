// Shared by the scene-parser tests: a valid scene exercising every section,
// and helpers to expect an InputError at a JSON path.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace eikon::test {

using nlohmann::json;

extern const char* const kValidScene;

json validScene();
// validScene() with every key added since the first format: a spot light as
// lights[2], a smoothing window and a full tracer section.
json sceneWithNewKeys();
// Writes `contents` to a file in the test temporary folder; returns its path.
std::string writeTempFile(const std::string& name, const std::string& contents);
// The message of the InputError that parsing `root` throws, or "" (and a test
// failure) if it throws none.
std::string parseErrorMessage(const json& root);
// Expects parsing to fail at `path` with a message containing `detail`.
void expectErrorAt(const json& root, const std::string& path, const std::string& detail = "");

}  // namespace eikon::test
