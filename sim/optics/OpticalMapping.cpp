#include "sim/optics/OpticalMapping.h"

#include "sim/optics/LiquidOptics.h"

#include <tbb/parallel_for.h>

namespace eikon::sim {

namespace {

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }


}  // namespace

OpticalModel::OpticalModel(const SimDesc& desc)
    : fluid_(desc.fluid),
      air_{desc.refractivity, desc.referenceTemperature, desc.referencePressure},
      pressure_(desc.ambientPressure),
      indexA_(desc.indexA),
      indexB_(desc.indexB),
      mixing_(desc.mixing),
      dyeExtinction_(desc.dyeExtinction),
      dyeScattering_(desc.dyeScattering) {}

double OpticalModel::index(double temperature, double concentration) const {
    if (fluid_ == SimDesc::Fluid::Air) return 1.0 + air_.refractivityAt(temperature, pressure_);
    return mixedIndex(indexA_, indexB_, concentration, mixing_);
}

double ambientDeltaIndex(const SimDesc& desc, double referenceIndex) {
    return OpticalModel(desc).index(desc.ambientTemperature, 0.0) - referenceIndex;
}

bool OpticalModel::absorbs() const { return positive(dyeExtinction_); }
bool OpticalModel::scatters() const { return positive(dyeScattering_); }

void mapOpticalFields(const OpticalModel& model, const SolverScalars& scalars, const FieldViews& fields) {
    const GridSpec& render = fields.grid;
    const glm::dvec3 solverH = scalars.solverGrid.voxelSize();
    const glm::ivec3 r = render.resolution;
    tbb::parallel_for(0, r.z, [&](int k) {
        for (int j = 0; j < r.y; ++j)
            for (int i = 0; i < r.x; ++i) {
                const glm::dvec3 x = render.cellCentre(i, j, k);
                double temperature = scalars.ambientTemperature, concentration = 0.0, dye = 0.0;
                if (scalars.solverGrid.contains(x)) {
                    const glm::dvec3 g = (x - scalars.solverGrid.boundsMin) / solverH - 0.5;
                    temperature = sampleTrilinear(scalars.temperature, g);
                    concentration = sampleTrilinear(scalars.concentration, g);
                    dye = sampleTrilinear(scalars.dye, g);
                }
                const std::size_t cell = render.linearIndex(i, j, k);
                fields.deltaIndex[cell] = static_cast<float>(model.index(temperature, concentration) - fields.referenceIndex);
                const Rgb kappa = model.extinction(dye);
                const Rgb sigma = model.scattering(dye);
                for (int channel = 0; channel < 3; ++channel) {
                    if (fields.hasExtinction()) fields.extinction[3 * cell + channel] = static_cast<float>(kappa[channel]);
                    if (fields.hasScattering()) fields.scattering[3 * cell + channel] = static_cast<float>(sigma[channel]);
                }
            }
    });
}

void writeOpticalFields(const OpticalModel& model, const SolverScalars& scalars, FieldSet& fields) {
    const std::size_t cells = fields.grid.cellCount();
    FieldSet next;
    next.grid = fields.grid;
    next.referenceIndex = fields.referenceIndex;
    next.deltaIndex.resize(cells);
    next.extinction.resize(model.absorbs() ? 3 * cells : 0);
    next.scattering.resize(model.scatters() ? 3 * cells : 0);
    mapOpticalFields(model, scalars, viewsOf(next));
    publishField(fields.deltaIndex, std::move(next.deltaIndex), fields.indexVersion);
    publishField(fields.extinction, std::move(next.extinction), fields.extinctionVersion);
    publishField(fields.scattering, std::move(next.scattering), fields.scatteringVersion);
}

}  // namespace eikon::sim
