#include "apps/library/GpuFieldPass.h"

#include "bridge/core/NumberFormat.h"
#include "bridge/layout/GpuLayouts.h"
#include "eikon/eikon.h"
#include "gl/ShaderLibrary.h"
#include "sim/optics/AirOptics.h"
#include "sim/optics/VolumeOptics.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace eikon::library {

namespace {

// The pass's checks (shaders/caller_fields.comp, CallerChecks), in its order.
enum CallerCheck : std::size_t {
    kTemperatureNotFinite,
    kIndexNotFinite,
    kExtinctionNotFinite,
    kScatteringNotFinite,
    kTemperatureNotPositive,
    kIndexNotPositive,
    kDeltaIndexOutOfRange,
    kExtinctionNegative,
    kScatteringNegative,
    kScatteringAboveExtinction,
    kSmallestTemperature,
    kSmallTemperature,
    kDensityNotFinite,
    kMappedExtinctionNotFinite,
    kMappedScatteringNotFinite,
    kCheckCount
};
constexpr std::uint32_t kNone = 0xffffffffu;
constexpr double kZeroCelsius = 273.15;  // K

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

[[noreturn]] void refuse(const std::string& field, const std::string& expected, const std::string& found) {
    throw Error("eikon::Renderer::setFields: field \"" + field + "\": expected " + expected + ", found " + found);
}

const BufferField* find(const std::vector<BufferField>& buffers, const char* name) {
    const auto it = std::find_if(buffers.begin(), buffers.end(), [&](const BufferField& b) { return b.name == name; });
    return it == buffers.end() ? nullptr : &*it;
}

// A buffer object of the current context holding at least the field's floats.
void checkBuffer(const BufferField& field, std::size_t cells) {
    if (!glIsBuffer(field.buffer))
        refuse(field.name, "the name of a buffer object made in the renderer's context (makeContextCurrent, then "
                           "glCreateBuffers)",
               "the name " + std::to_string(field.buffer) + " naming none");
    GLint64 bytes = 0;
    glGetNamedBufferParameteri64v(field.buffer, GL_BUFFER_SIZE, &bytes);
    const std::uint64_t needed = cells * static_cast<std::size_t>(field.channels) * sizeof(float);
    if (static_cast<std::uint64_t>(bytes) < needed)
        refuse(field.name,
               "a GL buffer of at least " + std::to_string(needed) + " bytes (nz·ny·nx" +
                   (field.channels == 3 ? "·3" : "") + " floats)",
               "buffer " + std::to_string(field.buffer) + " of " + std::to_string(bytes) + " bytes");
}

// Cell `cell`'s values in a caller's buffer: read back for a refusal only.
std::vector<float> valuesAt(GLuint buffer, std::uint32_t cell, int channels) {
    std::vector<float> values(static_cast<std::size_t>(channels));
    glGetNamedBufferSubData(buffer, static_cast<GLintptr>(cell) * channels * static_cast<GLintptr>(sizeof(float)),
                            static_cast<GLsizeiptr>(values.size() * sizeof(float)), values.data());
    return values;
}

}  // namespace

GpuFieldPass::GpuFieldPass(const Scene& scene, double referenceIndex)
    : scene_(scene),
      referenceIndex_(referenceIndex),
      checks_(kCheckCount * sizeof(std::uint32_t), {"the library's GPU path", "its checks"}) {}

const gl::Program& GpuFieldPass::program(const Variant& variant) {
    auto it = programs_.find(variant);
    if (it != programs_.end()) return it->second;
    const auto flag = [](bool on) { return std::string(on ? "1" : "0"); };
    gl::Program made = gl::compileComputeProgram(
        "caller_fields.comp", {{"EIKON_INDEX", flag(variant.temperature || variant.base != 0)},
                               {"EIKON_TEMPERATURE", flag(variant.temperature)},
                               {"EIKON_BASE", std::to_string(variant.base)},
                               {"EIKON_EXTINCTION", std::to_string(variant.extinctionChannels)},
                               {"EIKON_SCATTERING", std::to_string(variant.scatteringChannels)},
                               {"EIKON_DENSITY", flag(variant.density)},
                               {"EIKON_WRITES_EXTINCTION", flag(variant.writesExtinction)},
                               {"EIKON_WRITES_SCATTERING", flag(variant.writesScattering)}});
    return programs_.emplace(variant, std::move(made)).first->second;
}

