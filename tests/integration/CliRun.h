// Runs the eikon executable as a user would, for the command-line tests.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace eikon::test {

struct Outcome {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// A small valid scene the command-line tests start from: a glass sphere
// over a floor, 16³ cells, 4096 photons, 32 × 24 pixels.
inline constexpr const char* kSmallSphereScene = R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "medium": {"index": 1.0},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
  "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": 4096, "width": 32, "height": 24, "seed": 3}
})";

// `environment` is prefixed to the command line ("LP_NUM_THREADS=2").
inline Outcome runEikon(const std::string& arguments, const std::string& environment = "") {
    const std::string command = environment + " " + std::string(EIKON_EXECUTABLE) + " " + arguments + " 2>&1";
    Outcome outcome;
    FILE* pipe = popen(command.c_str(), "r");
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) outcome.output += buffer;
    const int status = pclose(pipe);
    outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return outcome;
}

// The lines of a run's report.jsonl, each parsed.
inline std::vector<nlohmann::json> readReport(const std::filesystem::path& path) {
    std::ifstream report(path);
    std::vector<nlohmann::json> lines;
    for (std::string line; std::getline(report, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

// runEikon, stopped after `seconds` (coreutils timeout: exit 124), so that a
// command that runs on for ever fails its test instead of holding ctest.
inline Outcome runEikonWithin(int seconds, const std::string& arguments, const std::string& environment = "") {
    return runEikon(arguments, environment + " timeout --kill-after=10 " + std::to_string(seconds));
}

// Starts `arguments` (the executable first) without a shell, with
// `environment` added, its stdout and stderr into one pipe whose read end is
// returned in `readEnd`; returns the child's pid.
inline pid_t spawnCapturingOutput(const std::vector<std::string>& arguments,
                                  const std::map<std::string, std::string>& environment, int& readEnd) {
    int ends[2];
    EXPECT_EQ(pipe(ends), 0);
    const pid_t child = fork();
    if (child == 0) {
        for (const auto& [name, value] : environment) setenv(name.c_str(), value.c_str(), 1);
        dup2(ends[1], STDOUT_FILENO);
        dup2(ends[1], STDERR_FILENO);
        close(ends[0]);
        std::vector<char*> argv;
        for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    close(ends[1]);
    readEnd = ends[0];
    return child;
}

// A command-line test's own folder, PREFIX<test name> in the temporary
// directory: made empty before the test, removed after it.
class CliFolderTest : public ::testing::Test {
protected:
    explicit CliFolderTest(std::string prefix) : prefix_(std::move(prefix)) {}
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               (prefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    // Writes `text` into the folder as `name`; returns its path.
    std::string writeScene(const std::string& name, const std::string& text) const {
        const std::filesystem::path path = dir_ / name;
        std::ofstream(path) << text;
        return path.string();
    }

    std::filesystem::path dir_;

private:
    std::string prefix_;
};

// The cells of one CSV row; a quoted cell may hold commas.
inline std::vector<std::string> csvCells(const std::string& row) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : row) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
        else cell += c;
    }
    cells.push_back(cell);
    return cells;
}

}  // namespace eikon::test
