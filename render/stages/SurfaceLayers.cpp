#include "render/stages/SurfaceLayers.h"

#include "bridge/core/Error.h"
#include "bridge/grid/FieldSet.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/ShapeTriangles.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <glm/vec4.hpp>

#include <algorithm>
#include <numeric>

namespace eikon::render {

Viewpoint cameraViewpoint(const CameraDesc& camera, const RenderDesc& render, double nearPlane, double farPlane) {
    const double aspect = static_cast<double>(render.width) / static_cast<double>(render.height);
    const glm::dmat4 projection = glm::perspective(glm::radians(camera.fovDeg), aspect, nearPlane, farPlane);
    const glm::dmat4 view = glm::lookAt(camera.position, camera.target, camera.up);
    Viewpoint viewpoint;
    viewpoint.viewProjection = glm::mat4(projection * view);
    viewpoint.eye = glm::vec3(camera.position);
    viewpoint.axis = glm::vec3(glm::normalize(camera.target - camera.position));
    return viewpoint;
}

SurfaceLayers::SurfaceLayers(int width, int height, const gl::GpuResource& resource)
    : near_(width, height, resource), far_(width, height, resource) {}

void SurfaceLayers::bind() const {
    near_.bindColour(layout::kNearLayerTexture);
    far_.bindColour(layout::kFarLayerTexture);
}

namespace {

// The uniform block ImageSpaceSurfaces: κ per sharp surface, in scene
// order, and its water body (WaterHeightFields) or −1.
gl::Buffer surfaceExtinction(const Scene& scene) {
    std::vector<glm::vec4> extinction;
    const std::vector<int> water = WaterHeightFields::waterOfSurface(scene);
    for (const ObjectDesc& object : scene.objects)
        if (object.isSharp())
            extinction.emplace_back(glm::vec3(object.material.extinction),
                                    static_cast<float>(water[extinction.size()]));
    extinction.resize(layout::kMaxSharpObjects, glm::vec4(0.0f));
    return gl::Buffer(extinction.size() * sizeof(glm::vec4), extinction.data(), GL_DYNAMIC_STORAGE_BIT,
                      {"objects", "the surfaces' extinction"});
}

// The bounds of the scene's spheres (their hulls: ShapeTriangles.h), boxes
// and water bodies (whose triangles wind counter-clockwise seen from
// outside too: sim/deform/WaterSurface) where its sharp surfaces are all
// of these and no two bounds meet; empty otherwise.
std::vector<BoxShape> apartShapeBounds(const Scene& scene) {
    std::vector<BoxShape> bounds;
    for (const ObjectDesc& object : scene.objects) {
        if (!object.isSharp()) continue;
        if (object.kind == ObjectDesc::Kind::Sphere) {
            const glm::dvec3 reach(kSphereHullScale * object.sphere.radius);
            bounds.push_back({object.sphere.center - reach, object.sphere.center + reach});
        } else if (object.kind == ObjectDesc::Kind::Box) {
            bounds.push_back(object.box);
        } else if (object.kind == ObjectDesc::Kind::Water) {
            bounds.push_back(waterHull(object.water));
        } else {
            return {};  // an imported mesh: its triangles' winding is its author's
        }
    }
    for (std::size_t i = 0; i < bounds.size(); ++i)
        for (std::size_t j = i + 1; j < bounds.size(); ++j)
            if (glm::all(glm::lessThanEqual(bounds[i].min, bounds[j].max)) &&
                glm::all(glm::lessThanEqual(bounds[j].min, bounds[i].max)))
                return {};
    return bounds;
}

}  // namespace

void SurfaceRaster::bindSurfaces() const {
    surfaces_.bind();
    extinction_.bindUniform(layout::kImageSpaceSurfaces);
    water_.bind();
}

SurfaceRaster::SurfaceRaster(const Scene& scene)
    : surfaces_(scene), extinction_(surfaceExtinction(scene)), water_(scene),
      layerSurfaces_(WaterHeightFields::hasLayerSurfaces(scene)) {
    for (int exact = 0; exact < 3; ++exact)
        for (int variant = 0; variant < (exact == 2 ? 2 : 3); ++variant)
            programs_[exact][variant] = gl::compileRasterProgram(
                "surface_layers.vert", "surface_layers.frag",
                {{"EIKON_EXACT_SHAPES", std::to_string(exact)},
                 {"EIKON_PEEL", variant == 0 ? "0" : "1"},
                 {"EIKON_NEAR_TEST", variant == 1 ? "1" : "0"}});
    const std::vector<float> shapes = shapeTriangles(scene);
    if (!shapes.empty()) {
        shapes_ = gl::Buffer(shapes.size() * sizeof(float), shapes.data(), GL_DYNAMIC_STORAGE_BIT,
                             {"objects", "the spheres' and boxes' triangles"});
        shapeTexels_ = gl::BufferTexture(shapes_, GL_RGBA32F, {"objects", "the spheres' and boxes' triangles"});
    }
    shapeSurfaces_.resize(layout::kMaxSharpObjects);
    std::iota(shapeSurfaces_.begin(), shapeSurfaces_.end(), 0);
    meshSurfaces_.assign(layout::kMaxSharpObjects, 0);
    waterSurfaces_ = WaterHeightFields::surfaceOfWater(scene);
    waterSurfaces_.resize(layout::kMaxSharpObjects, 0);
    waterOfSurface_ = WaterHeightFields::waterOfSurface(scene);
    waterOfSurface_.resize(layout::kMaxSharpObjects, -1);
    int surface = 0, meshes = 0;
    for (const ObjectDesc& object : scene.objects) {
        if (!object.isSharp()) continue;
        if (object.hasTriangleSurface()) meshSurfaces_[static_cast<std::size_t>(meshes++)] = surface;
        if (object.kind == ObjectDesc::Kind::Water)
            waterTriangles_ += static_cast<std::size_t>(object.water.triangleCount());
        ++surface;
    }
    const std::vector<float> hulls = waterHullTriangles(scene);
    if (!hulls.empty()) {
        waterHulls_ = gl::Buffer(hulls.size() * sizeof(float), hulls.data(), GL_DYNAMIC_STORAGE_BIT,
                                 {"objects", "the water bodies' hulls"});
        waterHullTexels_ = gl::BufferTexture(waterHulls_, GL_RGBA32F, {"objects", "the water bodies' hulls"});
    }
    apartShapeBounds_ = apartShapeBounds(scene);
}

bool SurfaceRaster::drawsFacingFaces(const Viewpoint& view) const {
    if (apartShapeBounds_.empty()) return false;
    if (view.orthographic) return true;  // a light's: its near plane lies before all the refractors
    const glm::dvec3 eye(view.eye);
    return std::none_of(apartShapeBounds_.begin(), apartShapeBounds_.end(), [&](const BoxShape& bounds) {
        return glm::all(glm::greaterThanEqual(eye, bounds.min)) && glm::all(glm::lessThanEqual(eye, bounds.max));
    });
}

void SurfaceRaster::drawTriangles(const gl::Program& program, const Viewpoint& view, std::size_t triangles,
                                  const gl::BufferTexture& texels, const std::vector<int>& surfaceOfOrdinal) const {
    if (triangles == 0) return;
    program.use();
    glUniformMatrix4fv(program.uniform("view_projection"), 1, GL_FALSE, glm::value_ptr(view.viewProjection));
    glUniform3fv(program.uniform("view_eye"), 1, glm::value_ptr(view.eye));
    glUniform3fv(program.uniform("view_axis"), 1, glm::value_ptr(view.axis));
    glUniform1i(program.uniform("view_orthographic"), view.orthographic ? 1 : 0);
    texels.bindSampler(layout::kSurfaceTriangleTexture);
    glUniform1iv(program.uniform("surface_of_ordinal"), layout::kMaxSharpObjects, surfaceOfOrdinal.data());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangles));
}

