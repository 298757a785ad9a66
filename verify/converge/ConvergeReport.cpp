#include "verify/converge/ConvergeReport.h"

#include "verify/plot/LogLogFigure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace eikon::converge {

namespace {

std::string number(double value, const char* format = "%.4g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string optionalNumber(const std::optional<double>& value) { return value ? number(*value) : ""; }

std::string percent(const std::optional<double>& value) {
    return value ? number(100.0 * *value, "%.3g") + "%" : "—";
}

int integratorOrder(TracerDesc::Integrator integrator) {
    switch (integrator) {
        case TracerDesc::Integrator::Euler: return 1;
        case TracerDesc::Integrator::Leapfrog: return 2;
        case TracerDesc::Integrator::Rk4: return 4;
    }
    return 2;
}

// The finest measured rung of `knob` (the scene's own counts as factor 1),
// finer meaning a larger factor of `factor`.
const Measured* finestOf(const Study& study, const std::string& knob, double Refinement::*factor) {
    const Measured* finest = nullptr;
    for (const Measured& m : study.rungs)
        if ((m.rung.knob == knob || m.rung.knob == "scene") && (!finest || m.rung.refinement.*factor > finest->rung.refinement.*factor))
            finest = &m;
    return finest;
}

std::optional<double> scaled(const std::optional<double>& error, double divisor) {
    if (!error || !(divisor > 0.0)) return std::nullopt;
    return *error / divisor;
}

const plot::Colour kKnobColours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14}};

plot::Colour knobColour(const std::string& knob) {
    if (knob == "photons" || knob == "refinement") return kKnobColours[0];
    if (knob == "step") return kKnobColours[1];
    if (knob == "grid") return kKnobColours[2];
    return kKnobColours[3];  // all
}

plot::Marker knobMarker(const std::string& knob) {
    if (knob == "photons" || knob == "refinement") return plot::Marker::Circle;
    if (knob == "step") return plot::Marker::Square;
    if (knob == "grid") return plot::Marker::Triangle;
    return plot::Marker::Diamond;
}

double Refinement::*knobFactor(const std::string& knob) {
    if (knob == "step") return &Refinement::step;
    if (knob == "grid") return &Refinement::grid;
    return &Refinement::photons;  // photons, refinement, all (whose factors move together)
}

}  // namespace

std::optional<Measured> cheapestWithin(const Study& study, double target) {
    std::optional<Measured> cheapest;
    for (const Measured& m : study.rungs)
        if (m.worst() <= target && (!cheapest || m.seconds < cheapest->seconds)) cheapest = m;
    return cheapest;
}

std::vector<OwnError> referenceOwnError(const Study& study) {
    std::vector<OwnError> errors;
    const Refinement& reference = study.reference.rung.refinement;
    if (!study.byWavefront)
        if (const Measured* m = finestOf(study, "photons", &Refinement::photons)) {
            // e² = σ²/N + σ²/N_ref (independent seeds), so E_ref = σ/√N_ref = e/√(N_ref/N + 1).
            const double divisor = std::sqrt(reference.photons / m->rung.refinement.photons + 1.0);
            errors.push_back({"photons",
                              "Monte Carlo noise, ∝ N^-1/2, from the rung at " + m->rung.setting +
                                  " (its other errors counted as noise: an upper bound)",
                              scaled(m->receivers, divisor), scaled(m->image, divisor), scaled(m->fluence, divisor)});
        }
    if (const Measured* m = finestOf(study, "step", &Refinement::step)) {
        // e = C(h^p − h_ref^p), so E_ref = C·h_ref^p = e / ((h/h_ref)^p − 1).
        const int p = integratorOrder(study.integrator);
        const double divisor = std::pow(reference.step / m->rung.refinement.step, p) - 1.0;
        errors.push_back({"step",
                          "Richardson with the integrator's order p = " + std::to_string(p) + " from the rung at " +
                              m->rung.setting + " (an upper bound where that rung's noise exceeds its step error)",
                          scaled(m->receivers, divisor), scaled(m->image, divisor), scaled(m->fluence, divisor)});
    }
    return errors;
}

std::string csvText(const Study& study) {
    std::ostringstream csv;
    csv << "knob,setting,photons_factor,step_factor,grid_factor,run_time_s,"
           "receivers_relative_l1,image_relative_l1,fluence_relative_l1\n";
    const auto row = [&](const Measured& m) {
        csv << m.rung.knob << ",\"" << m.rung.setting << "\"," << number(m.rung.refinement.photons) << ","
            << number(m.rung.refinement.step) << "," << number(m.rung.refinement.grid) << "," << number(m.seconds)
            << "," << optionalNumber(m.receivers) << "," << optionalNumber(m.image) << ","
            << optionalNumber(m.fluence) << "\n";
    };
    for (const Measured& m : study.rungs) row(m);
    row(study.reference);
    return csv.str();
}

