#include "apps/eikon/ProgressBar.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace eikon::app {

ProgressBar::ProgressBar(int total, bool quiet)
    : total_(total), enabled_(!quiet && total > 1 && ::isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::advance() {
    ++done_;
    if (enabled_) draw();
}

void ProgressBar::finish() {
    if (enabled_) std::fputc('\n', stderr);
}

void ProgressBar::draw() const {
    constexpr int kWidth = 40;
    const int filled = kWidth * done_ / total_;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double remaining = done_ > 0 ? seconds / done_ * (total_ - done_) : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d frames, %.1f s left ", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), done_, total_, remaining);
    std::fflush(stderr);
}

}  // namespace eikon::app
