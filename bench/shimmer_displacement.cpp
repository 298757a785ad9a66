// The heat shimmer a scene shows: how far the background seen through each
// pixel moves between successive frames, in pixels of the image.
//
//   bench_shimmer_displacement SCENE [FRAMES] [KEY.PATH=VALUE ...]
//
// Each frame traces one camera ray through each pixel's centre through the
// simulated fields and keeps the direction it leaves in. A ray that leaves
// downward meets the environment's ground (render.environment
// ground_height) at H = X + t·d, X where the straight ray leaves the grid:
// the shift of the ray inside the grid is left out, so the figure is, if
// anything, low. H is projected into the camera (the pinhole the scene
// describes, without the medium), and the shift of that projection between
// frame k−1 and frame k is the apparent displacement of the background at
// the pixel. Printed per frame: the RMS of it over the pixels whose straight
// ray crosses the grid (the air that can shimmer) and meets the ground in
// both frames; the same over the pixels that see the background through hot
// air (displaced by at least 1 px against the same view with no medium, in
// this frame or the one before); and the RMS displacement against no medium
// (the background's mean distortion).
//
// A scene with a BOS diagnostic (a camera looking through the air at a
// background image, docs/scene-format.md) is measured on its background
// instead: the point a pixel sees there is the pixel less the exact
// apparent displacement the diagnostic measured (the mean of its rays),
// and the pixels counted are those whose rays cross the grid.
#include "apps/common/FrameSource.h"
#include "gl/GlContext.h"
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace eikon;

struct Camera {
    glm::dvec3 position, forward, right, up;
    double halfHeight, aspect;
    int width, height;

    explicit Camera(const Scene& scene)
        : position(scene.camera.position), forward(glm::normalize(scene.camera.target - scene.camera.position)),
          right(glm::normalize(glm::cross(forward, scene.camera.up))), up(glm::cross(right, forward)),
          halfHeight(std::tan(glm::radians(scene.camera.fovDeg) / 2)),
          aspect(static_cast<double>(scene.render.width) / scene.render.height), width(scene.render.width),
          height(scene.render.height) {}

    glm::dvec3 direction(int px, int py) const {
        const double u = (px + 0.5) / width * 2.0 - 1.0, v = (py + 0.5) / height * 2.0 - 1.0;
        return glm::normalize(forward + u * halfHeight * aspect * right - v * halfHeight * up);
    }
    glm::dvec2 project(const glm::dvec3& point) const {
        const glm::dvec3 v = point - position;
        const double depth = glm::dot(v, forward);
        return {(glm::dot(v, right) / depth / (halfHeight * aspect) + 1.0) * width / 2,
                (1.0 - glm::dot(v, up) / depth / halfHeight) * height / 2};
    }
};

