#include "verify/accuracy/ErrorPlot.h"

#include "io/image/ImageIo.h"
#include "verify/accuracy/AccuracyReport.h"
#include "verify/accuracy/Canvas.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace eikon::accuracy {

namespace {

constexpr Colour kBlack{20, 20, 20}, kGrid{225, 225, 225}, kAxis{90, 90, 90}, kBudget{170, 170, 170};

Colour curveColour(const RunSettings& s) {
    using I = TracerDesc::Integrator;
    if (s.estimator == TracerDesc::Estimator::Wavefront) return {140, 86, 75};
    const bool octree = s.stepPolicy == TracerDesc::StepPolicy::Octree;
    if (s.integrator == I::Euler) return {214, 39, 40};
    if (s.integrator == I::Leapfrog) return octree ? Colour{255, 127, 14} : Colour{31, 119, 180};
    return octree ? Colour{148, 103, 189} : Colour{44, 160, 44};
}

Canvas::Marker sweepMarker(const std::string& sweep) {
    if (sweep == "grid") return Canvas::Marker::Triangle;
    if (sweep == "smoothing") return Canvas::Marker::Cross;
    if (sweep == "octree") return Canvas::Marker::Diamond;
    if (sweep == "photons") return Canvas::Marker::Circle;
    return Canvas::Marker::Square;
}

std::string decadeLabel(int exponent) {
    if (exponent == 0) return "1";
    if (exponent == 1) return "10";
    if (exponent == -1) return "0.1";
    return "1e" + std::to_string(exponent);
}

// One log–log panel of a case at (x, y) of size w × h.
void drawPanel(Canvas& canvas, double x, double y, double w, double h, const std::string& name,
               const std::vector<const RunRecord*>& runs) {
    const double left = x + 62, right = x + w - 12, top = y + 30, bottom = y + h - 44;
    canvas.text(x + 0.5 * (w - Canvas::textWidth(name)), y + 6, name, kBlack);
    double tMin = 1e300, tMax = 0, eMin = 1e300, eMax = 0;
    for (const RunRecord* r : runs) {
        if (r->measurement.error <= 0.0 || r->runtimeSeconds <= 0.0) continue;
        tMin = std::min(tMin, r->runtimeSeconds), tMax = std::max(tMax, r->runtimeSeconds);
        eMin = std::min(eMin, r->measurement.error), eMax = std::max(eMax, r->measurement.error);
    }
    if (tMax <= 0.0) return;
    const int tLo = static_cast<int>(std::floor(std::log10(tMin))), tHi = std::max(tLo + 1, static_cast<int>(std::ceil(std::log10(tMax))));
    const int eLo = static_cast<int>(std::floor(std::log10(eMin))), eHi = std::max(eLo + 1, static_cast<int>(std::ceil(std::log10(eMax))));
    auto px = [&](double t) { return left + (std::log10(t) - tLo) / (tHi - tLo) * (right - left); };
    auto py = [&](double e) { return bottom - (std::log10(e) - eLo) / (eHi - eLo) * (bottom - top); };
    const int eStride = (eHi - eLo) > 8 ? 2 : 1;
    for (int d = tLo; d <= tHi; ++d) {
        canvas.line(px(std::pow(10.0, d)), top, px(std::pow(10.0, d)), bottom, kGrid);
        const std::string label = decadeLabel(d);
        canvas.text(px(std::pow(10.0, d)) - 0.5 * Canvas::textWidth(label), bottom + 6, label, kBlack);
    }
    for (int d = eLo; d <= eHi; ++d) {
        canvas.line(left, py(std::pow(10.0, d)), right, py(std::pow(10.0, d)), kGrid);
        if ((d - eLo) % eStride) continue;
        const std::string label = decadeLabel(d);
        canvas.text(left - 6 - Canvas::textWidth(label), py(std::pow(10.0, d)) - 6, label, kBlack);
    }
    for (double budget : {0.01, 0.001})
        if (budget > std::pow(10.0, eLo) && budget < std::pow(10.0, eHi))
            canvas.line(left, py(budget), right, py(budget), kBudget, 1.0, 4.0);
    canvas.line(left, bottom, right, bottom, kAxis, 1.5);
    canvas.line(left, top, left, bottom, kAxis, 1.5);
    canvas.text(0.5 * (left + right) - 0.5 * Canvas::textWidth("run time (s)"), bottom + 24, "run time (s)", kAxis);

    // Curves: runs of one integrator, step policy and sweep, in sweep order
    // (step from coarse to fine, grid and photons upward).
    std::map<std::string, std::vector<const RunRecord*>> curves;
    for (const RunRecord* r : runs)
        if (r->measurement.error > 0.0 && r->runtimeSeconds > 0.0)
            curves[curveLabel(r->settings) + "/" + r->settings.sweep].push_back(r);
    for (const auto& [key, points] : curves) {
        const Colour colour = curveColour(points.front()->settings);
        // The step sweep of each integrator, and the wavefront's split sweep: solid.
        const bool stepSweep = points.front()->settings.sweep == "step" || points.front()->settings.sweep == "wavefront";
        for (std::size_t i = 1; i < points.size(); ++i)
            canvas.line(px(points[i - 1]->runtimeSeconds), py(points[i - 1]->measurement.error), px(points[i]->runtimeSeconds),
                        py(points[i]->measurement.error), colour, stepSweep ? 2.0 : 1.0, stepSweep ? 0.0 : 3.0);
        for (const RunRecord* p : points)
            canvas.marker(px(p->runtimeSeconds), py(p->measurement.error), sweepMarker(p->settings.sweep), colour, 7.0);
    }
}

}  // namespace

