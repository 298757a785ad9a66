// C++ side of the GLSL/C++ shim (GLSL side: shaders/common/glsl_prelude.glsl).
// Including a shared .glsl file after this header compiles the very code the
// GPU runs into namespace eikon::shader, so C++ tests can check it. This
// header includes every shared file but those that need their includer's
// accessors: integrators.glsl (field_at, tests/unit/test_integrators.cpp) and
// the grid passes' kernels (index_smoothing, index_gradient, octree_ranges,
// octree_labels: render/stages/NativePrepare.cpp, NativeStepStructure.cpp)
// and the photon tracer's (photon_tracer and the files it calls:
// render/stages/NativePhotonTrace.cpp); the other files of shaders/common
// declare GPU blocks and are GLSL only.
#pragma once

#include "bridge/layout/GpuLayouts.h"

#include <glm/glm.hpp>

#include <cmath>

#define INOUT(T) T&
#define OUT(T) T&
#define precise

namespace eikon::shader {

using namespace glm;
using uint = glm::uint;
// Constants GLSL is given (gl/ShaderLibrary prepends them).
using layout::kSharpBox;
using layout::kSharpTriangles;
using layout::kSharpSphere;
using layout::kEmitted;
using layout::kAbsorbed;
using layout::kEscaped;
using layout::kReceived;
using layout::kCutOff;
using layout::kBlocked;
using layout::kReflected;
using layout::kRouletteGain;
using layout::kTallyCount;

// GLSL built-ins GLM spells differently.
inline uint floatBitsToUint(float value) { return glm::floatBitsToUint(value); }
inline float uintBitsToFloat(uint value) { return glm::uintBitsToFloat(value); }
inline vec3 xyz_of(vec4 v) { return vec3(v); }
inline vec2 xy_of(vec4 v) { return vec2(v.x, v.y); }
inline vec2 zw_of(vec4 v) { return vec2(v.z, v.w); }

// GLSL has no `inline`: the shared functions get internal linkage instead,
// so any number of translation units may include this header.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {
#include "shaders/common/random.glsl"
#include "shaders/common/ray_step.glsl"
#include "shaders/common/attenuation.glsl"
#include "shaders/common/phase.glsl"
#include "shaders/common/sampling.glsl"
#include "shaders/common/receiver.glsl"
#include "shaders/common/fresnel.glsl"
#include "shaders/common/step_size.glsl"
#include "shaders/common/octree_levels.glsl"
#include "shaders/common/sharp_surfaces.glsl"
#include "shaders/common/footprint_coverage.glsl"
#include "shaders/common/lattice_directions.glsl"
#include "shaders/common/lattice_phase.glsl"
#include "shaders/common/invariant_units.glsl"
#include "shaders/common/stencil_flags.glsl"
#include "shaders/common/caustic_sheets.glsl"
}  // namespace
#pragma GCC diagnostic pop

// Types, with external linkage: C++ code outside this header names them.
#include "shaders/common/octree_label_rule.glsl"

}  // namespace eikon::shader
