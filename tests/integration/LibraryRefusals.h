// The library tests' check of a refusal: eikon::Renderer::setFields throws
// eikon::Error, and its message holds each of the words expected.
#pragma once

#include "eikon/eikon.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

inline void expectRefused(eikon::Renderer& renderer, const std::vector<eikon::Field>& fields,
                          const std::vector<std::string>& words) {
    try {
        renderer.setFields(fields);
        FAIL() << "accepted";
    } catch (const eikon::Error& error) {
        for (const std::string& word : words)
            EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what() << " lacks " << word;
    }
}
