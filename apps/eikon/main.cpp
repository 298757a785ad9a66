// eikon: the command-line front end. Composition only: parse the command
// line, hand over to a command, map failures to exit codes
// (0 success, 2 bad input, 1 anything else). Under mpirun every rank runs
// this; apps/eikon/Ranks.h says how they share a run and fail together.
#include "apps/common/ExitCodes.h"
#include "apps/eikon/AccuracyCommand.h"
#include "apps/eikon/BenchCommand.h"
#include "apps/eikon/ConvergeCommand.h"
#include "apps/eikon/InfoCommand.h"
#include "apps/eikon/ParaViewCommand.h"
#include "apps/eikon/Ranks.h"
#include "apps/eikon/RunCommand.h"
#include "apps/eikon/WarmShadersCommand.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace {

// bench, accuracy and converge measure one process, paraview writes one
// file and warm-shaders fills one machine's cache; under mpirun every rank
// would do the same thing at once.
void requireOneProcess(eikon::app::Ranks& ranks, const char* command) {
    ranks.checkInputsTogether([&] {
        if (ranks.distributed())
            throw eikon::InputError(std::string("eikon ") + command, "one process (start it without mpirun)",
                                    std::to_string(ranks.size()) + " ranks");
    });
}

}  // namespace

int main(int argc, char** argv) {
    eikon::app::Ranks& ranks = eikon::app::Ranks::start(argc, argv);
    CLI::App app{"eikon: eikonal photon tracing through refractive media that change while you watch"};
    app.require_subcommand(1);
    eikon::app::RunOptions runOptions;
    eikon::app::addRunCommand(app, runOptions);
    eikon::app::addInfoCommand(app);
    eikon::app::BenchOptions benchOptions;
    eikon::app::addBenchCommand(app, benchOptions);
    eikon::app::AccuracyOptions accuracyOptions;
    eikon::app::addAccuracyCommand(app, accuracyOptions);
    eikon::app::ConvergeOptions convergeOptions;
    eikon::app::addConvergeCommand(app, convergeOptions);
    eikon::app::ParaViewOptions paraviewOptions;
    eikon::app::addParaViewCommand(app, paraviewOptions);
    eikon::app::WarmShadersOptions warmShadersOptions;
    eikon::app::addWarmShadersCommand(app, warmShadersOptions);
    return eikon::app::runReportingFailures("eikon", [&] {
        return ranks.runGuarded([&] {
            // Every rank parses its own command line (a launcher may give each
            // its own): one that refuses it ends them all, and ranks started
            // with different commands are refused before any command starts.
            std::optional<int> printed;  // --help, --version
            eikon::app::Ranks::Agreement sameCommand;
            sameCommand.difference = [&](const std::string& theirs, int rank) {
                return "rank " + std::to_string(rank) + "'s command is " + theirs + ", rank 0's is " +
                       sameCommand.text;
            };
            ranks.checkInputsTogether(
                [&] {
                    printed = eikon::app::parseCommandLine(app, argc, argv);
                    sameCommand.text = printed ? "--help" : app.get_subcommands().front()->get_name();
                },
                sameCommand);
            if (printed) return *printed;
            if (app.got_subcommand("run")) return eikon::app::runCommand(runOptions);
            if (app.got_subcommand("bench")) {
                requireOneProcess(ranks, "bench");
                return eikon::app::benchCommand(benchOptions);
            }
            if (app.got_subcommand("accuracy")) {
                requireOneProcess(ranks, "accuracy");
                return eikon::app::accuracyCommand(accuracyOptions);
            }
            if (app.got_subcommand("converge")) {
                requireOneProcess(ranks, "converge");
                return eikon::app::convergeCommand(convergeOptions);
            }
            if (app.got_subcommand("paraview")) {
                requireOneProcess(ranks, "paraview");
                return eikon::app::paraviewCommand(paraviewOptions);
            }
            if (app.got_subcommand("warm-shaders")) {
                requireOneProcess(ranks, "warm-shaders");
                return eikon::app::warmShadersCommand(warmShadersOptions);
            }
            return eikon::app::infoCommand();
        });
    });
}
