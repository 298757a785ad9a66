#include "verify/accuracy/ErrorPlot.h"

#include "verify/accuracy/AccuracyReport.h"
#include "verify/plot/LogLogFigure.h"

#include <algorithm>
#include <map>

namespace eikon::accuracy {

namespace {

plot::Colour curveColour(const RunSettings& s) {
    using I = TracerDesc::Integrator;
    if (s.method == RenderDesc::Method::ImageSpace) return {227, 119, 194};
    if (s.estimator == TracerDesc::Estimator::Wavefront) return {140, 86, 75};
    const bool octree = s.stepPolicy == TracerDesc::StepPolicy::Octree;
    if (s.integrator == I::Euler) return {214, 39, 40};
    if (s.integrator == I::Leapfrog) return octree ? plot::Colour{255, 127, 14} : plot::Colour{31, 119, 180};
    return octree ? plot::Colour{148, 103, 189} : plot::Colour{44, 160, 44};
}

plot::Marker sweepMarker(const std::string& sweep) {
    if (sweep == "grid") return plot::Marker::Triangle;
    if (sweep == "smoothing") return plot::Marker::Cross;
    if (sweep == "octree") return plot::Marker::Diamond;
    if (sweep == "photons") return plot::Marker::Circle;
    return plot::Marker::Square;
}

// One panel of a case: a curve per integrator, step policy and sweep, in
// sweep order (step from coarse to fine, grid and photons upward).
plot::Panel casePanel(const std::string& name, const std::vector<const RunRecord*>& runs) {
    plot::Panel panel{name, {}, {0.01, 0.001}};
    std::map<std::string, std::vector<const RunRecord*>> curves;
    for (const RunRecord* r : runs)
        if (r->measurement.error > 0.0 && r->runtimeSeconds > 0.0)
            curves[curveLabel(r->settings) + "/" + r->settings.sweep].push_back(r);
    for (const auto& [key, points] : curves) {
        const RunSettings& settings = points.front()->settings;
        // The step sweep of each integrator, the wavefront's split sweep and image space's size: solid.
        const bool stepSweep = settings.sweep == "step" || settings.sweep == "wavefront" ||
                               settings.method == RenderDesc::Method::ImageSpace;
        plot::Curve curve{{}, {}, curveColour(settings), sweepMarker(settings.sweep), !stepSweep, stepSweep ? 2.0 : 1.0};
        for (const RunRecord* p : points) {
            curve.x.push_back(p->runtimeSeconds);
            curve.y.push_back(p->measurement.error);
        }
        panel.curves.push_back(std::move(curve));
    }
    return panel;
}

}  // namespace

void writeErrorPlot(const std::filesystem::path& file, const std::vector<RunRecord>& records) {
    std::vector<std::string> names;
    for (const auto& r : records)
        if (std::find(names.begin(), names.end(), r.measurement.caseName) == names.end())
            names.push_back(r.measurement.caseName);
    plot::Figure figure;
    figure.columns = std::min<int>(4, std::max<int>(1, static_cast<int>(names.size())));
    figure.xLabel = "run time of the light pass (s)";
    figure.yLabel = "error";
    for (const std::string& name : names) {
        std::vector<const RunRecord*> runs;
        for (const auto& r : records)
            if (r.measurement.caseName == name) runs.push_back(&r);
        figure.panels.push_back(casePanel(name, runs));
    }
    using I = TracerDesc::Integrator;
    using P = TracerDesc::StepPolicy;
    std::vector<plot::LegendEntry> colours;
    for (const auto& [settings, label] : std::vector<std::pair<RunSettings, const char*>>{
             {{.integrator = I::Euler}, "euler uniform"},
             {{.integrator = I::Leapfrog}, "leapfrog uniform"},
             {{.integrator = I::Rk4}, "rk4 uniform"},
             {{.integrator = I::Leapfrog, .stepPolicy = P::Octree}, "leapfrog octree"},
             {{.integrator = I::Rk4, .stepPolicy = P::Octree}, "rk4 octree"},
             {{.estimator = TracerDesc::Estimator::Wavefront}, "wavefront"},
             {{.method = RenderDesc::Method::ImageSpace}, "image space"}})
        colours.push_back({label, curveColour(settings)});
    std::vector<plot::LegendEntry> markers;
    for (const auto& [sweep, label] : std::vector<std::pair<const char*, const char*>>{
             {"step", "step sweep (solid)"},
             {"grid", "grid resolution"},
             {"smoothing", "smoothing width"},
             {"octree", "octree eps, eps', cap"},
             {"photons", "photon count"}})
        markers.push_back({label, {90, 90, 90}, sweepMarker(sweep), false});
    markers.push_back({"1% and 0.1% error", {160, 160, 160}, plot::Marker::None, true, true});
    figure.legendRows = {colours, markers};
    figure.caption = "error (dimensionless) against run time of the light pass, log-log; dashed: one knob at a fine "
                     "step; brown: the wavefront's split; pink: image space's caustic map or image size";
    plot::writeFigure(file, figure);
}

}  // namespace eikon::accuracy
