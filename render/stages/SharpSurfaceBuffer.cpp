#include "render/stages/SharpSurfaceBuffer.h"

#include "bridge/core/Error.h"

namespace eikon::render {

std::vector<layout::GpuSharpSurface> buildSharpSurfaces(const Scene& scene) {
    std::vector<layout::GpuSharpSurface> surfaces;
    int layers = 0;
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
            EIKON_CHECK(object.hasDistanceSurface());
            // An empty box until the first bounds arrive.
            surface.shapeA = glm::vec4(0.0f, 0.0f, 0.0f, layout::kSharpDistance);
            surface.shapeB = glm::vec4(0.0f, 0.0f, 0.0f, static_cast<float>(layers++));
        }
        surface.optics = glm::vec4(static_cast<float>(object.material.index - scene.medium.index),
                                   object.fresnel ? 1.0f : 0.0f, 0.0f, 0.0f);
        surfaces.push_back(surface);
    }
    EIKON_CHECK(surfaces.size() <= static_cast<std::size_t>(kMaxSharpObjects));
    return surfaces;
}

SharpSurfaceBuffer::SharpSurfaceBuffer(const Scene& scene) : surfaces_(buildSharpSurfaces(scene)) {
    if (!surfaces_.empty())
        buffer_ = gl::Buffer(surfaces_.size() * sizeof(layout::GpuSharpSurface), surfaces_.data());
}

void SharpSurfaceBuffer::bind(const FieldTextures& fields) {
    if (surfaces_.empty()) return;
    if (fields.surfaceVersion() != boundsVersion_) {
        const std::vector<float>& bounds = fields.surfaceBounds();
        bool changed = false;
        for (layout::GpuSharpSurface& surface : surfaces_) {
            if (static_cast<int>(surface.shapeA.w) != layout::kSharpDistance) continue;
            const auto layer = static_cast<std::size_t>(surface.shapeB.w);
            EIKON_CHECK_MSG((layer + 1) * kSurfaceBoundsFloats <= bounds.size(), "a sharp surface without its distance layer");
            const float* box = bounds.data() + layer * kSurfaceBoundsFloats;
            surface.shapeA = glm::vec4(box[0], box[1], box[2], surface.shapeA.w);
            surface.shapeB = glm::vec4(box[3], box[4], box[5], surface.shapeB.w);
            changed = true;
        }
        if (changed) buffer_.upload(surfaces_.data(), surfaces_.size() * sizeof(layout::GpuSharpSurface));
        boundsVersion_ = fields.surfaceVersion();
    }
    buffer_.bindStorage(layout::kSharpSurfaces);
}

}  // namespace eikon::render
