#include "sim/gpu/GpuField.h"

#include "bridge/core/Error.h"

#include <string>
#include <vector>

namespace eikon::sim::gpu {

gl::GpuResource solverResource(const std::string& what, glm::ivec3 size) {
    return {"sim.resolution", "the solver's " + what + " over " + std::to_string(size.x) + "×" +
                                  std::to_string(size.y) + "×" + std::to_string(size.z) + " samples"};
}

GpuField::GpuField(glm::ivec3 size, glm::dvec3 offset, const gl::GpuResource& resource)
    : size_(size), offset_(offset), buffer_(count() * sizeof(float), resource) {
    buffer_.clearToZero();
}

GpuField::GpuField(const GridField& layout, const gl::GpuResource& resource, double reference)
    : GpuField(layout.size, layout.offset, resource) {
    reference_ = reference;
    upload(layout);
}

void GpuField::upload(const GridField& field) {
    EIKON_CHECK(field.size == size_ && field.count() == count());
    std::vector<float> values(field.count());
    for (std::size_t s = 0; s < values.size(); ++s) values[s] = static_cast<float>(field.values[s] - reference_);
    buffer_.upload(values.data(), values.size() * sizeof(float));
}

void GpuField::download(GridField& field) const {
    const std::vector<float> values = buffer_.downloadAll<float>();
    field.size = size_;
    field.offset = offset_;
    field.values.resize(values.size());
    for (std::size_t s = 0; s < values.size(); ++s) field.values[s] = static_cast<double>(values[s]) + reference_;
}

}  // namespace eikon::sim::gpu