void SurfaceRaster::draw(const Viewpoint& view, SurfaceLayers& layers, const FieldTextures& fields) {
    water_.update(fields);
    water_.bind();
    GLint previousFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    vertexArray_.bind();
    surfaces_.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // the peel finds front and back; facing faces alone only where drawsFacingFaces
    glDisable(GL_BLEND);
    const bool facingFaces = drawsFacingFaces(view);
    const std::size_t fieldTriangles = surfaceTrianglesIn(fields.surfaceTriangles().bytes());
    EIKON_CHECK_MSG(fieldTriangles >= waterTriangles_, "the field buffers carry the water bodies' triangles after the meshes'");
    const std::size_t meshTriangles = fieldTriangles - waterTriangles_;
    // The far layer serves only the search for exits in the layers, which
    // water bodies do without (their height fields).
    const int peels = layerSurfaces_ ? 2 : 1;
    for (int peel = 0; peel < peels; ++peel) {
        gl::RasterTarget& target = peel == 0 ? layers.near_ : layers.far_;
        target.beginDrawing(glm::vec4(0.0f));
        if (peel == 1) layers.near_.bindColour(layout::kNearLayerTexture);
        if (facingFaces) {
            glEnable(GL_CULL_FACE);
            glCullFace(peel == 0 ? GL_BACK : GL_FRONT);
        }
        const int variant = peel == 0 ? 0 : facingFaces ? 2 : 1;
        drawTriangles(programs_[1][variant], view, surfaceTrianglesIn(shapes_.bytes()), shapeTexels_, shapeSurfaces_);
        drawTriangles(programs_[0][variant], view, meshTriangles, fields.surfaceTriangleTexels(), meshSurfaces_);
        if (waterHulls_.id()) {
            // The hulls' faces away from the viewpoint: they cover the hulls
            // once, seen from outside or in.
            glEnable(GL_CULL_FACE);
            glCullFace(GL_FRONT);
            const gl::Program& water = programs_[2][peel];
            water.use();
            glUniform1iv(water.uniform("water_of_surface"), layout::kMaxSharpObjects, waterOfSurface_.data());
            drawTriangles(water, view, surfaceTrianglesIn(waterHulls_.bytes()), waterHullTexels_, waterSurfaces_);
        }
        glDisable(GL_CULL_FACE);
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    gl::checkpoint("surface layers");
}

}  // namespace eikon::render