void writeErrorPlot(const std::filesystem::path& file, const std::vector<RunRecord>& records) {
    std::vector<std::string> names;
    for (const auto& r : records)
        if (std::find(names.begin(), names.end(), r.measurement.caseName) == names.end())
            names.push_back(r.measurement.caseName);
    constexpr int kColumns = 4, kPanelW = 420, kPanelH = 320, kLegendH = 90;
    const int rows = std::max(1, (static_cast<int>(names.size()) + kColumns - 1) / kColumns);
    Canvas canvas(kColumns * kPanelW, rows * kPanelH + kLegendH, {255, 255, 255});
    for (std::size_t i = 0; i < names.size(); ++i) {
        std::vector<const RunRecord*> runs;
        for (const auto& r : records)
            if (r.measurement.caseName == names[i]) runs.push_back(&r);
        drawPanel(canvas, static_cast<double>(i % kColumns) * kPanelW, static_cast<double>(i / kColumns) * kPanelH,
                  kPanelW, kPanelH, names[i], runs);
    }
    // Legend: colours (integrator, step policy), markers (what the curve sweeps).
    const double legendTop = rows * kPanelH + 10;
    double x = 20;
    using I = TracerDesc::Integrator;
    using P = TracerDesc::StepPolicy;
    const std::pair<RunSettings, const char*> colours[] = {
        {{.integrator = I::Euler}, "euler uniform"},
        {{.integrator = I::Leapfrog}, "leapfrog uniform"},
        {{.integrator = I::Rk4}, "rk4 uniform"},
        {{.integrator = I::Leapfrog, .stepPolicy = P::Octree}, "leapfrog octree"},
        {{.integrator = I::Rk4, .stepPolicy = P::Octree}, "rk4 octree"},
        {{.estimator = TracerDesc::Estimator::Wavefront}, "wavefront"}};
    for (const auto& [settings, label] : colours) {
        canvas.line(x, legendTop + 8, x + 28, legendTop + 8, curveColour(settings), 2.0);
        canvas.text(x + 36, legendTop + 2, label, kBlack);
        x += 60 + Canvas::textWidth(label);
    }
    x = 20;
    const std::pair<const char*, const char*> markers[] = {{"step", "step sweep (solid)"},
                                                           {"grid", "grid resolution"},
                                                           {"smoothing", "smoothing width"},
                                                           {"octree", "octree eps, eps', cap"},
                                                           {"photons", "photon count"}};
    for (const auto& [sweep, label] : markers) {
        canvas.marker(x + 8, legendTop + 38, sweepMarker(sweep), kAxis, 9.0);
        canvas.text(x + 22, legendTop + 32, label, kBlack);
        x += 50 + Canvas::textWidth(label);
    }
    canvas.line(x, legendTop + 38, x + 28, legendTop + 38, kBudget, 1.0, 4.0);
    canvas.text(x + 36, legendTop + 32, "1% and 0.1% error", kBlack);
    canvas.text(20, legendTop + 60,
                "error (dimensionless) against run time of the light pass (s), log-log; dashed: one knob "
                "at a fine step; brown: the wavefront's split",
                kAxis);
    io::writePng(file, canvas.width(), canvas.height(), canvas.rgba());
}

}  // namespace eikon::accuracy
