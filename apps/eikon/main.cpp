// eikon: the command-line front end. Composition only: parse the command
// line, hand over to a command, map failures to exit codes
// (0 success, 2 bad input, 1 anything else).
#include "apps/eikon/AccuracyCommand.h"
#include "apps/eikon/BenchCommand.h"
#include "apps/eikon/InfoCommand.h"
#include "apps/eikon/RunCommand.h"
#include "bridge/core/Error.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"eikon: eikonal photon tracing through refractive media that change while you watch"};
    app.require_subcommand(1);
    eikon::app::RunOptions runOptions;
    eikon::app::addRunCommand(app, runOptions);
    eikon::app::addInfoCommand(app);
    eikon::app::BenchOptions benchOptions;
    eikon::app::addBenchCommand(app, benchOptions);
    eikon::app::AccuracyOptions accuracyOptions;
    eikon::app::addAccuracyCommand(app, accuracyOptions);
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        return 2;
    }
    try {
        if (app.got_subcommand("run")) return eikon::app::runCommand(runOptions);
        if (app.got_subcommand("bench")) return eikon::app::benchCommand(benchOptions);
        if (app.got_subcommand("accuracy")) return eikon::app::accuracyCommand(accuracyOptions);
        return eikon::app::infoCommand();
    } catch (const eikon::InputError& error) {
        std::cerr << "eikon: error: " << error.what() << "\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "eikon: error: " << error.what() << "\n";
        return 1;
    }
}
