// Error reporting for eikon: bad input versus broken invariants.
//
// InputError is for anything a user supplied (scene file, CLI, mesh, image):
// the message names where (file and JSON path or line), what was expected and
// what was found, and the CLI turns it into exit code 2. CHECK is for
// invariants of our own code (after pbrt-v4 util/check.h, [Pharr23]): a
// failure is a bug.
#pragma once

#include <stdexcept>
#include <string>

namespace eikon {

class InputError : public std::runtime_error {
public:
    // where: "scene.json: objects[1].radius"; expected/found: plain words.
    InputError(const std::string& where, const std::string& expected, const std::string& found)
        : std::runtime_error(where + ": expected " + expected + ", found " + found), where_(where) {}
    // For input errors that are not about one value (a refused output folder, say).
    explicit InputError(const std::string& message) : std::runtime_error(message) {}

    const std::string& where() const { return where_; }

private:
    std::string where_;
};

// A broken invariant of eikon itself; never caused by user input.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

[[noreturn]] void failCheck(const char* file, int line, const char* condition, const std::string& detail);

}  // namespace eikon

#define EIKON_CHECK(condition)                                                   \
    do {                                                                         \
        if (!(condition)) ::eikon::failCheck(__FILE__, __LINE__, #condition, ""); \
    } while (false)

#define EIKON_CHECK_MSG(condition, detail)                                             \
    do {                                                                               \
        if (!(condition)) ::eikon::failCheck(__FILE__, __LINE__, #condition, (detail)); \
    } while (false)
