#include "io/scene/JsonReader.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace eikon {

std::string clipped(const std::string& text) {
    constexpr std::size_t kLongest = 80;
    if (text.size() <= kLongest) return text;
    return text.substr(0, kLongest) + "… (" + std::to_string(text.size()) + " characters)";
}

namespace {

std::string describeNode(const nlohmann::json* node) {
    if (node == nullptr) return "nothing";
    switch (node->type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::boolean: return node->get<bool>() ? "true" : "false";
    case nlohmann::json::value_t::string: return "a string " + clipped(node->dump());
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: {
        const std::size_t size = node->size();
        return "an array of " + std::to_string(size) + (size == 1 ? " element" : " elements");
    }
    case nlohmann::json::value_t::number_float: {
        const double value = node->get<double>();
        if (!std::isfinite(value)) return "a number too large to represent (" + formatNumber(value) + ")";
        return node->dump();
    }
    default: return node->dump();  // integers
    }
}

std::string quotedList(const std::vector<std::string>& words) {
    std::string list;
    for (const std::string& word : words) list += (list.empty() ? "\"" : ", \"") + word + "\"";
    return list;
}

}  // namespace

bool NumberRange::contains(double value) const {
    const bool aboveMin = minInclusive ? value >= min : value > min;
    const bool belowMax = maxInclusive ? value <= max : value < max;
    return aboveMin && belowMax;
}

std::string NumberRange::describe(const std::string& noun) const {
    const bool hasMin = std::isfinite(min);
    const bool hasMax = std::isfinite(max);
    if (hasMin && hasMax) {
        return noun + " in " + (minInclusive ? "[" : "(") + formatNumber(min) + ", " + formatNumber(max) +
               (maxInclusive ? "]" : ")");
    }
    if (hasMin) return noun + (minInclusive ? " >= " : " > ") + formatNumber(min);
    if (hasMax) return noun + (maxInclusive ? " <= " : " < ") + formatNumber(max);
    return noun;
}

JsonReader::JsonReader(const nlohmann::json& root, std::string sourceName)
    : JsonReader(&root, std::move(sourceName), "") {}

JsonReader::JsonReader(const nlohmann::json* node, std::string sourceName, std::string path)
    : node_(node), sourceName_(std::move(sourceName)), path_(std::move(path)) {}

std::string JsonReader::where() const {
    return path_.empty() ? sourceName_ : sourceName_ + ": " + path_;
}

void JsonReader::fail(const std::string& expected) const {
    fail(expected, describeNode(node_));
}

void JsonReader::fail(const std::string& expected, const std::string& found) const {
    throw InputError(where(), expected, found);
}

double JsonReader::number(NumberRange range) const {
    const std::string expected = range.describe("a number");
    if (node_ == nullptr || !node_->is_number()) fail(expected);
    const double value = node_->get<double>();
    if (!std::isfinite(value) || !range.contains(value)) fail(expected);
    return value;
}

long long JsonReader::integer(long long min, long long max) const {
    const std::string expected =
        NumberRange::closed(static_cast<double>(min), static_cast<double>(max)).describe("an integer");
    if (node_ == nullptr || !node_->is_number()) fail(expected);
    // Every range used by eikon lies within ±2^53, where doubles hold integers exactly.
    const double value = node_->get<double>();
    if (!std::isfinite(value) || value != std::floor(value)) fail(expected);
    if (value < static_cast<double>(min) || value > static_cast<double>(max)) fail(expected);
    return static_cast<long long>(value);
}

bool JsonReader::boolean() const {
    if (node_ == nullptr || !node_->is_boolean()) fail("true or false");
    return node_->get<bool>();
}

std::string JsonReader::string() const {
    if (node_ == nullptr || !node_->is_string()) fail("a string");
    return node_->get<std::string>();
}

std::string JsonReader::oneOf(std::initializer_list<const char*> choices) const {
    const std::vector<std::string> allowed(choices.begin(), choices.end());
    const std::string expected = "one of " + quotedList(allowed);
    if (node_ == nullptr || !node_->is_string()) fail(expected);
    const std::string value = node_->get<std::string>();
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) fail(expected);
    return value;
}

glm::dvec3 JsonReader::vec3(NumberRange range) const {
    if (node_ == nullptr || !node_->is_array() || node_->size() != 3) fail("an array of 3 numbers");
    return {element(0).number(range), element(1).number(range), element(2).number(range)};
}

glm::ivec3 JsonReader::ivec3(int min, int max) const {
    if (node_ == nullptr || !node_->is_array() || node_->size() != 3) fail("an array of 3 integers");
    glm::ivec3 result;
    for (int axis = 0; axis < 3; ++axis) result[axis] = static_cast<int>(element(axis).integer(min, max));
    return result;
}

Rgb JsonReader::rgb(NumberRange channelRange) const {
    if (node_ != nullptr && node_->is_number()) return Rgb(number(channelRange));
    if (node_ == nullptr || !node_->is_array() || node_->size() != 3) {
        fail("a grey value or an array of 3 values [r, g, b], each " + channelRange.describe("a number"));
    }
    return {element(0).number(channelRange), element(1).number(channelRange), element(2).number(channelRange)};
}

std::vector<JsonReader> JsonReader::array() const {
    if (node_ == nullptr || !node_->is_array()) fail("an array");
    std::vector<JsonReader> elements;
    for (std::size_t index = 0; index < node_->size(); ++index) elements.push_back(element(index));
    return elements;
}

JsonObjectReader JsonReader::object(std::initializer_list<const char*> allowedKeys) const {
    return JsonObjectReader(*this, allowedKeys);
}

JsonReader JsonReader::member(const std::string& key) const {
    if (node_ == nullptr || !node_->is_object()) fail("an object");
    return child(key);
}

JsonReader JsonReader::element(std::size_t index) const {
    const bool present = node_ != nullptr && node_->is_array() && index < node_->size();
    return JsonReader(present ? &(*node_)[index] : nullptr, sourceName_, path_ + "[" + std::to_string(index) + "]");
}

JsonReader JsonReader::child(const std::string& key) const {
    const bool present = node_ != nullptr && node_->is_object() && node_->contains(key);
    const std::string name = clipped(key);
    return JsonReader(present ? &node_->at(key) : nullptr, sourceName_, path_.empty() ? name : path_ + "." + name);
}

JsonObjectReader::JsonObjectReader(const JsonReader& node, std::initializer_list<const char*> allowedKeys)
    : node_(node), allowedKeys_(allowedKeys.begin(), allowedKeys.end()) {
    if (node_.node_ == nullptr || !node_.node_->is_object()) node_.fail("an object");
    for (const auto& item : node_.node_->items()) {
        if (std::find(allowedKeys_.begin(), allowedKeys_.end(), item.key()) == allowedKeys_.end()) {
            node_.child(item.key()).fail("one of the keys " + quotedList(allowedKeys_), "an unknown key");
        }
    }
}

JsonReader JsonObjectReader::member(const std::string& key) const {
    checkAllowed(key);
    return node_.child(key);
}

std::optional<JsonReader> JsonObjectReader::optional(const std::string& key) const {
    checkAllowed(key);
    if (!node_.node_->contains(key)) return std::nullopt;
    return node_.child(key);
}

void JsonObjectReader::checkAllowed(const std::string& key) const {
    EIKON_CHECK_MSG(std::find(allowedKeys_.begin(), allowedKeys_.end(), key) != allowedKeys_.end(),
                    "key \"" + key + "\" read but not declared allowed at " + node_.path());
}

}  // namespace eikon
