// A progress bar on stderr for runs of several frames; silent when stderr is
// not a terminal, when asked to be quiet, or for a single frame.
#pragma once

#include <chrono>

namespace eikon::app {

class ProgressBar {
public:
    ProgressBar(int total, bool quiet);
    void advance();
    void finish();

private:
    void draw() const;
    int total_;
    int done_ = 0;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace eikon::app
