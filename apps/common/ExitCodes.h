// The exit codes of eikon's programs: 0 success, 2 bad input (command line,
// scene file, --set), 1 anything else. Parses the command line and runs
// `body`, mapping each failure to its code with one message; SIGINT and
// SIGTERM remove the temporaries being written before the program ends.
// eikon parses inside its ranks' check of their inputs (apps/eikon/Ranks.h),
// so it takes the two steps apart.
#pragma once

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <optional>
#include <string>

namespace eikon::app {

// A failure another process of the same job has reported (apps/eikon/Ranks.h):
// this one exits with its code and says nothing more.
struct ReportedElsewhere : std::exception {
    explicit ReportedElsewhere(int exitCode) : code(exitCode) {}
    const char* what() const noexcept override { return "reported by another rank"; }
    int code;
};

// Parses the command line. --help and --version print their text and give
// the exit code to end with (0); a line CLI11 refuses is bad input, an
// InputError with CLI11's message and its hint.
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);
    } catch (const CLI::ParseError& error) {
        throw InputError(std::string(error.what()) + "\nRun with --help for more information.");
    }
    return std::nullopt;
}

// Runs `body`, mapping each failure to its exit code with one message.
template <typename Body>
int runReportingFailures(const std::string& program, Body&& body) {
    io::removeTemporariesOnSignals();  // an interrupted run leaves no half-written files
    try {
        return body();
    } catch (const ReportedElsewhere& reported) {
        return reported.code;
    } catch (const InputError& error) {
        std::cerr << program << ": error: " << error.what() << "\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << program << ": error: " << error.what() << "\n";
        return 1;
    }
}

template <typename Body>
int parseAndRun(CLI::App& app, int argc, char** argv, const std::string& program, Body&& body) {
    return runReportingFailures(program, [&] {
        if (const std::optional<int> printed = parseCommandLine(app, argc, argv)) return *printed;
        return body();
    });
}

}  // namespace eikon::app
