#include "apps/eikon/DiagnosticExport.h"

#include "bridge/core/Error.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::app {

namespace {

// `values` (components per pixel, row 0 at the top) as a cell array of
// rows from the bottom, VTK's y growing upward.
NamedArray upright(const char* name, const char* unit, int components, const std::vector<float>& values, int width,
                   int height) {
    NamedArray array{name, components, std::vector<float>(values.size()), {unit, ArrayRole::Scalar}};
    const auto rowValues = static_cast<std::size_t>(width) * static_cast<std::size_t>(components);
    for (int row = 0; row < height; ++row)
        std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(row * rowValues), rowValues,
                    array.values.begin() + static_cast<std::ptrdiff_t>((height - 1 - row) * rowValues));
    return array;
}

}  // namespace

ExportFrame diagnosticExportFrame(const render::DiagnosticMeasurements& measured, const CameraDesc& camera) {
    const auto pixels = static_cast<std::size_t>(measured.width) * static_cast<std::size_t>(measured.height);
    // The image plane: metres across an orthographic camera's, radians of view (at unit distance) across a perspective one's.
    const double width = camera.orthographic()
                             ? camera.widthM
                             : 2.0 * std::tan(glm::radians(camera.fovDeg) / 2) * measured.width / measured.height;
    const double pixel = width / measured.width;  // square: the height follows the image's aspect
    const glm::dvec3 half(0.5 * width, 0.5 * pixel * measured.height, 0.0);
    ExportFrame frame{{{measured.width, measured.height, 1}, -half, glm::dvec3(half.x, half.y, pixel)}, {}};
    const struct {
        const char* name;
        const char* unit;
        int components;
        const std::vector<float>& values;
    } arrays[] = {{"deflection", "rad", 2, measured.deflection},
                  {"optical_path_difference", "m", 1, measured.opticalPathDifference},
                  {"displacement", "px", 2, measured.displacement},
                  {"relative_irradiance", "1", 3, measured.irradiance}};
    for (const auto& array : arrays) {
        if (array.values.empty()) continue;
        EIKON_CHECK_EQ(array.values.size(), static_cast<std::size_t>(array.components) * pixels);
        frame.arrays.push_back(
            upright(array.name, array.unit, array.components, array.values, measured.width, measured.height));
    }
    return frame;
}

}  // namespace eikon::app
