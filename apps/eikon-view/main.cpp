// eikon-view: the interactive viewer. Composition only: parse the command
// line, run the viewer, map failures to exit codes (0 success, 2 bad input,
// 1 anything else).
#include "apps/common/ExitCodes.h"
#include "apps/eikon-view/Viewer.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
    CLI::App app{"eikon-view: watch a scene live — orbit (left drag), pan (middle), zoom (wheel), move the light "
                 "(right drag); space pauses the simulation, n steps, r resets, p saves a screenshot"};
    eikon::view::ViewerOptions options;
    app.add_option("scene", options.scenePath, "Scene file (JSON, see docs/scene-format.md)")->required();
    app.add_option("--set", options.overrides, "Override a scene value, e.g. --set render.photons=100000")
        ->type_name("KEY.PATH=VALUE");
    app.add_option("--width", options.width, "Window width in pixels")->check(CLI::Range(64, 8192));
    app.add_option("--height", options.height, "Window height in pixels")->check(CLI::Range(64, 8192));
    app.add_option("--frames", options.frames, "Close after this many frames (0: when the window is closed)")
        ->check(CLI::Range(0, 1000000));
    app.add_option("--screenshot", options.screenshotPath, "With --frames: write the last frame's image here (PNG)");
    app.add_option("--window-shot", options.windowShotPath,
                   "With --frames: write the whole window, panel included, here (PNG)");
    app.add_option("--animate", options.animate,
                   "Scripted input: orbit (turn the camera each frame), orbit-return (orbit, then back to the "
                   "scene's camera) or light (drag the light each frame)")
        ->check(CLI::IsMember({"orbit", "orbit-return", "light"}));
    app.add_option("--target-ms", options.targetFrameMs, "Frame time to keep while a light is dragged")
        ->check(CLI::Range(5.0, 10000.0));
    app.add_option("--preview-ms", options.previewViewMs,
                   "View-pass time to keep while the camera moves: a preview of one ray per k×k pixels")
        ->check(CLI::Range(0.01, 10000.0));
    app.add_option("--camera-frame-ms", options.cameraFrameMs,
                   "Mean frame time to keep while the camera moves, by holding a moving scene between its frames "
                   "(0: the scene advances every frame); photon tracing then keeps to it where it is shorter than "
                   "--target-ms")
        ->check(CLI::Range(0.0, 10000.0));
    CLI::Option* follow = app.add_flag("--follow", options.follow,
                                       "Follow the scene's volume (a .pvd or .series time series, an OpenFOAM "
                                       "case) as a simulation writes it: show each new step once it is complete");
    app.add_option("--follow-poll-ms", options.followPollMs,
                   "With --follow: milliseconds between looks at the series")
        ->check(CLI::Range(1.0, 600000.0))
        ->needs(follow);
    app.add_option("--follow-timeout", options.followTimeoutS,
                   "With --follow: seconds to wait for the first complete step")
        ->check(CLI::Range(0.001, 1e7))
        ->needs(follow);
    return eikon::app::parseAndRun(app, argc, argv, "eikon-view", [&] { return eikon::view::runViewer(options); });
}
