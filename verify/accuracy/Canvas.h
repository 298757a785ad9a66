// An RGBA8 raster with the few primitives a chart needs: rectangles, thick
// and dashed lines, markers and text (stb_easy_font's segment font).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace eikon::accuracy {

struct Colour {
    std::uint8_t r, g, b;
};

class Canvas {
public:
    Canvas(int width, int height, Colour background);

    void fillRect(double x0, double y0, double x1, double y1, Colour colour);
    // A line of `thickness` pixels; dash > 0 draws dash-pixel dashes with equal gaps.
    void line(double x0, double y0, double x1, double y1, Colour colour, double thickness = 1.0, double dash = 0.0);
    enum class Marker { Square, Circle, Triangle, Cross, Diamond };
    void marker(double x, double y, Marker shape, Colour colour, double size);
    // Text with its top-left corner at (x, y), `scale` pixels per font unit.
    void text(double x, double y, const std::string& text, Colour colour, double scale = 2.0);
    static double textWidth(const std::string& text, double scale = 2.0);

    int width() const { return width_; }
    int height() const { return height_; }
    const std::vector<std::uint8_t>& rgba() const { return rgba_; }

private:
    void dot(double x, double y, double radius, Colour colour);
    int width_, height_;
    std::vector<std::uint8_t> rgba_;
};

}  // namespace eikon::accuracy
