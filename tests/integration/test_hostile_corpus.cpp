// The hostile corpus (tests/hostile, written by tools/make_hostile_corpus.py):
// every case run through `eikon run` as a user would. A refusal must be exit
// code 2 with one line in eikon's form naming the file and the JSON path or
// line at fault, and must leave nothing on disk; a valid case must render.
// No case may crash, hang, or end in any other code.
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(EIKON_SOURCE_DIR) / "tests" / "hostile";

struct HostileCase {
    std::string name, scene, message;
    std::vector<std::string> overrides;
    int exit = 0;  // 0 runs, 2 is refused, -1 either (a flipped byte that may leave a valid file)
    int frames = 1;  // --frames: a volume sequence's later files
    std::map<std::string, std::string> environment;  // variables eikon runs with (EIKON_MEMORY_LIMIT_MB)
};

void PrintTo(const HostileCase& hostile, std::ostream* out) { *out << hostile.name; }

std::vector<HostileCase> loadCases() {
    std::vector<HostileCase> cases;
    std::ifstream lines(kCorpus / "cases.jsonl");
    for (std::string line; std::getline(lines, line);) {
        const nlohmann::json entry = nlohmann::json::parse(line);
        cases.push_back({entry.at("name"), entry.at("scene"), entry.at("message"), entry.at("set"), entry.at("exit"),
                         entry.value("frames", 1), entry.value("env", std::map<std::string, std::string>{})});
    }
    return cases;
}

const std::vector<HostileCase>& allCases() {
    static const std::vector<HostileCase> cases = loadCases();
    return cases;
}

struct Outcome {
    bool finished = false;  // false: still running after the deadline, then killed
    int status = 0;         // waitpid's
    std::string output;     // stdout and stderr together
};

// Runs the command without a shell (overrides hold quotes and long values),
// with `environment` added, killing it when it outlives `deadline`.
Outcome runWithDeadline(const std::vector<std::string>& arguments, std::chrono::seconds deadline,
                        const std::map<std::string, std::string>& environment) {
    int readEnd = -1;
    const pid_t child = eikon::test::spawnCapturingOutput(arguments, environment, readEnd);
    fcntl(readEnd, F_SETFL, O_NONBLOCK);
    Outcome outcome;
    const auto end = std::chrono::steady_clock::now() + deadline;
    char buffer[4096];
    while (true) {
        for (ssize_t got; (got = read(readEnd, buffer, sizeof buffer)) > 0;) outcome.output.append(buffer, got);
        if (waitpid(child, &outcome.status, WNOHANG) == child) {
            outcome.finished = true;
            break;
        }
        if (std::chrono::steady_clock::now() > end) {
            kill(child, SIGKILL);
            waitpid(child, &outcome.status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    for (ssize_t got; (got = read(readEnd, buffer, sizeof buffer)) > 0;) outcome.output.append(buffer, got);
    close(readEnd);
    return outcome;
}

class HostileCorpus : public ::testing::TestWithParam<HostileCase> {};

TEST_P(HostileCorpus, RefusedCleanlyOrRendered) {
    const HostileCase& hostile = GetParam();
    const fs::path folder = fs::temp_directory_path() / ("eikon_hostile_" + hostile.name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path out = folder / "out";
    std::vector<std::string> arguments{EIKON_EXECUTABLE, "run", (kCorpus / hostile.scene).string(), "--out",
                                       out.string(), "--quiet"};
    for (const std::string& assignment : hostile.overrides) {
        arguments.push_back("--set");
        arguments.push_back(assignment);
    }
    if (hostile.frames != 1) {
        arguments.push_back("--frames");
        arguments.push_back(std::to_string(hostile.frames));
    }
    const Outcome outcome = runWithDeadline(arguments, std::chrono::seconds(120), hostile.environment);
    ASSERT_TRUE(outcome.finished) << "still running after 120 s";
    ASSERT_TRUE(WIFEXITED(outcome.status)) << "ended by signal " << WTERMSIG(outcome.status) << ":\n" << outcome.output;
    const int code = WEXITSTATUS(outcome.status);
    if (hostile.exit == -1) {
        EXPECT_TRUE(code == 0 || code == 2) << "exit code " << code << ":\n" << outcome.output;
    } else {
        ASSERT_EQ(code, hostile.exit) << outcome.output.substr(0, 2000);
    }
    if (code == 2) {
        EXPECT_EQ(outcome.output.rfind("eikon: error: ", 0), 0u) << outcome.output.substr(0, 2000);
        EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << outcome.output.substr(0, 2000);
        EXPECT_LE(outcome.output.size(), 1200u) << "a message is one line's worth, not an echo of the input";
        EXPECT_NE(outcome.output.find(hostile.message), std::string::npos)
            << "should name \"" << hostile.message << "\": " << outcome.output.substr(0, 2000);
        EXPECT_FALSE(fs::exists(out)) << "a refused run wrote its output folder";
        EXPECT_TRUE(fs::is_empty(folder)) << "a refused run wrote beside its output folder";
    } else if (code == 0) {
        EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.png")) << outcome.output;
    }
    fs::remove_all(folder);
}

std::string caseName(const ::testing::TestParamInfo<HostileCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Cases, HostileCorpus, ::testing::ValuesIn(allCases()), caseName);

// The corpus is the generator's: at least 300 cases, every file it names
// present, so a corpus cut short by a failed regeneration is seen.
TEST(HostileCorpusFiles, HoldsAtLeast300CasesAndTheirScenes) {
    EXPECT_GE(allCases().size(), 300u);
    for (const HostileCase& hostile : allCases())
        EXPECT_TRUE(fs::is_regular_file(kCorpus / hostile.scene)) << hostile.scene;
}

}  // namespace
