#include "apps/eikon/DiagnosticExport.h"

#include "bridge/core/Error.h"

namespace eikon::app {

ExportFrame diagnosticExportFrame(const render::DiagnosticMeasurements& measured, const CameraDesc& camera) {
    const auto pixels = static_cast<std::size_t>(measured.width) * static_cast<std::size_t>(measured.height);
    EIKON_CHECK(measured.deflection.size() == 2 * pixels && measured.opticalPathDifference.size() == pixels);
    const double pixel = camera.widthM / measured.width;  // square: the height follows the image's aspect
    const glm::dvec3 half(0.5 * camera.widthM, 0.5 * pixel * measured.height, 0.0);
    ExportFrame frame{{{measured.width, measured.height, 1}, -half, glm::dvec3(half.x, half.y, pixel)}, {}};
    NamedArray deflection{"deflection", 2, std::vector<float>(2 * pixels), {"rad", ArrayRole::Scalar}};
    NamedArray opd{"optical_path_difference", 1, std::vector<float>(pixels), {"m", ArrayRole::Scalar}};
    for (int row = 0; row < measured.height; ++row) {
        const auto from = static_cast<std::size_t>(row) * measured.width;                         // row 0 at the top
        const auto to = static_cast<std::size_t>(measured.height - 1 - row) * measured.width;     // VTK's y grows upward
        for (std::size_t i = 0; i < static_cast<std::size_t>(measured.width); ++i) {
            deflection.values[2 * (to + i)] = measured.deflection[2 * (from + i)];
            deflection.values[2 * (to + i) + 1] = measured.deflection[2 * (from + i) + 1];
            opd.values[to + i] = measured.opticalPathDifference[from + i];
        }
    }
    frame.arrays.push_back(std::move(deflection));
    frame.arrays.push_back(std::move(opd));
    return frame;
}

}  // namespace eikon::app
