// JSON allows a key twice in an object and nlohmann keeps the last value;
// for a scene that silently drops what the user wrote first. This parser
// callback (nlohmann::json::parse(text, DuplicateKeyCheck(file))) follows
// the key path of what is being read and throws InputError for a key given
// twice, naming the file and the key's path.
#pragma once

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace eikon {

class DuplicateKeyCheck {
public:
    explicit DuplicateKeyCheck(std::string sourceName) : sourceName_(std::move(sourceName)) {}

    bool operator()(int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed);

private:
    struct Frame {
        bool object;
        std::set<std::string> keys;
        std::string key;  // the member being read
        int index;        // the element being read
    };

    void enterElement();
    std::string pathTo(const std::string& key) const;

    std::string sourceName_;
    std::vector<Frame> frames_;
};

}  // namespace eikon
