// eikon: the command-line front end. Composition only: parse the command
// line, hand over to a command, map failures to exit codes
// (0 success, 2 bad input, 1 anything else).
#include "apps/common/ExitCodes.h"
#include "apps/eikon/AccuracyCommand.h"
#include "apps/eikon/BenchCommand.h"
#include "apps/eikon/InfoCommand.h"
#include "apps/eikon/RunCommand.h"

#include <CLI/CLI.hpp>

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
    return eikon::app::parseAndRun(app, argc, argv, "eikon", [&] {
        if (app.got_subcommand("run")) return eikon::app::runCommand(runOptions);
        if (app.got_subcommand("bench")) return eikon::app::benchCommand(benchOptions);
        if (app.got_subcommand("accuracy")) return eikon::app::accuracyCommand(accuracyOptions);
        return eikon::app::infoCommand();
    });
}
