#include "sim/voxelize/Compositor.h"

#include "bridge/core/Error.h"
#include "sim/voxelize/AnalyticVoxelizer.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

namespace {

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

bool anyPositive(const std::vector<ObjectDesc>& objects, Rgb Material::*property) {
    return std::any_of(objects.begin(), objects.end(),
                       [&](const ObjectDesc& object) { return positive(object.material.*property); });
}

void ensureSized(std::vector<float>& field, std::size_t size, float value) {
    if (field.empty()) field.assign(size, value);
}

bool isAnalytic(const ObjectDesc& object) {
    return object.kind == ObjectDesc::Kind::Sphere || object.kind == ObjectDesc::Kind::Box;
}

}  // namespace

void fillMedium(const Scene& scene, FieldSet& fields, const CellBox& region) {
    const std::size_t cells = fields.grid.cellCount();
    EIKON_CHECK_EQ(fields.deltaIndex.size(), cells);
    const Material& medium = scene.medium;
    if (positive(medium.extinction)) ensureSized(fields.extinction, 3 * cells, 0.0f);
    if (positive(medium.scattering)) ensureSized(fields.scattering, 3 * cells, 0.0f);
    if (medium.anisotropy != 0.0) ensureSized(fields.anisotropy, cells, 0.0f);
    fillMedium(scene, viewsOf(fields), region);
}

void fillMedium(const Scene& scene, const FieldViews& fields, const CellBox& region) {
    const Material& medium = scene.medium;
    tbb::parallel_for(region.min.z, region.max.z, [&](int k) {
        for (int j = region.min.y; j < region.max.y; ++j) {
            const float delta = scene.airProfile ? static_cast<float>(airProfileIndex(*scene.airProfile,
                                                                                      fields.grid.cellCentre(0, j, 0).y) -
                                                                      fields.referenceIndex)
                                                 : 0.0f;
            for (int i = region.min.x; i < region.max.x; ++i) {
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                fields.deltaIndex[cell] = delta;
                for (int channel = 0; channel < 3; ++channel) {
                    if (fields.hasExtinction()) fields.extinction[3 * cell + channel] = static_cast<float>(medium.extinction[channel]);
                    if (fields.hasScattering()) fields.scattering[3 * cell + channel] = static_cast<float>(medium.scattering[channel]);
                }
                if (fields.hasAnisotropy()) fields.anisotropy[cell] = static_cast<float>(medium.anisotropy);
            }
        }
    });
}

void paintObjects(const Scene& scene, FieldSet& fields, const CoverageGrids& grids, const CellBox* region) {
    if (scene.objects.empty()) return;
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
        EIKON_CHECK_MSG(isAnalytic(scene.objects[o]) || (o < grids.size() && grids[o] != nullptr),
                        "object " + std::to_string(o) + " is a mesh without a coverage grid");
    const std::size_t cells = fields.grid.cellCount();
    const bool anyAnisotropy = std::any_of(scene.objects.begin(), scene.objects.end(),
                                           [](const ObjectDesc& object) { return object.material.anisotropy != 0.0; });
    if (anyPositive(scene.objects, &Material::extinction)) ensureSized(fields.extinction, 3 * cells, 0.0f);
    if (anyPositive(scene.objects, &Material::scattering)) ensureSized(fields.scattering, 3 * cells, 0.0f);
    if (anyAnisotropy) ensureSized(fields.anisotropy, cells, 0.0f);
    paintObjects(scene, viewsOf(fields), grids, region);
}

void paintObjects(const Scene& scene, const FieldViews& fields, const CoverageGrids& grids, const CellBox* region) {
    if (scene.objects.empty()) return;
    const CellBox box = region ? *region : CellBox::whole(fields.grid);
    tbb::parallel_for(box.min.z, box.max.z, [&](int k) {
        for (int j = box.min.y; j < box.max.y; ++j)
            for (int i = box.min.x; i < box.max.x; ++i) {
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                Material m;
                m.index = fields.referenceIndex + fields.deltaIndex[cell];
                for (int channel = 0; channel < 3; ++channel) {
                    if (fields.hasExtinction()) m.extinction[channel] = fields.extinction[3 * cell + channel];
                    if (fields.hasScattering()) m.scattering[channel] = fields.scattering[3 * cell + channel];
                }
                if (fields.hasAnisotropy()) m.anisotropy = fields.anisotropy[cell];
                bool covered = false;
                for (std::size_t o = 0; o < scene.objects.size(); ++o) {
                    const ObjectDesc& object = scene.objects[o];
                    const double c = isAnalytic(object) ? coverage(object, fields.grid, i, j, k, scene.grid.supersampling)
                                                        : (*grids[o])[cell];
                    if (c <= 0.0) continue;
                    covered = true;
                    // A sharp object's index is not voxelized: the tracer applies it exactly
                    // at its surface (render/stages/SharpSurfaceBuffer.h); its attenuation is.
                    if (!object.isSharp()) m.index += c * (object.material.index - m.index);
                    m.extinction += c * (object.material.extinction - m.extinction);
                    m.scattering += c * (object.material.scattering - m.scattering);
                    m.anisotropy += c * (object.material.anisotropy - m.anisotropy);
                }
                if (!covered) continue;
                fields.deltaIndex[cell] = static_cast<float>(m.index - fields.referenceIndex);
                for (int channel = 0; channel < 3; ++channel) {
                    if (fields.hasExtinction()) fields.extinction[3 * cell + channel] = static_cast<float>(m.extinction[channel]);
                    if (fields.hasScattering()) fields.scattering[3 * cell + channel] = static_cast<float>(m.scattering[channel]);
                }
                if (fields.hasAnisotropy()) fields.anisotropy[cell] = static_cast<float>(m.anisotropy);
            }
    });
}

}  // namespace eikon::sim
