// Error reporting for eikon: bad input versus broken invariants.
//
// InputError is for anything a user supplied (scene file, CLI, mesh, image):
// the message names where (file and JSON path or line), what was expected and
// what was found, and the CLI turns it into exit code 2. NumericalBreakdown
// is a computation that broke down on valid input (exit code 1). CHECK is for
// invariants of our own code (after pbrt-v4 util/check.h, [Pharr23]): a
// failure is a bug.
#pragma once

#include <stdexcept>
#include <string>
#include <type_traits>

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

// A computation whose numbers left the range it works in (a solver's field
// became NaN or infinite): a failure of the run, exit code 1, not an input
// error, though its message names the keys that drive the computation, as
// an InputError's does ("where: expected what, found what").
class NumericalBreakdown : public std::runtime_error {
public:
    NumericalBreakdown(const std::string& where, const std::string& expected, const std::string& found)
        : std::runtime_error(where + ": expected " + expected + ", found " + found) {}
    explicit NumericalBreakdown(const std::string& message) : std::runtime_error(message) {}
};

// A broken invariant of eikon itself; never caused by user input.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

[[noreturn]] void failCheck(const char* file, int line, const char* condition, const std::string& detail);

// A number or enumerator as EIKON_CHECK_EQ prints it.
template <class T>
std::string checkedValue(const T& value) {
    if constexpr (std::is_enum_v<T>)
        return std::to_string(static_cast<std::underlying_type_t<T>>(value));
    else if constexpr (std::is_same_v<T, bool>)
        return value ? "true" : "false";
    else {
        static_assert(std::is_arithmetic_v<T>, "EIKON_CHECK_EQ prints numbers and enumerators");
        return std::to_string(value);
    }
}

// EIKON_CHECK_EQ's failure: both sides, each as written and as valued.
template <class A, class B>
[[noreturn]] void failCheckEq(const char* file, int line, const char* a, const char* b, const A& aValue,
                              const B& bValue) {
    failCheck(file, line, (std::string(a) + " == " + b).c_str(),
              std::string(a) + " is " + checkedValue(aValue) + ", " + b + " is " + checkedValue(bValue));
}

}  // namespace eikon

#define EIKON_CHECK(condition)                                                   \
    do {                                                                         \
        if (!(condition)) ::eikon::failCheck(__FILE__, __LINE__, #condition, ""); \
    } while (false)

// EIKON_CHECK(a == b) that names both values when it fails; each side is
// evaluated once.
#define EIKON_CHECK_EQ(a, b)                                                            \
    do {                                                                                \
        const auto& eikonCheckA = (a);                                                  \
        const auto& eikonCheckB = (b);                                                  \
        if (!(eikonCheckA == eikonCheckB))                                              \
            ::eikon::failCheckEq(__FILE__, __LINE__, #a, #b, eikonCheckA, eikonCheckB); \
    } while (false)

#define EIKON_CHECK_MSG(condition, detail)                                             \
    do {                                                                               \
        if (!(condition)) ::eikon::failCheck(__FILE__, __LINE__, #condition, (detail)); \
    } while (false)
