#include "verify/plot/LogLogFigure.h"

#include "io/files/AtomicFile.h"

#include <plplot/plstream.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace eikon::plot {

namespace {

constexpr Colour kInk{20, 20, 20}, kGrid{222, 222, 222}, kGuide{160, 160, 160}, kQuiet{90, 90, 90};
constexpr int kLegendRowHeight = 24;
constexpr double kCharacterMillimetres = 3.4;
// PLplot's colour map 0 entry redefined for each colour drawn (0 is the background).
constexpr int kDrawingColour = 1;

void useColour(plstream& pls, const Colour& colour) {
    pls.scol0(kDrawingColour, colour.r, colour.g, colour.b);
    pls.col0(kDrawingColour);
}

const char* glyph(Marker marker) {
    switch (marker) {
        case Marker::None: return "";
        case Marker::Square: return "■";
        case Marker::Triangle: return "▲";
        case Marker::Cross: return "×";
        case Marker::Diamond: return "◆";
        case Marker::Circle: return "●";
    }
    return "";
}

struct Decades {
    int low = 0, high = 1;
};

// The decades that hold every positive value of `values`.
Decades decadesOf(const std::vector<double>& values) {
    double smallest = 1e300, largest = 0.0;
    for (double v : values)
        if (v > 0.0 && std::isfinite(v)) smallest = std::min(smallest, v), largest = std::max(largest, v);
    if (largest <= 0.0) return {};
    const int low = static_cast<int>(std::floor(std::log10(smallest)));
    return {low, std::max(low + 1, static_cast<int>(std::ceil(std::log10(largest))))};
}

void drawPanel(plstream& pls, const Panel& panel, const Figure& figure, double x0, double x1, double y0, double y1) {
    std::vector<double> xs, ys;
    for (const Curve& curve : panel.curves)
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i)
            if (curve.x[i] > 0.0 && curve.y[i] > 0.0) xs.push_back(curve.x[i]), ys.push_back(curve.y[i]);
    const Decades t = decadesOf(xs), e = decadesOf(ys);
    pls.vpor(x0, x1, y0, y1);
    pls.wind(t.low, t.high, e.low, e.high);
    useColour(pls, kGrid);
    pls.width(1.0);
    pls.box("gl", 0.0, 0, "gl", 0.0, 0);
    useColour(pls, kGuide);
    pls.lsty(2);
    for (double guide : panel.guides) {
        if (guide <= 0.0 || std::log10(guide) <= e.low || std::log10(guide) >= e.high) continue;
        const PLFLT gx[2] = {static_cast<PLFLT>(t.low), static_cast<PLFLT>(t.high)};
        const PLFLT gy[2] = {std::log10(guide), std::log10(guide)};
        pls.line(2, gx, gy);
    }
    for (const Curve& curve : panel.curves) {
        std::vector<PLFLT> cx, cy;
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i)
            if (curve.x[i] > 0.0 && curve.y[i] > 0.0)
                cx.push_back(std::log10(curve.x[i])), cy.push_back(std::log10(curve.y[i]));
        if (cx.empty()) continue;
        useColour(pls, curve.colour);
        pls.lsty(curve.dashed ? 3 : 1);
        pls.width(curve.width);
        if (cx.size() > 1) pls.line(static_cast<PLINT>(cx.size()), cx.data(), cy.data());
        if (curve.marker != Marker::None) pls.string(static_cast<PLINT>(cx.size()), cx.data(), cy.data(), glyph(curve.marker));
    }
    pls.lsty(1);
    pls.width(1.0);
    useColour(pls, kInk);
    pls.box("bcnlst", 0.0, 0, "bcnlstv", 0.0, 0);
    pls.mtex("t", 1.0, 0.5, 0.5, panel.title.c_str());
    useColour(pls, kQuiet);
    pls.mtex("b", 2.8, 0.5, 0.5, figure.xLabel.c_str());
    pls.mtex("l", 4.2, 0.5, 0.5, figure.yLabel.c_str());
}

constexpr double kCharWidth = 7.5;  // pixels of a legend character, about

double entryWidth(const LegendEntry& entry) { return 60.0 + kCharWidth * static_cast<double>(entry.text.size()); }

// The legend's rows wrapped to `width` pixels, then the caption's lines.
struct LegendLayout {
    std::vector<std::vector<LegendEntry>> rows;
    std::vector<std::string> caption;
    double height() const { return kLegendRowHeight * static_cast<double>(rows.size() + caption.size()) + 10.0; }
};

