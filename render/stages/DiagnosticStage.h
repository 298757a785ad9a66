// The diagnostics' pass (shaders/diagnostic_rays.comp): in place of the
// view and post, parallel light from the orthographic camera's image plane
// through the graded field — one march gives each pixel its optical path
// difference and deflection, and its transmittance where the scene has
// extinction — and the scene's instrument (an interferometer or a
// schlieren cut-off, shaders/common/diagnostic_instruments.glsl) makes the
// picture of them. Runs alone when only the camera changes.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/PostStage.h"

#include <glm/vec4.hpp>

#include <vector>

namespace eikon::render {

// What a frame's rays measured, per pixel, row 0 at the top.
struct DiagnosticMeasurements {
    int width = 0, height = 0;
    std::vector<float> deflection;             // rad, 2 per pixel: on the image's right and up axes
    std::vector<float> opticalPathDifference;  // m: ∫ (n − n_ref) ds along the ray
};

class DiagnosticStage {
public:
    // The scene's diagnostic and orthographic camera (checked by the scene parser).
    DiagnosticStage(const Scene& scene, const FieldTextures& fields);

    // Marches every pixel's ray and forms the picture: I/I₀ as a linear
    // camera records it, sRGB-encoded (no exposure, no filmic curve).
    Image8 run(const FieldTextures& fields);
    void setCamera(const CameraDesc& camera);

    std::vector<float> downloadHdr() const;  // linear I/I₀, RGBA per pixel
    DiagnosticMeasurements downloadMeasurements() const;
    // Per pixel (ε right, ε up, OPD, how the ray ended: 1 crossed the grid,
    // 2 missed it, 0 cut by the step cap), as the pass wrote it.
    std::vector<glm::vec4> downloadRays() const;

private:
    RenderDesc render_;
    DiagnosticDesc diagnostic_;
    double stepLength_;
    unsigned maxSteps_;
    gl::Program program_;
    gl::Buffer camera_;
    gl::Buffer rays_;
    gl::Buffer hdr_;
    gl::Buffer ldr_;
};

}  // namespace eikon::render
