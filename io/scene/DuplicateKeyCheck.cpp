#include "io/scene/DuplicateKeyCheck.h"

#include "bridge/core/Error.h"
#include "io/scene/JsonReader.h"

namespace eikon {

bool DuplicateKeyCheck::operator()(int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
    case Event::object_start:
    case Event::array_start:
        enterElement();
        frames_.push_back({event == Event::object_start, {}, {}, -1});
        break;
    case Event::object_end:
    case Event::array_end:
        frames_.pop_back();
        break;
    case Event::key: {
        Frame& object = frames_.back();
        const std::string key = parsed.get<std::string>();
        if (!object.keys.insert(key).second)
            throw InputError(sourceName_ + ": " + pathTo(clipped(key)), "each key once in its object",
                             "\"" + clipped(key) + "\" twice (the first value would be lost)");
        object.key = key;
        break;
    }
    case Event::value:
        enterElement();
        break;
    }
    return true;
}

void DuplicateKeyCheck::enterElement() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
}

std::string DuplicateKeyCheck::pathTo(const std::string& key) const {
    std::string path;
    for (std::size_t f = 0; f + 1 < frames_.size(); ++f)
        path += frames_[f].object ? (path.empty() ? "" : ".") + clipped(frames_[f].key)
                                  : "[" + std::to_string(frames_[f].index) + "]";
    return path + (path.empty() ? "" : ".") + key;
}

}  // namespace eikon
