// The library's GPU path (eikon::Field::buffer): the caller's fields in GL
// buffers of the renderer's context, taken without a byte crossing to the
// host. The index's fields (temperature, index, δn) are mapped to δn by a
// compute pass (shaders/caller_fields.comp) through the host path's own
// text (shaders/common/gas_index.glsl) into a buffer of the pass's;
// extinction and scattering (RGB) are checked there and copied into their
// textures from where they lie. Every check of the host path is made on the
// GPU; the pass reads back a few words, the first cell failing each.
#pragma once

#include "apps/library/BufferField.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"

#include <map>
#include <optional>
#include <tuple>
#include <vector>

namespace eikon::library {

class GpuFieldPass {
public:
    // For `scene` (its grid and medium) with reference index n_ref.
    GpuFieldPass(const Scene& scene, double referenceIndex);

    // The outcome of one frame's buffers: δn's buffer (0: the index is the
    // host's), the caller's extinction and scattering buffers (0: none), and
    // the smallest nonzero temperature where every nonzero one is at least
    // kAbsoluteTemperatureLooking (for the renderer's refusal of an
    // undeclared absolute temperature; none otherwise).
    struct Taken {
        GLuint deltaIndex = 0, extinction = 0, scattering = 0;
        std::optional<float> absoluteLookingTemperature;
    };
    // Checks and maps `buffers` (the renderer's context current) with the
    // scene's `volume` keys `optics`. eikon::Error naming the field, what
    // was expected and what was found (the cell and its value): nothing of
    // the last frame taken is changed then.
    Taken take(const std::vector<BufferField>& buffers, const VolumeDesc& optics);
    // The frame taken is the renderer's: the next take writes δn elsewhere.
    void keep(const Taken& taken);

private:
    const gl::Program& program(bool temperature, int base, bool extinction, bool scattering);
    void checkScene(const std::vector<BufferField>& buffers, const VolumeDesc& optics) const;

    Scene scene_;
    double referenceIndex_;
    std::map<std::tuple<bool, int, bool, bool>, gl::Program> programs_;
    // δn into one buffer while the other holds the last frame kept: a
    // refused frame leaves it.
    gl::Buffer deltaIndex_[2];
    int next_ = 0;
    gl::Buffer checks_;
};

}  // namespace eikon::library
