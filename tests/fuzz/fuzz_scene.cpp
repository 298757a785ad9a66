// libFuzzer target: a scene file and its `--set` overrides through
// loadSceneFile, as `eikon run` reads them. Input: the scene's JSON text,
// then optionally a NUL byte and one override per line. Every outcome but a
// parsed scene or an InputError (a crash, a hang, a leak, any other
// exception) is a finding.
#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"
#include "tests/fuzz/FuzzScratchFile.h"

#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input = eikon::fuzz::asBytes(data, size);
    const std::size_t split = input.find('\0');
    std::vector<std::string> overrides;
    if (split != std::string_view::npos) {
        std::istringstream lines{std::string(input.substr(split + 1))};
        for (std::string line; std::getline(lines, line);) overrides.push_back(line);
    }
    const auto path = eikon::fuzz::writeScratchFile("scene.json", input.substr(0, split));
    try {
        eikon::loadSceneFile(path.string(), overrides);
    } catch (const eikon::InputError&) {
    }
    return 0;
}
