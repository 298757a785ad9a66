// EIKON_CHECK_EQ: a broken equality names both sides and both values, and
// evaluates each side once.
#include "bridge/core/Error.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

namespace eikon {
namespace {

TEST(CheckEq, FailureNamesBothSidesAndTheirValues) {
    const std::size_t cells = 12;
    const int expected = 16;
    try {
        EIKON_CHECK_EQ(cells, static_cast<std::size_t>(expected));
        FAIL() << "12 == 16 passed";
    } catch (const InternalError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("CHECK(cells == static_cast<std::size_t>(expected)) failed"), std::string::npos)
            << message;
        EXPECT_NE(message.find("cells is 12"), std::string::npos) << message;
        EXPECT_NE(message.find("static_cast<std::size_t>(expected) is 16"), std::string::npos) << message;
        EXPECT_NE(message.find("test_check_eq.cpp:"), std::string::npos) << message;
    }
}

TEST(CheckEq, PassesAndEvaluatesEachSideOnce) {
    int calls = 0;
    const auto next = [&] { return ++calls; };
    EIKON_CHECK_EQ(next(), 1);
    EXPECT_EQ(calls, 1);
}

enum class Colour { Red = 1, Green = 2 };

TEST(CheckEq, PrintsEnumeratorsByValue) {
    try {
        EIKON_CHECK_EQ(Colour::Red, Colour::Green);
        FAIL() << "Red == Green passed";
    } catch (const InternalError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("Colour::Red is 1, Colour::Green is 2"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace eikon
