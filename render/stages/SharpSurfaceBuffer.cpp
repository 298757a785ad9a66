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
    EIKON_CHECK(surfaces.size() <= static_cast<std::size_t>(kMaxSharpObjects));
    return surfaces;
}

SharpSurfaceBuffer::SharpSurfaceBuffer(const Scene& scene) : SharpSurfaceBuffer(buildSharpSurfaces(scene)) {}

SharpSurfaceBuffer::SharpSurfaceBuffer(std::vector<layout::GpuSharpSurface> surfaces) : surfaces_(std::move(surfaces)) {
    if (!surfaces_.empty())
        buffer_ = gl::Buffer(surfaces_.size() * sizeof(layout::GpuSharpSurface), surfaces_.data());
}

void SharpSurfaceBuffer::bind() const {
    if (!surfaces_.empty()) buffer_.bindStorage(layout::kSharpSurfaces);
}

}  // namespace eikon::render
