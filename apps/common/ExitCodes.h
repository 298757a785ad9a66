// The exit codes of eikon's programs: 0 success, 2 bad input (command line,
// scene file, --set), 1 anything else. Parses the command line and runs
// `body`, mapping each failure to its code with one message; SIGINT and
// SIGTERM remove the temporaries being written before the program ends.
#pragma once

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <string>

namespace eikon::app {

// A failure another process of the same job has reported (apps/eikon/Ranks.h):
// this one exits with its code and says nothing more.
struct ReportedElsewhere : std::exception {
    explicit ReportedElsewhere(int exitCode) : code(exitCode) {}
    const char* what() const noexcept override { return "reported by another rank"; }
    int code;
};

template <typename Body>
int parseAndRun(CLI::App& app, int argc, char** argv, const std::string& program, Body&& body) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);
    } catch (const CLI::ParseError& error) {
        // One line in eikon's own form, then CLI11's hint.
        std::cerr << program << ": error: " << error.what() << "\n"
                  << "Run with --help for more information.\n";
        return 2;
    }
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

}  // namespace eikon::app
