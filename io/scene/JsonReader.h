// Typed, range-checked reading of a JSON document that always knows where it
// is: every failure throws InputError naming the source file and the JSON path
// of the offending node (e.g. "scene.json: objects[1].radius").
#pragma once

#include "bridge/core/NumberFormat.h"
#include "bridge/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <glm/vec3.hpp>

#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace eikon {

// An interval of acceptable numbers; it also words itself for messages.
struct NumberRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minInclusive = true;
    bool maxInclusive = true;

    static NumberRange any() { return {}; }
    static NumberRange atLeast(double low) { return {low, std::numeric_limits<double>::infinity(), true, true}; }
    static NumberRange above(double low) { return {low, std::numeric_limits<double>::infinity(), false, true}; }
    static NumberRange closed(double low, double high) { return {low, high, true, true}; }
    static NumberRange open(double low, double high) { return {low, high, false, false}; }

    bool contains(double value) const;
    std::string describe(const std::string& noun) const;  // "a number > 0", "an integer in [1, 16]"
};

// Text quoted from the input in a message, cut to a line's worth: a 4 MB key
// or string must not become a 4 MB message.
std::string clipped(const std::string& text);

// Henyey–Greenstein g as the fields hold it: float32 rounds |g| > 1 − 6e-8
// to 1, where the phase function is a delta.
inline const NumberRange kAnisotropyRange = NumberRange::closed(-0.99999, 0.99999);

// Positions (m): an extent max − min stays finite and float32 holds every
// coordinate the GPU is given (a million kilometres).
inline const NumberRange kCoordinateRange = NumberRange::closed(-1e9, 1e9);
// Lengths (m), for the same reason.
inline const NumberRange kLengthRange = {0.0, 1e9, false, true};
// Extinction and scattering coefficients (1/m), which the fields hold in float32.
inline const NumberRange kAttenuationRange = NumberRange::closed(0.0, 1e30);

class JsonObjectReader;

// One node of the document (possibly absent), with its file and JSON path.
class JsonReader {
public:
    // The document root; sourceName is the file name used in messages.
    JsonReader(const nlohmann::json& root, std::string sourceName);

    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const std::string& expected) const;  // found: a description of this node
    [[noreturn]] void fail(const std::string& expected, const std::string& found) const;

    // Typed reads; an absent node fails them all with "found nothing".
    double number(NumberRange range = NumberRange::any()) const;  // finite only
    long long integer(long long min, long long max) const;        // 3 and 3.0 pass, 2.5 fails
    bool boolean() const;  // JSON true or false only, not 0/1 or "true"
    std::string string() const;
    std::string oneOf(std::initializer_list<const char*> choices) const;
    glm::dvec3 vec3(NumberRange range = NumberRange::any()) const;  // each component in range
    glm::ivec3 ivec3(int min, int max) const;
    Rgb rgb(NumberRange channelRange) const;  // one number (grey) or [r, g, b]
    std::vector<JsonReader> array() const;
    JsonObjectReader object(std::initializer_list<const char*> allowedKeys) const;

    // A member of this node, which must be an object; absent if the key is.
    // For a "type" read before it decides which other keys are allowed.
    JsonReader member(const std::string& key) const;

    // The element at index, or an absent node with that path.
    JsonReader element(std::size_t index) const;

private:
    JsonReader(const nlohmann::json* node, std::string sourceName, std::string path);

    JsonReader child(const std::string& key) const;  // absent unless this is an object with key
    std::string where() const;

    const nlohmann::json* node_;  // nullptr when the key is absent from the file
    std::string sourceName_;
    std::string path_;

    friend class JsonObjectReader;
};

// An object node whose keys have been checked against an allowed list.
class JsonObjectReader {
public:
    JsonObjectReader(const JsonReader& node, std::initializer_list<const char*> allowedKeys);

    // The member, or an absent node with its path: reading it fails, so a
    // typed read of member(key) is how a required key is read.
    JsonReader member(const std::string& key) const;
    std::optional<JsonReader> optional(const std::string& key) const;

private:
    void checkAllowed(const std::string& key) const;

    JsonReader node_;
    std::vector<std::string> allowedKeys_;
};

}  // namespace eikon
