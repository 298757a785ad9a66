// eikon-view: a window in which the scene runs — the same frame loop as
// `eikon run` — while the user orbits the camera, drags the light and edits
// settings. Only the stages whose inputs changed run, so orbiting costs a
// view pass, drawn as a preview while the camera moves (ViewPreview.h),
// and meanwhile a fluid solver on the CPU advances in the background
// (ViewerSession::beginBackgroundAdvance) while other moving scenes are
// held between their frames as far as keeps the camera to its frame time
// (SimulationPacer.h);
// while a light is dragged or the scene moves, the photon count
// drops to keep the target frame time and returns to the scene's count when
// the drag ends or the scene is paused.
#pragma once

#include <string>
#include <vector>

namespace eikon::view {

struct ViewerOptions {
    std::string scenePath;
    std::vector<std::string> overrides;  // --set key.path=value
    int width = 1280, height = 800;      // window, pixels
    int frames = 0;                      // > 0: close after this many frames (tests, demos)
    std::string screenshotPath;          // with frames: the last frame's image goes here
    std::string windowShotPath;          // with frames: the whole window, panel included
    double targetFrameMs = 100.0;        // while dragging a light
    double previewViewMs = 40.0;         // view-pass time to keep while the camera moves (ViewPreview.h)
    // Mean frame time to keep while the camera moves, by holding a moving
    // scene between its frames (SimulationPacer.h), and photon tracing's
    // meanwhile where shorter than targetFrameMs; 0: the scene advances
    // every frame. 60 ms, 16.7 frames/s: a margin over the 15 aimed at.
    double cameraFrameMs = 60.0;
    // Scripted input for benchmarks and demos: "orbit" turns the camera 1.8°
    // per frame, "light" drags the first light 6 pixels per frame,
    // "orbit-return" orbits and then returns to the scene's camera; with
    // frames, the mean frames per second over them, how many of them
    // advanced a moving scene and the longest are printed at the end, which
    // waits for the full image (the preview refined).
    std::string animate;
    // Follow the scene's volume as a simulation writes it (--follow): each
    // new step is shown once complete; the first is awaited for
    // followTimeoutS at most, later ones for as long as the window is open.
    bool follow = false;
    double followPollMs = 250.0;
    double followTimeoutS = 60.0;
};

// Returns the process exit code. Throws InputError for a bad scene.
int runViewer(const ViewerOptions& options);

}  // namespace eikon::view
