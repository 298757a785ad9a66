#include "io/scene/SceneOverride.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <vector>

namespace eikon {
namespace {

bool isArrayIndex(const std::string& segment) {
    return !segment.empty() && segment.size() <= 9 &&
           std::all_of(segment.begin(), segment.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<std::string> splitKeyPath(const std::string& keyPath) {
    std::vector<std::string> segments;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = keyPath.find('.', start);
        segments.push_back(keyPath.substr(start, dot - start));
        if (dot == std::string::npos) return segments;
        start = dot + 1;
    }
}

// The member or element named by segment; `parent` is the key path so far.
nlohmann::json& stepInto(nlohmann::json& node, const std::string& segment, const std::string& parent,
                         const std::string& where) {
    const std::string at = parent.empty() ? "the top level" : parent;
    if (node.is_array()) {
        if (!isArrayIndex(segment)) throw InputError(where, "an array index at " + at, "\"" + segment + "\"");
        const std::size_t index = std::stoul(segment);
        if (index >= node.size()) {
            throw InputError(where, "an index below " + std::to_string(node.size()) + " (the length of " + at + ")",
                             segment);
        }
        return node[index];
    }
    if (node.is_null()) node = nlohmann::json::object();
    if (!node.is_object()) {
        throw InputError(where, "an object or array at " + at, std::string("a ") + node.type_name());
    }
    return node[segment];
}

nlohmann::json parseOverrideValue(const std::string& text) {
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    return value.is_discarded() ? nlohmann::json(text) : value;
}

}  // namespace

void applyOverride(nlohmann::json& root, const std::string& assignment) {
    const std::string where = "--set " + assignment;
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos) throw InputError(where, "key.path=value", "no '='");
    const std::string keyPath = assignment.substr(0, equals);
    if (keyPath.empty()) throw InputError(where, "a key path before '='", "an empty key path");

    nlohmann::json* node = &root;
    std::string walked;
    for (const std::string& segment : splitKeyPath(keyPath)) {
        if (segment.empty()) throw InputError(where, "key names separated by single '.'", "an empty key in " + keyPath);
        node = &stepInto(*node, segment, walked, where);
        walked += (walked.empty() ? "" : ".") + segment;
    }
    *node = parseOverrideValue(assignment.substr(equals + 1));
}

}  // namespace eikon