// Where the ray from `origin` along `d` leaves the box, if it crosses it.
std::optional<glm::dvec3> boxExit(const glm::dvec3& origin, const glm::dvec3& d, const glm::dvec3& low,
                                  const glm::dvec3& high) {
    double near = 0.0, far = 1e30;
    for (int a = 0; a < 3; ++a) {
        const double t0 = (low[a] - origin[a]) / d[a], t1 = (high[a] - origin[a]) / d[a];
        near = std::max(near, std::min(t0, t1));
        far = std::min(far, std::max(t0, t1));
    }
    if (!(near < far)) return std::nullopt;
    return origin + far * d;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s SCENE [FRAMES] [KEY.PATH=VALUE ...]\n", argv[0]);
        return 2;
    }
    const std::string path = argv[1];
    const int frames = argc > 2 ? std::stoi(argv[2]) : 12;
    std::vector<std::string> overrides(argv + std::min(argc, 3), argv + argc);
    try {
        const Scene scene = parseScene(loadSceneDocument(path, overrides), path);
        const auto context = gl::createHeadlessContext(0);
        sim::SceneFields fields(scene);
        fields.placeFluidSolver(!context->info().rendersOnCpu());
        fields.placeWater(!context->info().rendersOnCpu());
        render::RendererOptions options;
        options.recordViewExits = true;
        app::FrameSource source(scene, fields, options, false, app::ExportNeeds());
        const Camera camera(scene);
        const double ground = scene.render.environment.groundHeight;
        const glm::dvec3 low = scene.grid.boundsMin, high = scene.grid.boundsMax;
        const auto hitPixel = [&](const glm::dvec3& exit, const glm::dvec3& d) -> std::optional<glm::dvec2> {
            if (d.y >= 0.0 || exit.y < ground) return std::nullopt;
            return camera.project(exit + ((exit.y - ground) / -d.y) * d);
        };
        std::vector<std::optional<glm::dvec2>> before;
        std::vector<char> hotBefore;
        for (int frame = 0; frame < frames; ++frame) {
            const bool more = frame + 1 < frames;
            if (more) source.beginNext();
            source.render();
            // Per pixel, where the background it sees through the medium lies
            // in the image, and where it would without the medium.
            const std::size_t pixels = static_cast<std::size_t>(camera.width) * camera.height;
            std::vector<std::optional<glm::dvec2>> seen(pixels), unbent(pixels);
            if (const render::DiagnosticStage* bos = source.renderer().diagnosticStage()) {
                if (!bos->hasReference()) throw std::runtime_error("a diagnostic scene is measured only with \"bos\"");
                const render::DiagnosticMeasurements measured = bos->downloadMeasurements();
                const std::vector<glm::vec4> rays = bos->downloadRays();
                for (std::size_t i = 0; i < pixels; ++i) {
                    if (rays[i].w != 1.0f) continue;
                    const glm::dvec2 centre(static_cast<double>(i % camera.width) + 0.5,
                                            static_cast<double>(i / camera.width) + 0.5);
                    const glm::dvec2 d(measured.displacement[2 * i], measured.displacement[2 * i + 1]);
                    seen[i] = centre - glm::dvec2(d.x, -d.y);  // d on the image's right and up axes
                    unbent[i] = centre;
                }
            } else {
                const std::vector<glm::vec4> exits = source.renderer().viewStage().downloadExits();
                for (int py = 0; py < camera.height; ++py)
                    for (int px = 0; px < camera.width; ++px) {
                        const std::size_t i = static_cast<std::size_t>(py) * camera.width + px;
                        const glm::dvec3 straight = camera.direction(px, py);
                        const auto exit = boxExit(camera.position, straight, low, high);
                        if (!exit || exits[i].w != 1.0f) continue;
                        seen[i] = hitPixel(*exit, glm::normalize(glm::dvec3(exits[i])));
                        if (seen[i]) unbent[i] = hitPixel(*exit, straight);
                    }
            }
            double shimmer = 0.0, distortion = 0.0, hotShimmer = 0.0;
            long long counted = 0, distorted = 0, hotCounted = 0;
            std::vector<char> hot(pixels, 0);
            for (std::size_t i = 0; i < pixels; ++i) {
                if (!seen[i]) continue;
                if (const auto& still = unbent[i]) {
                    const glm::dvec2 shift = *seen[i] - *still;
                    distortion += glm::dot(shift, shift);
                    ++distorted;
                    hot[i] = glm::dot(shift, shift) >= 1.0;
                }
                if (!before.empty() && before[i]) {
                    const glm::dvec2 shift = *seen[i] - *before[i];
                    shimmer += glm::dot(shift, shift);
                    ++counted;
                    if (hot[i] || hotBefore[i]) {
                        hotShimmer += glm::dot(shift, shift);
                        ++hotCounted;
                    }
                }
            }
            std::printf("frame %d: RMS displacement since the frame before %.3f px over %lld pixels, %.3f px over the "
                        "%lld seen through hot air; against no medium %.3f px\n",
                        frame, counted ? std::sqrt(shimmer / counted) : 0.0, counted,
                        hotCounted ? std::sqrt(hotShimmer / hotCounted) : 0.0, hotCounted,
                        distorted ? std::sqrt(distortion / distorted) : 0.0);
            std::fflush(stdout);
            before = std::move(seen);
            hotBefore = std::move(hot);
            if (more) {
                if (source.throughRing()) source.waitNext();
                source.publishNext();
            }
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 2;
    }
    return 0;
}
