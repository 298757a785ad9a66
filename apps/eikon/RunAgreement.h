// What every rank of `eikon run` must hold alike before any rank writes
// (Ranks::checkInputsTogether): the arguments that shape what is written,
// as each rank resolved them; the scene document after its --set
// overrides, in canonical form (keys sorted); and every file the scene
// reads — meshes, the environment map and a single volume file by size and
// CRC-32 of their bytes (each rank reads them whole anyway), the files of a
// volume sequence by size (each rank reads only its frames'). Ranks that a
// launcher started with different command lines, or that read different
// copies of a scene, would otherwise write one run mixed from both.
#pragma once

#include "apps/eikon/Ranks.h"
#include "apps/eikon/RunCommand.h"
#include "bridge/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace eikon::app {

// `outDir`: the output folder as resolved (--out, or out/<scene name>).
Ranks::Agreement runAgreement(const RunOptions& options, const std::filesystem::path& outDir,
                              const nlohmann::json& sceneDocument, const Scene& scene);

}  // namespace eikon::app
