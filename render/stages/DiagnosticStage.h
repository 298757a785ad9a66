// The diagnostics' pass (shaders/diagnostic_rays.comp): in place of the
// view and post, light along the camera's rays through the graded field —
// parallel from the orthographic camera's image plane, or from a
// perspective camera's pinhole for BOS — one march gives each ray its
// optical path difference and deflection, its transmittance where the
// scene has extinction, and where it lands on the shadowgraph's screen or
// BOS's background; the scene's instrument (an interferometer, a schlieren
// cut-off, shaders/common/diagnostic_instruments.glsl; the screen's
// intensity law, shaders/shadowgraph_screen.comp; the random-dot
// background, shaders/common/bos_background.glsl) makes the picture of
// them. render.samples_per_pixel = k² rays a pixel, through the centres of
// a k × k grid over it as the view's (render/stages/PixelSamples.h), each
// pixel the mean of its rays' picture and measurements: a box filter over
// the pixel. The shadowgraph cuts each pixel's square of its beam into
// k × k. The rays refract and reflect at the scene's sharp surfaces as the
// camera's view rays do. Runs alone when only the camera changes.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/PostStage.h"
#include "render/stages/SharpSurfaceBuffer.h"
#include "render/stages/VaryingVoxels.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace eikon::render {

// What a frame's rays measured, per pixel (the mean of its rays), row 0 at the top.
// Each is empty where the instrument does not measure it.
struct DiagnosticMeasurements {
    int width = 0, height = 0;
    std::vector<float> deflection;             // rad, 2 per pixel: on the image's right and up axes
    std::vector<float> opticalPathDifference;  // m: ∫ (n − n_ref) ds along the ray
    std::vector<float> displacement;           // BOS: px, 2 per pixel, on the image's right and up axes
    std::vector<float> irradiance;             // shadowgraph: I/I₀ on the screen, RGB per pixel
};

class DiagnosticStage {
public:
    // The shadowgraph's beam beside the picture on every side, in pixels:
    // light bent onto the picture from at most this far is on it.
    static constexpr std::size_t kBeamMargin = 8;

    // The scene's diagnostic and orthographic camera (checked by the scene
    // parser). The rays march by the camera's leapfrog, or by RK4 for the
    // error estimate's reference march (render/stages/DiagnosticErrorEstimate.h).
    DiagnosticStage(const Scene& scene, const FieldTextures& fields,
                    TracerDesc::Integrator integrator = TracerDesc::Integrator::Leapfrog);

    // Marches every pixel's k² rays and forms the picture: I/I₀ as a linear
    // camera records it, sRGB-encoded (no exposure, no filmic curve).
    Image8 run(const FieldTextures& fields);
    void setCamera(const CameraDesc& camera);
    // Where the fields vary (VaryingVoxels.h): the rays march the box, grown
    // by the reach of the smoothing, the gradient's central differences and
    // the trilinear filter, and cross the rest straight; inside it the
    // leapfrog steps across nodes where the medium is nearly uniform
    // (DiagnosticNodeSteps.h; RK4, the error estimate's reference, keeps
    // its uniform steps). Until set, the whole grid in uniform steps.
    void setVaryingVoxels(const VaryingVoxels& varying);
    // 1: the full picture, k² rays a pixel. s > 1: the viewer's preview
    // while the camera moves, one ray per s×s block of pixels filling the
    // block, as the view's (ViewStage::setPixelStride), about s²·k² times
    // cheaper; the shadowgraph previews with one square a pixel of its beam.
    void setPixelStride(int stride);
    int pixelStride() const { return pixelStride_; }  // as set
    // The stride of the latest picture: as set, but 1 for the shadowgraph.
    int drawnStride() const { return diagnostic_.type == DiagnosticDesc::Type::Shadowgraph ? 1 : pixelStride_; }
    // The rays each pixel of the latest picture averages (the shadowgraph: squares of its beam).
    int raysPerPixel() const { return drawnSide() * drawnSide(); }

    std::vector<float> downloadHdr() const;  // linear I/I₀, RGBA per pixel
    DiagnosticMeasurements downloadMeasurements() const;
    // (ε right, ε up, OPD, how the rays ended: 1 crossed the grid, 2 all
    // missed it, 0 one was cut by the step cap, 3 one was lost: turned back
    // by a sharp surface), as the pass wrote it: per
    // pixel, the mean of its rays; or for the shadowgraph per corner ray of
    // its beam, kBeamMargin pixels wider than the picture on every side, k
    // corners a pixel along each side (k² = render.samples_per_pixel).
    std::vector<glm::vec4> downloadRays() const;
    // Whether the scene has sharp surfaces for the rays to cross.
    bool crossesSharpSurfaces() const { return !surfaces_.empty(); }
    // The pixels of the latest picture with a lost ray (turned back by a
    // sharp surface: it brings no light); for the shadowgraph, the lost
    // corner rays of its beam.
    int lostRays() const;
    // BOS: the background seen without the medium (sRGB, as the picture).
    Image8 downloadReference() const;
    bool hasReference() const { return diagnostic_.type == DiagnosticDesc::Type::Bos; }
    // BOS: the dots' 1/e² diameter on the background, m (0 for the others;
    // unused with an image pattern).
    double dotDiameter() const { return dotDiameter_; }
    // BOS: the background image's width on the background, m (0 without one).
    double patternWidth() const { return patternSize_.x; }

    // The screen's or background's distance from the camera along its axis:
    // the diagnostic's distance behind the grid's farthest corner.
    double planeDepth(const CameraDesc& camera) const;

private:
    // k, or 1 in a preview.
    int drawnSide() const { return pixelStride_ > 1 ? 1 : sampleSide_; }
    // The shadowgraph's corner rays along a side of `pixels` pixels, `side` squares a pixel.
    static std::size_t beamCorners(std::size_t pixels, int side);

    RenderDesc render_;
    DiagnosticDesc diagnostic_;
    CameraDesc cameraDesc_;
    GridSpec grid_;
    SharpSurfaceBuffer surfaces_;
    int sampleSide_;  // k: render.samples_per_pixel = k²
    int pixelStride_ = 1;
    double varyingReach_;  // voxels: how far a voxel's δn and κ reach into the traced medium
    glm::vec3 varyingLow_, varyingHigh_;  // the box the rays march, world coordinates
    bool nodeSteps_;        // the leapfrog: it may step across nearly uniform nodes
    double nodeEpsilon_;    // tracer.epsilon
    bool nodeLevelsSet_ = false;
    gl::Texture3D nodeLevels_;  // per brick, the level of its nearly uniform node (DiagnosticNodeSteps.h)
    int extinctionChannels_;  // 3 where the scene has extinction, else 1 (T = 1)
    int screenChannels_;      // shadowgraph: the channels its screen tallies, 1 where T is grey
    float uniformDelta_ = 0.0f;
    glm::vec3 uniformExtinction_{0.0f};
    double stepLength_;
    unsigned maxSteps_;
    double dotDiameter_ = 0.0;  // BOS, m
    gl::Texture2D pattern_;     // BOS: the background image, where the scene names one
    glm::dvec2 patternSize_{0.0};  // its width and height on the background, m
    gl::Program program_;
    gl::Program deposit_;  // shadowgraph: the screen's two passes
    gl::Program resolve_;
    gl::Buffer camera_;
    gl::Buffer rays_;
    gl::Buffer landing_;    // shadowgraph, BOS
    gl::Buffer reference_;  // BOS
    gl::Buffer screen_;     // shadowgraph
    gl::Buffer hdr_;
    gl::Buffer ldr_;
};

}  // namespace eikon::render