std::string markdownText(const Study& study, const std::string& command, const std::string& renderer) {
    std::ostringstream md;
    md << "# Convergence of the scene's frame\n\n`" << command << "` on " << renderer << ": " << study.rungs.size()
       << " settings and the reference in " << number(study.wallSeconds, "%.0f") << " s of a "
       << number(study.budgetSeconds, "%.0f") << " s budget. Errors are " << kMetric
       << " against the reference (" << study.reference.rung.setting << ", another seed), over every texel, pixel "
       << "or cell and channel; run times are the frame's render stages.\n\n";
    md << "![error against run time](converge.png)\n\n## Cheapest setting for an error\n\n"
       << "| target | setting | run time (s) | receivers | image | fluence |\n|---|---|---:|---:|---:|---:|\n";
    for (double target : {0.1, 0.01, 0.001}) {
        const auto pick = cheapestWithin(study, target);
        md << "| " << percent(target) << " | ";
        if (pick)
            md << pick->rung.knob << ": " << pick->rung.setting << " | " << number(pick->seconds) << " | "
               << percent(pick->receivers) << " | " << percent(pick->image) << " | " << percent(pick->fluence) << " |\n";
        else
            md << "not reached by any setting tried | | | | |\n";
    }
    md << "\n## The reference's own error\n\n";
    const auto own = referenceOwnError(study);
    if (own.empty()) md << "Not extrapolated: no knob of known order was measured.\n";
    for (const OwnError& e : own)
        md << "- " << e.knob << ": receivers " << percent(e.receivers) << ", image " << percent(e.image) << ", fluence "
           << percent(e.fluence) << " — " << e.method << ".\n";
    if (study.byWavefront) md << "- refinement: not extrapolated (the wavefront's order in its split threshold is not known).\n";
    md << "- grid: not extrapolated (the order in the grid depends on the field; read it off the grid curve).\n";
    md << "\n## Every setting\n\n| knob | setting | run time (s) | receivers | image | fluence |\n"
       << "|---|---|---:|---:|---:|---:|\n";
    for (const Measured& m : study.rungs)
        md << "| " << m.rung.knob << " | " << m.rung.setting << " | " << number(m.seconds) << " | "
           << percent(m.receivers) << " | " << percent(m.image) << " | " << percent(m.fluence) << " |\n";
    md << "| reference | " << study.reference.rung.setting << " | " << number(study.reference.seconds) << " | | | |\n";
    md << "\n## Left out\n\n";
    for (const std::string& item : study.leftOut) md << "- " << item << "\n";
    md << "- fluence of the grid rungs: their cells are not the reference's.\n";
    return md.str();
}

void writePlot(const Study& study, const std::filesystem::path& folder) {
    plot::Figure figure;
    figure.xLabel = "run time of the frame (s)";
    figure.yLabel = std::string(kMetric) + " error";
    const std::pair<const char*, std::optional<double> Measured::*> outputs[] = {
        {"receivers", &Measured::receivers}, {"image", &Measured::image}, {"fluence", &Measured::fluence}};
    std::vector<std::string> knobs;
    for (const Measured& m : study.rungs)
        if (m.rung.knob != "scene" && std::find(knobs.begin(), knobs.end(), m.rung.knob) == knobs.end())
            knobs.push_back(m.rung.knob);
    for (const auto& [name, error] : outputs) {
        plot::Panel panel{name, {}, {0.1, 0.01, 0.001}};
        for (const std::string& knob : knobs) {
            // The knob's rungs and the scene's own setting, coarse to fine.
            std::map<double, const Measured*> points;
            for (const Measured& m : study.rungs)
                if ((m.rung.knob == knob || m.rung.knob == "scene") && m.*error)
                    points[m.rung.refinement.*knobFactor(knob)] = &m;
            plot::Curve curve{{}, {}, knobColour(knob), knobMarker(knob), knob == "all", 2.0};
            for (const auto& [factor, m] : points) {
                curve.x.push_back(m->seconds);
                curve.y.push_back(*(m->*error));
            }
            if (curve.x.size() > 0) panel.curves.push_back(std::move(curve));
        }
        if (!panel.curves.empty()) figure.panels.push_back(std::move(panel));
    }
    figure.columns = std::max<int>(1, static_cast<int>(figure.panels.size()));
    std::vector<plot::LegendEntry> legend;
    for (const std::string& knob : knobs) legend.push_back({knob, knobColour(knob), knobMarker(knob), true, knob == "all"});
    legend.push_back({"10%, 1%, 0.1%", {160, 160, 160}, plot::Marker::None, true, true});
    figure.legendRows = {legend};
    figure.caption = "each knob refined alone about the scene's own setting (the curves meet there); all: every knob "
                     "together; against the reference " + study.reference.rung.setting;
    plot::writeFigure(folder / "converge.png", figure);
}

}  // namespace eikon::converge
