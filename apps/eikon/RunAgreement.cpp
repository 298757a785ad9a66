#include "apps/eikon/RunAgreement.h"

#include "bridge/core/Error.h"
#include "io/vdb/VolumeFramePath.h"

#include <zlib.h>

#include <fstream>
#include <optional>
#include <set>
#include <vector>

namespace eikon::app {

namespace {

using nlohmann::json;

// CRC-32 of a file's bytes, read in pieces.
std::uint32_t fileCrc32(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path + " to compare it with the other ranks' copies");
    std::vector<char> piece(std::size_t{1} << 20);
    uLong crc = crc32_z(0L, Z_NULL, 0);
    while (in.read(piece.data(), static_cast<std::streamsize>(piece.size())) || in.gcount() > 0)
        crc = crc32_z(crc, reinterpret_cast<const Bytef*>(piece.data()), static_cast<z_size_t>(in.gcount()));
    return static_cast<std::uint32_t>(crc);
}

// One file the scene reads, by what the ranks can compare: its key path in
// the scene, its size and (`whole`) the CRC-32 of its bytes. Its path, which
// a rank resolves against its own scene file's folder, is not compared.
json fileFacts(const std::string& key, const std::string& path, bool whole) {
    json facts = {{"key", key}, {"bytes", std::filesystem::file_size(path)}};
    if (whole) facts["crc32"] = fileCrc32(path);
    return facts;
}

json filesRead(const Scene& scene, int frames) {
    json files = json::array();
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].kind == ObjectDesc::Kind::Mesh)
            files.push_back(fileFacts("objects[" + std::to_string(i) + "].mesh.path", scene.objects[i].mesh.path, true));
    if (scene.render.environment.kind == EnvironmentDesc::Kind::Hdr)
        files.push_back(fileFacts("render.environment.path", scene.render.environment.path, true));
    if (scene.volume && !scene.volume->sequence) files.push_back(fileFacts("volume.path", scene.volume->path, true));
    if (scene.volume && scene.volume->sequence)
        for (int frame = 0; frame < frames; ++frame)
            files.push_back(fileFacts("volume.path, rendered frame " + std::to_string(frame),
                                      volumeFramePath(*scene.volume, scene.volume->frameStart + frame), false));
    return files;
}

// A value in a message: short ones as they are written, long ones elided.
std::string shown(const json& value) {
    if (value.is_null()) return "absent";
    const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    return text.size() <= 60 ? text : text.substr(0, 57) + "...";
}

std::string joined(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// Where two documents first differ: the key path, written as the scene file
// writes it, and the two values there (null where absent).
struct Difference {
    std::string path;
    json mine, theirs;
};

// Values are compared as written (1 and 1.0 differ), keys in sorted order.
std::optional<Difference> firstDifference(const json& mine, const json& theirs, const std::string& path) {
    if (mine.type() != theirs.type()) return Difference{path, mine, theirs};
    if (mine.is_object()) {
        std::set<std::string> keys;
        for (const auto& [key, value] : mine.items()) keys.insert(key);
        for (const auto& [key, value] : theirs.items()) keys.insert(key);
        for (const std::string& key : keys) {
            const json absent;
            if (auto at = firstDifference(mine.contains(key) ? mine[key] : absent,
                                          theirs.contains(key) ? theirs[key] : absent, joined(path, key)))
                return at;
        }
        return std::nullopt;
    }
    if (mine.is_array()) {
        for (std::size_t i = 0; i < std::max(mine.size(), theirs.size()); ++i) {
            const json absent;
            if (auto at = firstDifference(i < mine.size() ? mine[i] : absent, i < theirs.size() ? theirs[i] : absent,
                                          path + "[" + std::to_string(i) + "]"))
                return at;
        }
        return std::nullopt;
    }
    if (mine.dump() == theirs.dump()) return std::nullopt;
    return Difference{path, mine, theirs};
}

// Rank `rank`'s facts against rank 0's (`mine`), in words.
std::string describeDifference(const json& mine, const json& theirs, int rank) {
    const std::string them = "rank " + std::to_string(rank) + "'s ";
    const json& myArguments = mine["arguments"];
    const json& theirArguments = theirs["arguments"];
    for (std::size_t i = 0; i < myArguments.size() && i < theirArguments.size(); ++i)
        if (myArguments[i] != theirArguments[i])
            return them + myArguments[i][0].get<std::string>() + " is " + shown(theirArguments[i][1]) +
                   ", rank 0's is " + shown(myArguments[i][1]);
    if (auto at = firstDifference(mine["scene"], theirs["scene"], ""))
        return them + "scene differs from rank 0's at " + (at->path.empty() ? "its top level" : at->path) + " (" +
               shown(at->theirs) + ", rank 0's " + shown(at->mine) + ")";
    const json& myFiles = mine["files"];
    const json& theirFiles = theirs["files"];
    for (std::size_t i = 0; i < myFiles.size() && i < theirFiles.size(); ++i) {
        if (myFiles[i] == theirFiles[i]) continue;
        const std::string key = myFiles[i]["key"].get<std::string>();
        if (myFiles[i]["bytes"] != theirFiles[i]["bytes"])
            return them + "file for " + key + " holds " + theirFiles[i]["bytes"].dump() + " bytes, rank 0's " +
                   myFiles[i]["bytes"].dump();
        return them + "file for " + key + " differs from rank 0's in its bytes (CRC-32 " +
               theirFiles[i].value("crc32", json()).dump() + ", rank 0's " + myFiles[i].value("crc32", json()).dump() +
               ")";
    }
    return them + "scene files differ from rank 0's";  // the same facts in another order
}

}  // namespace

Ranks::Agreement runAgreement(const RunOptions& options, const std::filesystem::path& outDir,
                              const nlohmann::json& sceneDocument, const Scene& scene) {
    // Every argument but the scene's path (its document and files are
    // compared instead), --set (folded into the document) and --quiet (only
    // rank 0 shows progress).
    const json arguments = json::array({json::array({"--out", outDir.string()}),
                                        json::array({"--frames", std::to_string(options.frames)}),
                                        json::array({"--force", options.force ? "on" : "off"}),
                                        json::array({"--vtk", options.vtk ? "on" : "off"}),
                                        json::array({"--distribute", options.distribute}),
                                        json::array({"--pipelining", options.pipelining})});
    const json facts = {{"arguments", arguments}, {"scene", sceneDocument}, {"files", filesRead(scene, options.frames)}};
    return {facts.dump(), [facts](const std::string& theirs, int rank) {
                return describeDifference(facts, json::parse(theirs), rank);
            }};
}

}  // namespace eikon::app
