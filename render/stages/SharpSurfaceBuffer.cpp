#include "render/stages/SharpSurfaceBuffer.h"

#include "bridge/core/Error.h"

#include <utility>

namespace eikon::render {

std::vector<layout::GpuSharpSurface> buildSharpSurfaces(const Scene& scene) {
    std::vector<layout::GpuSharpSurface> surfaces;
    int meshes = 0;
    for (const ObjectDesc& object : scene.objects) {
        if (!object.isSharp()) continue;
        layout::GpuSharpSurface surface{};
        if (object.kind == ObjectDesc::Kind::Sphere) {
            surface.shapeA = glm::vec4(glm::vec3(object.sphere.center), layout::kSharpSphere);
            surface.shapeB = glm::vec4(static_cast<float>(object.sphere.radius), 0.0f, 0.0f, 0.0f);
        } else if (object.kind == ObjectDesc::Kind::Box) {
            surface.shapeA = glm::vec4(glm::vec3(object.box.min), layout::kSharpBox);
            surface.shapeB = glm::vec4(glm::vec3(object.box.max), 0.0f);
        } else {
            EIKON_CHECK(object.hasTriangleSurface());
            surface.shapeA = glm::vec4(0.0f, 0.0f, 0.0f, layout::kSharpTriangles);
            surface.shapeB = glm::vec4(0.0f, 0.0f, 0.0f, static_cast<float>(meshes++));  // roots come first
        }
        surface.optics = glm::vec4(static_cast<float>(object.material.index - scene.medium.index),
                                   object.fresnel ? 1.0f : 0.0f, 0.0f, 0.0f);
        surfaces.push_back(surface);
    }
    EIKON_CHECK(surfaces.size() <= static_cast<std::size_t>(layout::kMaxSharpObjects));
    return surfaces;
}

bool hasTriangleSurfaces(const std::vector<layout::GpuSharpSurface>& surfaces) {
    for (const layout::GpuSharpSurface& surface : surfaces)
        if (static_cast<int>(surface.shapeA.w + 0.5f) == layout::kSharpTriangles) return true;
    return false;
}

SharpSurfaceBuffer::SharpSurfaceBuffer(const Scene& scene) : SharpSurfaceBuffer(buildSharpSurfaces(scene)) {}

SharpSurfaceBuffer::SharpSurfaceBuffer(std::vector<layout::GpuSharpSurface> surfaces) : surfaces_(std::move(surfaces)) {
    EIKON_CHECK(surfaces_.size() <= static_cast<std::size_t>(layout::kMaxSharpObjects));
    if (surfaces_.empty()) return;
    std::vector<layout::GpuSharpSurface> block(surfaces_);  // the uniform block's whole array
    block.resize(layout::kMaxSharpObjects);
    buffer_ = gl::Buffer(block.size() * sizeof(layout::GpuSharpSurface), block.data());
}

void SharpSurfaceBuffer::bind() const {
    if (!surfaces_.empty()) buffer_.bindUniform(layout::kSharpSurfaces);
}

}  // namespace eikon::render
