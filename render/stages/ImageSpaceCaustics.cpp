#include "render/stages/ImageSpaceCaustics.h"

#include "bridge/core/Error.h"
#include "bridge/grid/FieldSet.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/ImageSpaceView.h"
#include "render/stages/PhotonEmission.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eikon::render {

namespace {

// This frame's offset of the photons within their texels (a rotated 2×2 pattern).
glm::vec2 jitterOf(int frame) {
    static constexpr float offsets[kTemporalFrames][2] = {{0.0f, 0.0f}, {0.25f, 0.25f}, {-0.25f, 0.25f}, {0.25f, -0.25f}};
    return {offsets[frame % kTemporalFrames][0], offsets[frame % kTemporalFrames][1]};
}

gl::Program causticsProgram(const Scene& scene, const ReceiverMaps& receivers, int pass) {
    gl::ShaderDefines options = WaterHeightFields::programOptions(scene);
    options.insert({{"EIKON_PASS", std::to_string(pass)}, receivers.countOption()});
    return gl::compileComputeProgram("image_space_caustics.comp", options);
}

}  // namespace

ImageSpaceCaustics::ImageSpaceCaustics(const Scene& scene, ReceiverMaps& receivers, SurfaceRaster& raster)
    : scene_(scene), receivers_(receivers), raster_(raster), lights_(scene.lights),
      directProgram_(causticsProgram(scene, receivers, 0)), photonProgram_(causticsProgram(scene, receivers, 1)),
      polygons_(scene.render.causticMapTexels, receivers) {
    const int texels = scene.render.causticMapTexels;
    for (std::size_t i = 0; i < lights_.size(); ++i)
        layers_.push_back(std::make_unique<SurfaceLayers>(
            texels, texels, gl::GpuResource{"render.caustic_map_texels", "light " + std::to_string(i) + "'s layers"}));
    // W per tally unit: 2^-40 of all the light, so a texel holds 2^24 times all of it.
    Rgb total(0.0);
    double receiverArea = 0.0;
    for (const ReceiverDesc& receiver : scene.receivers) receiverArea += receiver.size * receiver.size;
    for (const LightDesc& light : lights_)
        total += light.kind == LightDesc::Kind::Directional ? light.irradiance * receiverArea : light.power;
    for (int c = 0; c < 3; ++c) powerUnit_[c] = static_cast<float>(std::max(total[c], 1e-20) / std::ldexp(1.0, 40));
}

void ImageSpaceCaustics::setLight(std::size_t index, const LightDesc& light) {
    EIKON_CHECK_MSG(index < lights_.size(), "no such light");
    lights_[index] = light;
    lightFrames_.clear();  // its layers are drawn again
}

std::vector<LightFrame> ImageSpaceCaustics::lightFramesNow(const FieldTextures& fields) const {
    // The refractors: shapes exactly, meshes by their trees' root boxes now.
    std::vector<RefractorExtent> refractors;
    int meshes = 0;
    for (const ObjectDesc& object : scene_.objects) {
        if (!object.isSharp()) continue;
        if (object.kind == ObjectDesc::Kind::Sphere)
            refractors.push_back(RefractorExtent::ofSphere(object.sphere.center, object.sphere.radius));
        else if (object.kind == ObjectDesc::Kind::Box)
            refractors.push_back(RefractorExtent::ofBox(object.box.min, object.box.max));
        else ++meshes;
    }
    if (meshes > 0) {
        std::vector<float> roots(static_cast<std::size_t>(meshes) * kSurfaceNodeFloats);
        fields.surfaceNodes().download(roots.data(), roots.size() * sizeof(float));
        for (int k = 0; k < meshes; ++k) {
            const float* node = roots.data() + static_cast<std::size_t>(k) * kSurfaceNodeFloats;
            refractors.push_back(
                RefractorExtent::ofBox(glm::dvec3(node[0], node[1], node[2]), glm::dvec3(node[4], node[5], node[6])));
        }
    }
    std::vector<LightFrame> frames;
    for (const LightDesc& light : lights_)
        frames.push_back(lightFrameOver(light, refractors, scene_.render.causticMapTexels));
    return frames;
}

