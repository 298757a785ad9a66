#include "sim/volume/VolumeFollower.h"

#include "bridge/core/Error.h"

#include <chrono>
#include <thread>
#include <utility>

namespace eikon::sim {

namespace fs = std::filesystem;

VolumeFollower::VolumeFollower(io::VtkVolumeSource& source, std::vector<io::VtkArrayRequest> requests, Read read)
    : source_(source), requests_(std::move(requests)), read_(std::move(read)) {}

// Each file's size and modification time; none while a file is missing.
std::optional<std::string> VolumeFollower::signatureOf(int step) const {
    std::string signature;
    for (const fs::path& file : source_.stepFiles(step, requests_)) {
        std::error_code error;
        const std::uintmax_t size = fs::file_size(file, error);
        if (error) return std::nullopt;
        const auto time = fs::last_write_time(file, error);
        if (error) return std::nullopt;
        signature += std::to_string(size) + ":" + std::to_string(time.time_since_epoch().count()) + ";";
    }
    return signature;
}

bool VolumeFollower::poll() {
    if (ready_) return true;
    source_.refresh();
    bool inOrder = true;  // every step before this one is taken, or complete and failed
    for (int step = 0; step < source_.stepCount(); ++step) {
        const std::string name = source_.stepName(step);
        if (done_.count(name)) continue;
        Watched& watched = watched_[name];
        const std::optional<std::string> signature = signatureOf(step);
        const bool complete = signature && watched.signature == signature;  // unchanged since the last look
        watched.signature = signature;
        if (!complete) inOrder = false;  // later steps still get their sizes noted
        if (!inOrder || watched.failedAt == signature) continue;
        try {
            VolumeGrids samples = read_(step);
            Step ready{step, name, std::move(samples), {}};
            for (int before = 0; before < step; ++before) {  // the writer has moved on past them
                const std::string skipped = source_.stepName(before);
                if (done_.insert(skipped).second) ready.skipped.push_back({skipped, watched_[skipped].reason});
            }
            done_.insert(name);
            ready_ = std::move(ready);
            return true;
        } catch (const InputError& error) {
            watched.failedAt = signature;
            watched.reason = error.what();
        }
    }
    return false;
}

// Whether a step listed is neither taken nor failed as it stands: one a
// writer may still be writing.
bool VolumeFollower::waitingForCompletion() {
    for (int step = 0; step < source_.stepCount(); ++step) {
        const std::string name = source_.stepName(step);
        if (done_.count(name)) continue;
        const Watched& watched = watched_[name];
        if (!watched.failedAt || watched.failedAt != watched.signature) return true;
    }
    return false;
}

VolumeFollower::Outcome VolumeFollower::wait(const VolumeDesc::Follow& follow) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto interval = std::chrono::duration<double>(follow.pollSeconds);
    for (;;) {
        // The stop file is looked for first: steps the writer finished before it count.
        const bool stopping = !follow.stopFile.empty() && fs::exists(follow.stopFile);
        if (poll()) return Outcome::Ready;
        if (stopping && !waitingForCompletion()) return Outcome::Stopped;
        if (std::chrono::duration<double>(Clock::now() - start).count() >= follow.timeoutSeconds)
            return Outcome::TimedOut;
        std::this_thread::sleep_for(interval);
    }
}

VolumeFollower::Step VolumeFollower::take() {
    EIKON_CHECK_MSG(ready_.has_value(), "take() without a ready step");
    Step step = std::move(*ready_);
    ready_.reset();
    return step;
}

std::vector<SkippedStep> VolumeFollower::finish() {
    std::vector<SkippedStep> skipped;
    for (int step = 0; step < source_.stepCount(); ++step) {
        const std::string name = source_.stepName(step);
        if (!done_.insert(name).second) continue;
        const Watched& watched = watched_[name];
        skipped.push_back({name, watched.failedAt ? watched.reason
                                                  : std::string("never complete while followed (its files missing "
                                                                "or still changing)")});
    }
    return skipped;
}

}  // namespace eikon::sim