LegendLayout layoutLegend(const Figure& figure, double width) {
    LegendLayout layout;
    for (const auto& row : figure.legendRows) {
        layout.rows.emplace_back();
        double x = 20.0;
        for (const LegendEntry& entry : row) {
            if (!layout.rows.back().empty() && x + entryWidth(entry) > width) {
                layout.rows.emplace_back();
                x = 20.0;
            }
            layout.rows.back().push_back(entry);
            x += entryWidth(entry);
        }
    }
    const auto perLine = static_cast<std::size_t>(std::max(20.0, (width - 40.0) / kCharWidth));
    std::string line;
    for (std::size_t start = 0; start < figure.caption.size();) {
        std::size_t end = figure.caption.find(' ', start);
        if (end == std::string::npos) end = figure.caption.size();
        const std::string word = figure.caption.substr(start, end - start);
        if (!line.empty() && line.size() + 1 + word.size() > perLine) {
            layout.caption.push_back(line);
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
        start = end + 1;
    }
    if (!line.empty()) layout.caption.push_back(line);
    return layout;
}

// The legend and the caption, in pixel units of the band below the panels.
void drawLegend(plstream& pls, const LegendLayout& layout, double width, double totalHeight) {
    const double band = layout.height();
    pls.vpor(0.0, 1.0, 0.0, band / totalHeight);
    pls.wind(0.0, width, 0.0, band);
    double y = band - 0.6 * kLegendRowHeight;
    for (const auto& row : layout.rows) {
        double x = 20.0;
        for (const LegendEntry& entry : row) {
            useColour(pls, entry.colour);
            if (entry.line) {
                pls.lsty(entry.dashed ? 3 : 1);
                pls.width(2.0);
                const PLFLT lx[2] = {x, x + 28.0}, ly[2] = {y, y};
                pls.line(2, lx, ly);
            }
            if (entry.marker != Marker::None) {
                const PLFLT mx[1] = {x + 14.0}, my[1] = {y};
                pls.string(1, mx, my, glyph(entry.marker));
            }
            pls.lsty(1);
            useColour(pls, kInk);
            pls.ptex(x + 36.0, y, 1.0, 0.0, 0.0, entry.text.c_str());
            x += entryWidth(entry);
        }
        y -= kLegendRowHeight;
    }
    useColour(pls, kQuiet);
    for (const std::string& line : layout.caption) {
        pls.ptex(20.0, y, 1.0, 0.0, 0.0, line.c_str());
        y -= kLegendRowHeight;
    }
}

void render(const Figure& figure, const char* device, const std::filesystem::path& file) {
    const int rows = std::max(1, (static_cast<int>(figure.panels.size()) + figure.columns - 1) / figure.columns);
    const double width = figure.columns * figure.panelWidth;
    const LegendLayout legend = layoutLegend(figure, width);
    const double height = rows * figure.panelHeight + legend.height();
    auto pls = std::make_unique<plstream>();
    pls->sdev(device);
    pls->sfnam(file.c_str());
    pls->spage(0.0, 0.0, static_cast<PLINT>(width), static_cast<PLINT>(height), 0, 0);
    pls->scol0(0, 255, 255, 255);
    pls->init();
    pls->adv(0);
    // PLplot scales its default character height with the page; text of a
    // fixed pixel height reads the same on a figure of any size.
    pls->schr(kCharacterMillimetres, 1.0);
    for (std::size_t i = 0; i < figure.panels.size(); ++i) {
        const double column = static_cast<double>(static_cast<int>(i) % figure.columns);
        const double row = static_cast<double>(static_cast<int>(i) / figure.columns);
        const double top = height - row * figure.panelHeight;
        drawPanel(*pls, figure.panels[i], figure, (column * figure.panelWidth + 72.0) / width,
                  ((column + 1.0) * figure.panelWidth - 16.0) / width, (top - figure.panelHeight + 52.0) / height,
                  (top - 30.0) / height);
    }
    drawLegend(*pls, legend, width, height);
    pls.reset();  // ends the stream: the file is complete
}

}  // namespace

void writeFigure(const std::filesystem::path& png, const Figure& figure) {
    std::filesystem::path svg = png;
    svg.replace_extension(".svg");
    for (const auto& [device, file] : {std::pair{"pngcairo", png}, std::pair{"svgcairo", svg}}) {
        const std::filesystem::path temporary = io::temporaryPathFor(file);
        // PLplot asks for another name on a terminal, then ends the process,
        // where it cannot open its file: the file must open here first.
        if (!std::ofstream(temporary))
            io::commitTemporary(temporary, file, false, "its folder cannot be written");  // throws
        render(figure, device, temporary);
        io::commitTemporary(temporary, file, std::filesystem::exists(temporary) && std::filesystem::file_size(temporary) > 0,
                            "PLplot's " + std::string(device) + " driver wrote nothing");
    }
}

}  // namespace eikon::plot
