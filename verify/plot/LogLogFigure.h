// Error-against-run-time figures: panels of log–log curves with decade
// tick labels, light grid, dashed guide lines and a legend, drawn by PLplot
// and written as PNG and SVG (its cairo drivers) beside each other, each
// atomically. `eikon accuracy` and `eikon converge` draw with it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace eikon::plot {

struct Colour {
    int r = 0, g = 0, b = 0;
};

enum class Marker { None, Square, Triangle, Cross, Diamond, Circle };

struct Curve {
    std::vector<double> x, y;  // positive; others are left out
    Colour colour;
    Marker marker = Marker::Square;
    bool dashed = false;
    double width = 2.0;
};

struct Panel {
    std::string title;
    std::vector<Curve> curves;
    std::vector<double> guides;  // horizontal dashed lines (error budgets)
};

struct LegendEntry {
    std::string text;
    Colour colour;
    Marker marker = Marker::None;
    bool line = true;
    bool dashed = false;
};

struct Figure {
    std::vector<Panel> panels;
    int columns = 1;
    int panelWidth = 420, panelHeight = 320;  // pixels of the PNG
    std::string xLabel, yLabel;
    std::vector<std::vector<LegendEntry>> legendRows;
    std::string caption;
};

// Writes `png` and the same figure as `png` with the extension .svg.
// Throws std::runtime_error naming the file where PLplot cannot write it.
void writeFigure(const std::filesystem::path& png, const Figure& figure);

}  // namespace eikon::plot