void ImageSpaceCaustics::run(const FieldTextures& fields, bool changed) {
    if (changed || frames_ >= kTemporalFrames) {
        receivers_.clearTallies();
        frames_ = 0;
    }
    const bool drawLayers = changed || lightFrames_.size() != lights_.size();
    if (drawLayers) lightFrames_ = lightFramesNow(fields);
    const glm::vec2 jitter = jitterOf(frames_);
    polygons_.clear();
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        const LightDesc& light = lights_[i];
        const LightFrame& frame = lightFrames_[i];
        SurfaceLayers& layers = *layers_[i];
        if (drawLayers) {
            layers.useCorner(frame.texels);
            raster_.draw(frame.view, layers, fields);
        }
        const bool spot = light.kind == LightDesc::Kind::Spot;
        const Rgb intensity = light.kind == LightDesc::Kind::Directional ? light.irradiance
                              : spot ? spotPeakIntensity(light)
                                     : light.power / (4.0 * std::numbers::pi);
        const glm::vec2 versines = spot ? glm::vec2(spotVersines(light)) : glm::vec2(-1.0f, 0.0f);
        fields.bindForTracing();
        receivers_.bind();
        raster_.bindSurfaces();
        layers.bind();
        for (gl::Program* program : {&directProgram_, &photonProgram_}) {
            program->use();
            if (program == &directProgram_ || raster_.hasLayerSurfaces())  // the photons read it in the layers alone
                glUniformMatrix4fv(program->uniform("view_projection"), 1, GL_FALSE,
                                   glm::value_ptr(frame.view.viewProjection));
            glUniform3fv(program->uniform("light_position"), 1, glm::value_ptr(frame.view.eye));
            glUniform3fv(program->uniform("light_axis"), 1, glm::value_ptr(frame.view.axis));
            glUniform1i(program->uniform("light_kind"), spot ? 1 : light.kind == LightDesc::Kind::Point ? 0 : 2);
            glUniform3fv(program->uniform("light_intensity"), 1, glm::value_ptr(glm::vec3(intensity)));
            glUniform3fv(program->uniform("spot_axis"), 1, glm::value_ptr(glm::vec3(glm::normalize(light.direction))));
            glUniform2fv(program->uniform("spot_versines"), 1, glm::value_ptr(versines));
            glUniform2i(program->uniform("layer_size"), layers.width(), layers.height());
            glUniform3fv(program->uniform("power_unit"), 1, glm::value_ptr(powerUnit_));
        }
        directProgram_.use();
        receivers_.dispatchOverTexels(directProgram_);
        photonProgram_.use();
        polygons_.bindVertices({layers.width(), layers.height()});
        glUniform3fv(photonProgram_.uniform("frame_right"), 1, glm::value_ptr(frame.right));
        glUniform3fv(photonProgram_.uniform("frame_up"), 1, glm::value_ptr(frame.up));
        glUniform1f(photonProgram_.uniform("frame_half_extent"), static_cast<float>(frame.halfExtent));
        glUniform2fv(photonProgram_.uniform("jitter"), 1, glm::value_ptr(jitter));
        photonProgram_.dispatchCovering(static_cast<std::size_t>(layers.width()),
                                        static_cast<std::size_t>(layers.height()));
        // The cells read the landings as texels, and their work groups as a command.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        polygons_.drawLight({layers.width(), layers.height()}, powerUnit_);
    }
    polygons_.addAtlasToTallies(powerUnit_);
    ++frames_;
    receivers_.filter(powerUnit_ / static_cast<float>(frames_));
    gl::checkpoint("image-space caustics");
}

}  // namespace eikon::render