// What the GPU path leaves to the host: objects and paint composited over
// the fields, and the medium's and volume's terms of κ, σs, g and ε.
void GpuFieldPass::checkScene(const std::vector<BufferField>& buffers, const VolumeDesc& optics) const {
    const BufferField& first = buffers.front();
    if (!scene_.objects.empty() || !scene_.paint.empty())
        refuse(first.name, "values in host memory in a scene with objects or paint (composited over the fields on "
                           "the host)",
               "GL buffer " + std::to_string(first.buffer));
    const BufferField* density = find(buffers, "density");
    const BufferField* extinction = find(buffers, "extinction");
    const BufferField* scattering = find(buffers, "scattering");
    const BufferField* coefficients = density ? density : extinction ? extinction : scattering;
    if (!coefficients) return;
    const std::string inBuffer = "GL buffer " + std::to_string(coefficients->buffer);
    if (positive(scene_.medium.extinction) || positive(scene_.medium.scattering))
        refuse(coefficients->name,
               "values in host memory in a scene whose medium absorbs or scatters (added on the host)", inBuffer);
    if (optics.emission == VolumeDesc::Emission::Blackbody)
        refuse(coefficients->name,
               "values in host memory with volume.emission \"blackbody\" (a cell emits as it absorbs, on the host)",
               inBuffer);
    const bool scatters = scattering || (density && positive(optics.densityScattering));
    if (scatters && (scene_.medium.anisotropy != 0.0 || optics.anisotropy != 0.0))
        refuse(scattering ? "scattering" : "density",
               "values in host memory with an anisotropy g ≠ 0 (σs-weighted on the host)",
               "GL buffer " + std::to_string((scattering ? scattering : density)->buffer));
}

