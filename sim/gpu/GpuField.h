// A GridField on the GPU: the same lattice (size and offset of sample
// (0, 0, 0)), its samples as float32 in a shader storage buffer, x fastest,
// so that index (i, j, k) means the same sample on both sides. Fields that
// sit far from zero are stored as an offset from a reference value (the
// temperature as T − T_ambient), which float32 then resolves as finely as
// it resolves the change, as δn does for the index (docs/architecture.md).
#pragma once

#include "gl/GlObjects.h"
#include "sim/field/GridField.h"

#include <string>

namespace eikon::sim::gpu {

class GpuField {
public:
    GpuField() = default;
    // `what` names the field in GPU-memory errors ("sim.resolution: temperature").
    GpuField(glm::ivec3 size, glm::dvec3 offset, const gl::GpuResource& resource);
    // A field shaped like `layout`, its values uploaded.
    GpuField(const GridField& layout, const gl::GpuResource& resource, double reference = 0.0);

    glm::ivec3 size() const { return size_; }
    glm::dvec3 offset() const { return offset_; }
    std::size_t count() const { return static_cast<std::size_t>(size_.x) * size_.y * size_.z; }
    // The value subtracted on upload and added back on download.
    double reference() const { return reference_; }
    const gl::Buffer& buffer() const { return buffer_; }
    void bind(GLuint binding) const { buffer_.bindStorage(binding); }

    // field.values − reference, rounded to float32; the lattice must match.
    void upload(const GridField& field);
    // The samples + reference into field (resized and reshaped to this lattice).
    void download(GridField& field) const;
    void copyFrom(const GpuField& source) { buffer_.copyFrom(source.buffer_); }

private:
    glm::ivec3 size_{0};
    glm::dvec3 offset_{0.5};
    double reference_ = 0.0;
    gl::Buffer buffer_;
};

// The resource of one solver field, for GPU-memory messages.
gl::GpuResource solverResource(const std::string& what, glm::ivec3 size);

}  // namespace eikon::sim::gpu
