#include "verify/accuracy/Canvas.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace eikon::accuracy {

Canvas::Canvas(int width, int height, Colour background)
    : width_(width), height_(height), rgba_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    fillRect(0, 0, width, height, background);
}

void Canvas::fillRect(double x0, double y0, double x1, double y1, Colour colour) {
    const int i0 = std::max(0, static_cast<int>(std::lround(std::min(x0, x1))));
    const int i1 = std::min(width_, static_cast<int>(std::lround(std::max(x0, x1))));
    const int j0 = std::max(0, static_cast<int>(std::lround(std::min(y0, y1))));
    const int j1 = std::min(height_, static_cast<int>(std::lround(std::max(y0, y1))));
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            std::uint8_t* p = &rgba_[(static_cast<std::size_t>(j) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(i)) * 4];
            p[0] = colour.r, p[1] = colour.g, p[2] = colour.b, p[3] = 255;
        }
}

void Canvas::dot(double x, double y, double radius, Colour colour) {
    if (radius <= 0.75) {
        fillRect(std::floor(x), std::floor(y), std::floor(x) + 1, std::floor(y) + 1, colour);
        return;
    }
    for (double dy = -radius; dy <= radius; dy += 1.0)
        for (double dx = -radius; dx <= radius; dx += 1.0)
            if (dx * dx + dy * dy <= radius * radius)
                fillRect(std::floor(x + dx), std::floor(y + dy), std::floor(x + dx) + 1, std::floor(y + dy) + 1, colour);
}

void Canvas::line(double x0, double y0, double x1, double y1, Colour colour, double thickness, double dash) {
    const double length = std::hypot(x1 - x0, y1 - y0);
    const int samples = std::max(1, static_cast<int>(std::ceil(length * 2.0)));
    for (int s = 0; s <= samples; ++s) {
        const double t = static_cast<double>(s) / samples;
        if (dash > 0.0 && std::fmod(t * length, 2.0 * dash) >= dash) continue;
        dot(x0 + t * (x1 - x0), y0 + t * (y1 - y0), 0.5 * thickness, colour);
    }
}

void Canvas::marker(double x, double y, Marker shape, Colour colour, double size) {
    const double r = 0.5 * size;
    switch (shape) {
        case Marker::Square: fillRect(x - r, y - r, x + r, y + r, colour); break;
        case Marker::Circle: dot(x, y, r, colour); break;
        case Marker::Triangle:
            for (double dy = -r; dy <= r; dy += 1.0) {
                const double half = r * (dy + r) / (2.0 * r);
                fillRect(x - half, y + dy, x + half, y + dy + 1, colour);
            }
            break;
        case Marker::Cross:
            line(x - r, y - r, x + r, y + r, colour, 2.0);
            line(x - r, y + r, x + r, y - r, colour, 2.0);
            break;
        case Marker::Diamond:
            for (double dy = -r; dy <= r; dy += 1.0) {
                const double half = r - std::abs(dy);
                fillRect(x - half, y + dy, x + half, y + dy + 1, colour);
            }
            break;
    }
}

void Canvas::text(double x, double y, const std::string& text, Colour colour, double scale) {
    std::vector<char> quads(300 * text.size() + 64);  // stb_easy_font: ~270 bytes per character at most
    std::string copy = text;
    const int count = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, quads.data(), static_cast<int>(quads.size()));
    // Each quad is 4 vertices of 16 bytes (x, y, z as float, then RGBA); axis-aligned.
    for (int q = 0; q < count; ++q) {
        float a[2], c[2];  // corners 0 and 2
        std::memcpy(a, &quads[static_cast<std::size_t>(q) * 64], sizeof a);
        std::memcpy(c, &quads[static_cast<std::size_t>(q) * 64 + 32], sizeof c);
        fillRect(x + scale * a[0], y + scale * a[1], x + scale * c[0], y + scale * c[1], colour);
    }
}

double Canvas::textWidth(const std::string& text, double scale) {
    std::string copy = text;
    return scale * stb_easy_font_width(copy.data());
}

}  // namespace eikon::accuracy