GpuFieldPass::Taken GpuFieldPass::take(const std::vector<BufferField>& buffers, const VolumeDesc& optics) {
    checkScene(buffers, optics);
    const GridSpec grid = scene_.grid.spec();
    const std::size_t cells = grid.cellCount();
    for (const BufferField& field : buffers) checkBuffer(field, cells);
    const BufferField* temperature = find(buffers, "temperature");
    const BufferField* index = find(buffers, "index");
    const BufferField* deltaIndex = find(buffers, "delta_index");
    const BufferField* base = index ? index : deltaIndex;
    const BufferField* extinction = find(buffers, "extinction");
    const BufferField* scattering = find(buffers, "scattering");
    const BufferField* density = find(buffers, "density");
    const bool mapsIndex = temperature || base;
    // κ and σs as the host path has them (writeVolumeOptics, the medium's
    // none): mapped into the pass's buffers beside a density or from a grey
    // field, read where they lie when RGB alone.
    const bool absorbs = extinction || scattering || (density && positive(optics.densityExtinction));
    const bool scatters = scattering || (density && positive(optics.densityScattering));
    const bool mapsCoefficients =
        absorbs && (density || (extinction && extinction->channels == 1) || (scattering && scattering->channels == 1));

    Variant variant;
    variant.temperature = temperature != nullptr;
    variant.base = index ? 1 : deltaIndex ? 2 : 0;
    variant.extinctionChannels = extinction ? extinction->channels : 0;
    variant.scatteringChannels = scattering ? scattering->channels : 0;
    variant.density = density != nullptr;
    variant.writesExtinction = mapsCoefficients;
    variant.writesScattering = mapsCoefficients && scatters;
    const gl::Program& pass = program(variant);
    const GLuint id = pass.id();
    const glm::ivec3 r = grid.resolution;
    glProgramUniform3i(id, pass.uniform("cells"), r.x, r.y, r.z);
    gl::Buffer& target = deltaIndex_[next_];
    if (mapsIndex) {
        // The host path's constants (writeVolumeOptics): Gladstone–Dale at p0 = 1 atm.
        const sim::GladstoneDale air{optics.refractivity, optics.referenceTemperature, 101325.0};
        glProgramUniform1d(id, pass.uniform("ambient_temperature"), optics.ambientTemperature);
        glProgramUniform1d(id, pass.uniform("refractivity"), air.refractivity);
        glProgramUniform1d(id, pass.uniform("reference_temperature"), air.referenceTemperature);
        glProgramUniform1d(id, pass.uniform("reference_pressure"), air.referencePressure);
        glProgramUniform1d(id, pass.uniform("pressure"), optics.pressure);
        glProgramUniform1d(id, pass.uniform("ambient_refractivity"),
                           air.refractivityAt(optics.ambientTemperature, optics.pressure));
        glProgramUniform1d(id, pass.uniform("reference_index"), referenceIndex_);
        if (temperature) {
            glProgramUniform1ui(id, pass.uniform("unit"), static_cast<GLuint>(optics.temperatureUnit));
            glProgramUniform1d(id, pass.uniform("temperature_scale"), optics.temperatureScale);
            glProgramUniform1d(id, pass.uniform("zero_celsius"), kZeroCelsius);
            glProgramUniform1f(id, pass.uniform("absolute_looking"),
                               static_cast<float>(sim::kAbsoluteTemperatureLooking));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kOpticsTemperature, temperature->buffer);
        }
        if (base) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kOpticsConcentration, base->buffer);
        else glProgramUniform1d(id, pass.uniform("medium_delta"), scene_.medium.index - referenceIndex_);
        if (target.bytes() != cells * sizeof(float))
            target = gl::Buffer(cells * sizeof(float), gl::gridResource("the caller's δn", r.x, r.y, r.z));
        target.bindStorage(layout::kOpticsDeltaIndex);
    }
    if (extinction) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kSolverSource, extinction->buffer);
    if (scattering) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kSolverField, scattering->buffer);
    if (density) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kOpticsDye, density->buffer);
        const VolumeRgb& e = optics.densityExtinction;
        const VolumeRgb& s = optics.densityScattering;
        glProgramUniform3d(id, pass.uniform("density_extinction"), e.r, e.g, e.b);
        glProgramUniform3d(id, pass.uniform("density_scattering"), s.r, s.g, s.b);
    }
    const auto mapped = [&](gl::Buffer* pair, const char* what, GLuint binding) {
        gl::Buffer& buffer = pair[next_];
        if (buffer.bytes() != 3 * cells * sizeof(float))
            buffer = gl::Buffer(3 * cells * sizeof(float), gl::gridResource(what, r.x, r.y, r.z));
        buffer.bindStorage(binding);
        return buffer.id();
    };
    const GLuint mappedExtinction =
        variant.writesExtinction ? mapped(extinction_, "the caller's κ", layout::kOpticsExtinction) : 0;
    const GLuint mappedScattering =
        variant.writesScattering ? mapped(scattering_, "the caller's σs", layout::kOpticsScattering) : 0;
    std::array<std::uint32_t, kCheckCount> found{};
    found.fill(kNone);
    found[kSmallTemperature] = 0;
    checks_.upload(found.data(), sizeof found);
    checks_.bindStorage(layout::kSolverPartials);
    pass.use();
    pass.dispatchOverCells(r);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    checks_.download(found.data(), sizeof found);

    // The first failing cell of each check, in the host path's order of checks.
    const auto at = [&](std::uint32_t cell) {
        const auto nx = static_cast<std::uint32_t>(r.x), ny = static_cast<std::uint32_t>(r.y);
        const int i = static_cast<int>(cell % nx), j = static_cast<int>(cell / nx % ny),
                  k = static_cast<int>(cell / (nx * ny));
        return " at cell (i, j, k) = (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) +
               "), " + formatPosition(grid.cellCentre(i, j, k));
    };
    const auto notFinite = [&](const BufferField* field, std::size_t check) {
        if (found[check] == kNone) return;
        const std::vector<float> v = valuesAt(field->buffer, found[check], field->channels);
        const auto it = std::find_if(v.begin(), v.end(), [](float x) { return !std::isfinite(x); });
        const float bad = it == v.end() ? v.front() : *it;
        refuse(field->name, "finite values", std::string(std::isnan(bad) ? "NaN" : "an infinity") + at(found[check]));
    };
    if (temperature) notFinite(temperature, kTemperatureNotFinite);
    if (base) notFinite(base, kIndexNotFinite);
    if (extinction) notFinite(extinction, kExtinctionNotFinite);
    if (scattering) notFinite(scattering, kScatteringNotFinite);
    if (density) notFinite(density, kDensityNotFinite);
    if (found[kTemperatureNotPositive] != kNone) {
        const std::uint32_t cell = found[kTemperatureNotPositive];
        const std::vector<float> sample = valuesAt(temperature->buffer, cell, 1);
        sim::VolumeSamples samples;
        samples.temperature = sample;
        refuse("temperature", "a finite temperature > 0 K (in its unit, eikon::Field::unit)",
               formatRounded(sim::volumeTemperature(optics, samples, 0)) + " K" + at(cell));
    }
    if (found[kIndexNotPositive] != kNone)
        refuse("index", "an index n > 0", formatRounded(valuesAt(index->buffer, found[kIndexNotPositive], 1)[0]) +
                                               at(found[kIndexNotPositive]));
    if (found[kDeltaIndexOutOfRange] != kNone) {
        const std::uint32_t cell = found[kDeltaIndexOutOfRange];
        refuse(base ? base->name : "temperature",
               "a finite index n > 0 (the medium's or the index's, plus n_air(T) − n_air(ambient_temperature) by "
               "Gladstone–Dale)",
               "n = " + formatRounded(referenceIndex_ + valuesAt(target.id(), cell, 1)[0]) + at(cell));
    }
    const auto negative = [&](const BufferField* field, std::size_t check, const char* expected) {
        if (found[check] == kNone) return;
        const std::vector<float> v = valuesAt(field->buffer, found[check], field->channels);
        refuse(field->name, expected, formatRounded(*std::min_element(v.begin(), v.end())) + " /m" + at(found[check]));
    };
    if (extinction) negative(extinction, kExtinctionNegative, "an extinction >= 0 in each channel");
    if (scattering) negative(scattering, kScatteringNegative, "a scattering >= 0 in each channel");
    // κ and σs mapped: past float32, or σs above κ, by their values in the pass's buffers.
    const BufferField* named = density ? density : extinction ? extinction : scattering;
    if (variant.writesExtinction && found[kMappedExtinctionNotFinite] != kNone)
        refuse(named->name, "a finite extinction (density_extinction·ρ + the extinction, in float32)",
               "an extinction past float32" + at(found[kMappedExtinctionNotFinite]));
    if (variant.writesExtinction && found[kMappedScatteringNotFinite] != kNone)
        refuse(named->name, "a finite scattering (density_scattering·ρ + the scattering, in float32)",
               "a scattering past float32" + at(found[kMappedScatteringNotFinite]));
    if ((scattering || variant.writesScattering) && found[kScatteringAboveExtinction] != kNone) {
        const std::uint32_t cell = found[kScatteringAboveExtinction];
        const std::vector<float> sigma =
            valuesAt(variant.writesScattering ? mappedScattering : scattering->buffer, cell, 3);
        const std::vector<float> kappa =
            valuesAt(variant.writesExtinction ? mappedExtinction : extinction->buffer, cell, 3);
        refuse(scattering ? "scattering" : named->name, "scattering <= extinction in each channel",
               "σs (" + formatRounded(sigma[0]) + ", " + formatRounded(sigma[1]) + ", " + formatRounded(sigma[2]) +
                   ") /m above κ (" + formatRounded(kappa[0]) + ", " + formatRounded(kappa[1]) + ", " +
                   formatRounded(kappa[2]) + ") /m" + at(cell));
    }

    Taken taken;
    if (mapsIndex) taken.deltaIndex = target.id();
    taken.extinction = variant.writesExtinction ? mappedExtinction : extinction ? extinction->buffer : 0;
    taken.scattering = variant.writesScattering ? mappedScattering : scattering ? scattering->buffer : 0;
    if (temperature && found[kSmallTemperature] == 0 && found[kSmallestTemperature] != kNone)
        taken.absoluteLookingTemperature = std::bit_cast<float>(found[kSmallestTemperature]);
    return taken;
}

void GpuFieldPass::keep() { next_ = 1 - next_; }

}  // namespace eikon::library
