#include "render/graph/MemoryEstimate.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "render/graph/FrameRenderer.h"
#include "render/stages/StepStructureStage.h"

#include <algorithm>
#include <string>

namespace eikon::render {

namespace {

using Bytes = std::uint64_t;

Bytes product(Bytes a, Bytes b) { return a * b; }

bool any(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

// The per-frame error estimate (ErrorEstimateStage) keeps three more sets
// of receiver maps (the even half of the photons, the probe's and the
// reference's) and draws two or three more views, each with the
// environment's texture.
bool estimatesErrors(const Scene& scene) {
    return scene.render.method == RenderDesc::Method::Eikonal && scene.render.errorEstimate;
}

Bytes receiverCopies(const Scene& scene) { return estimatesErrors(scene) ? 4 : 1; }

Bytes environmentCopies(const Scene& scene) {
    if (!estimatesErrors(scene)) return 1;
    const bool byBatches = tracesLight(scene, any(scene.medium.scattering)) &&
                           scene.tracer.estimator == TracerDesc::Estimator::Photons;  // a view of the even half
    return byBatches ? 4 : 3;
}

std::string cellsText(const glm::ivec3& r) {
    return std::to_string(r.x) + "×" + std::to_string(r.y) + "×" + std::to_string(r.z) + " cells";
}

// The octree's step pyramid (StepStructureStage): RGBA32F, every level in
// one texture of the grid's own nodes (common/octree_levels.glsl).
Bytes stepPyramidBytes(const glm::ivec3& resolution) {
    const glm::ivec3 size = stepPyramidSize(resolution);
    return 16 * product(product(Bytes(size.x), Bytes(size.y)), Bytes(size.z));
}

// The fields of every cell: δn on the host (FieldSet) and as an R32F texture
// with its RGBA32F gradient (FieldTextures); for the eikonal tracer the
// smoothing's two R32F scratch textures (PrepareStage), the octree's RGBA32F
// step sizes and pyramid, and with the error estimate its reference step
// sizes (StepStructureStage; with uniform steps an octree of its own for
// them, FrameRenderer) — counted as GL memory, where the compute shaders hold
// them; the native grid passes (render.device, StageDevice.h) hold the
// scratch and the pyramid on the host, the same bytes; a medium that attenuates or scatters fills every
// cell with RGB on the host and RGBA32F on the GPU; the lattice holds its
// links' densities twice per channel and an RGB fluence (LatticeScattering),
// in an anisotropic medium also its source's share per link.
MemoryItem gridItem(const Scene& scene) {
    const glm::ivec3 r = scene.grid.resolution;
    const Bytes cells = product(product(Bytes(r.x), Bytes(r.y)), Bytes(r.z));
    Bytes hostPerCell = 4, glPerCell = 4 + 16;
    Bytes gl = 0;
    const bool eikonal = scene.render.method == RenderDesc::Method::Eikonal;
    if (eikonal) {
        if (scene.grid.smoothingSigmaVoxels > 0.0) glPerCell += 2 * 4;
        const bool octree = scene.tracer.stepPolicy == TracerDesc::StepPolicy::Octree;
        if (octree || scene.render.errorEstimate) {
            glPerCell += 16 + (scene.render.errorEstimate ? 16 : 0);
            gl += stepPyramidBytes(r);
        }
    }
    const bool attenuates = any(scene.medium.extinction), scatters = any(scene.medium.scattering);
    if (attenuates) hostPerCell += 12, glPerCell += 16;
    if (scatters) hostPerCell += 12, glPerCell += 16;
    if (eikonal && scatters && scene.tracer.multipleScattering == TracerDesc::MultipleScattering::Lbm)
        glPerCell += (2 * 3 + (scene.medium.anisotropy != 0.0 ? 1 : 0)) * Bytes(scene.tracer.lattice.directions) * 4 + 12;
    return {"grid.resolution", "the fields over " + cellsText(r), cells * hostPerCell, cells * glPerCell + gl};
}

// Per receiver: its tallies (two 32-bit words per channel) and its RGB32F
// map (ReceiverMaps), in each set of maps.
void addReceivers(const Scene& scene, std::vector<MemoryItem>& items) {
    for (std::size_t i = 0; i < scene.receivers.size(); ++i) {
        const Bytes edge = Bytes(scene.receivers[i].resolution);
        items.push_back({"receivers[" + std::to_string(i) + "].resolution",
                         "receiver " + std::to_string(i) + "'s map of " + std::to_string(edge) + "² texels", 0,
                         receiverCopies(scene) * edge * edge * (6 * 4 + 3 * 4)});
    }
}

// The camera's image: the linear RGBA32F image (ViewStage, ImageSpaceView),
// and in image space the pixel list and the camera's two surface layers of
// 20 bytes a pixel (SurfaceLayers).
MemoryItem imageItem(const Scene& scene) {
    const Bytes pixels = product(Bytes(scene.render.width), Bytes(scene.render.height));
    const bool imageSpace = scene.render.method == RenderDesc::Method::ImageSpace;
    return {"render.width × render.height", "the image of " + std::to_string(scene.render.width) + "×" +
                                std::to_string(scene.render.height) + " pixels",
            0, pixels * (16 + (imageSpace ? 4 + 2 * 20 : 0))};
}

// Image space: each light's two surface layers, and the caustic polygons'
// photon landings, triangles and deposits, 48 bytes each, over the map's
// cells in two sheets, each drawn on up to four receivers (CausticPolygons).
MemoryItem causticItem(const Scene& scene) {
    const Bytes texels = Bytes(scene.render.causticMapTexels);
    const Bytes sheets = 2, element = 48;
    const Bytes cells = (texels - 1) * (texels - 1) * sheets;
    const Bytes receivers = std::clamp<Bytes>(scene.receivers.size(), 1, 4);
    const Bytes polygons = texels * texels * sheets * element + cells * 2 * receivers * element +
                           cells * std::max<Bytes>(4, 2 * receivers) * element;
    const Bytes layers = Bytes(scene.lights.size()) * 2 * texels * texels * 20;
    return {"render.caustic_map_texels", "the caustic maps of " + std::to_string(texels) + "² texels", 0,
            polygons + layers};
}

// An HDR environment: the decoded RGBA float image the scene holds, and
// each view's RGBA32F texture of it (ViewStage).
MemoryItem environmentItem(const Scene& scene, const FloatImage& image) {
    const Bytes pixels = product(Bytes(image.width), Bytes(image.height));
    return {"render.environment.path",
            "the environment map of " + std::to_string(image.width) + "×" + std::to_string(image.height) + " pixels",
            pixels * 16, environmentCopies(scene) * pixels * 16};
}

// The wavefront's two refinement levels of patches (WavefrontStage).
MemoryItem wavefrontItem(const Scene& scene) {
    const Bytes patches = Bytes(scene.tracer.wavefront.maxPatches);
    return {"tracer.wavefront.max_patches", std::to_string(patches) + " wavefront patches a level", 0,
            2 * patches * sizeof(layout::GpuWavefrontPatch)};
}

}  // namespace

std::vector<MemoryItem> estimateMemory(const Scene& scene) {
    std::vector<MemoryItem> items{gridItem(scene), imageItem(scene)};
    addReceivers(scene, items);
    if (scene.render.method == RenderDesc::Method::ImageSpace) items.push_back(causticItem(scene));
    if (scene.render.environment.kind == EnvironmentDesc::Kind::Hdr && scene.render.environment.image)
        items.push_back(environmentItem(scene, *scene.render.environment.image));
    if (scene.render.method == RenderDesc::Method::Eikonal && scene.tracer.estimator == TracerDesc::Estimator::Wavefront)
        items.push_back(wavefrontItem(scene));
    return items;
}

void requireMemoryFits(const Scene& scene, const MemoryLimit& limit) {
    if (!limit.bytes) return;
    const std::vector<MemoryItem> items = estimateMemory(scene);
    Bytes total = 0;
    for (const MemoryItem& item : items) total += item.bytes();
    if (total <= limit.bytes) return;
    const MemoryItem& largest = *std::max_element(
        items.begin(), items.end(), [](const MemoryItem& a, const MemoryItem& b) { return a.bytes() < b.bytes(); });
    throw InputError(scene.sourcePath + ": " + largest.keyPath, "sizes whose memory fits " + limit.source,
                     largest.what + ", at least " + mebibytes(largest.bytes()) + " (the scene: " + mebibytes(total) +
                         " in all)");
}

}  // namespace eikon::render
