#include "render/stages/ReceiverMaps.h"

#include "bridge/core/Error.h"
#include "bridge/scene/ReceiverAxes.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"

#include <cstdint>

namespace eikon::render {

std::vector<layout::GpuReceiver> buildReceivers(const std::vector<ReceiverDesc>& receivers) {
    std::vector<layout::GpuReceiver> result;
    unsigned firstTexel = 0;
    for (const auto& desc : receivers) {
        const auto [normal, axisU, axisV] = receiverAxes(desc);
        const double texelEdge = desc.size / desc.resolution;
        layout::GpuReceiver receiver{};
        receiver.origin = glm::vec4(glm::vec3(desc.point), static_cast<float>(desc.size));
        receiver.normal = glm::vec4(glm::vec3(normal), static_cast<float>(texelEdge * texelEdge));
        receiver.axisU = glm::vec4(glm::vec3(axisU), 0.0f);
        receiver.axisV = glm::vec4(glm::vec3(axisV), 0.0f);
        receiver.albedo = glm::vec4(glm::vec3(desc.albedo), 0.0f);
        receiver.map = glm::uvec4(firstTexel, static_cast<unsigned>(desc.resolution), desc.bounce ? 1u : 0u, 0u);
        firstTexel += static_cast<unsigned>(desc.resolution * desc.resolution);
        result.push_back(receiver);
    }
    return result;
}

ReceiverMaps::ReceiverMaps(const std::vector<ReceiverDesc>& receivers) : receivers_(buildReceivers(receivers)) {
    for (const auto& desc : receivers)
        kernelRadius_.push_back(desc.filter == ReceiverDesc::Filter::Binomial   ? 1
                                : desc.filter == ReceiverDesc::Filter::Adaptive ? kAdaptiveKernel
                                                                                : 0);
    for (const auto& receiver : receivers_) texelCount_ += receiver.map.y * receiver.map.y;
    const std::size_t texels = texelCount_;
    EIKON_CHECK(receivers_.size() <= static_cast<std::size_t>(layout::kMaxReceivers));  // the scene parser's limit
    std::vector<layout::GpuReceiver> block(receivers_);  // the uniform block's whole array
    block.resize(layout::kMaxReceivers);
    geometry_ = gl::Buffer(block.size() * sizeof(layout::GpuReceiver), block.data());
    tallies_ = gl::Buffer(6 * texels * sizeof(std::uint32_t), {"receivers[].resolution", "the receivers' tallies"});
    maps_ = gl::Buffer(3 * texels * sizeof(float), {"receivers[].resolution", "the receivers' maps"});
    mapTexels_ = gl::BufferTexture(maps_, GL_RGB32F, {"receivers[].resolution", "the receivers' maps"});
    tallyTexels_ = gl::BufferTexture(tallies_, GL_RG32UI, {"receivers[].resolution", "the receivers' tallies"});
    for (const int radius : kernelRadius_)
        if (!filterPrograms_.count(radius))
            filterPrograms_.emplace(radius, gl::compileComputeProgram("receiver_filter.comp",
                                                                      {{"EIKON_FILTER_RADIUS", std::to_string(radius)}}));
}

void ReceiverMaps::bind() const {
    geometry_.bindUniform(layout::kReceivers);
    tallies_.bindStorage(layout::kReceiverTallies);
    maps_.bindStorage(layout::kReceiverMaps);
    mapTexels_.bindSampler(layout::kReceiverMapTexture);
}

void ReceiverMaps::dispatchOverTexels(const gl::Program& program) const {
    constexpr std::size_t kRow = 1024;  // texels per row of the dispatch
    glUniform1ui(program.uniform("texel_count"), texelCount_);
    program.dispatchCovering(kRow, (texelCount_ + kRow - 1) / kRow);
}

void ReceiverMaps::filter(const glm::vec3& powerUnit) {
    if (receivers_.empty()) return;
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the passes that tallied wrote a storage buffer
    bind();
    tallyTexels_.bindSampler(layout::kReceiverTallyTexture);
    for (std::size_t r = 0; r < receivers_.size(); ++r) {
        const layout::GpuReceiver& receiver = receivers_[r];
        const gl::Program& program = filterPrograms_.at(kernelRadius_[r]);
        program.use();
        glUniform3f(program.uniform("power_unit"), powerUnit.r, powerUnit.g, powerUnit.b);
        if (kernelRadius_[r] == kAdaptiveKernel)
            glUniform1f(program.uniform("units_per_photon"), static_cast<float>(layout::kPowerUnitsPerPhoton));
        glUniform1ui(program.uniform("first_texel"), receiver.map.x);
        glUniform1i(program.uniform("resolution"), static_cast<GLint>(receiver.map.y));
        glUniform1f(program.uniform("texel_area"), receiver.normal.w);
        program.dispatchCovering(receiver.map.y, receiver.map.y);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkpoint("receiver filter");
}

std::vector<std::uint64_t> ReceiverMaps::downloadTallies() const {
    static_assert(sizeof(std::uint64_t) == 2 * sizeof(std::uint32_t));  // low word first, as on every GL host
    std::vector<std::uint64_t> tallies(tallies_.bytes() / sizeof(std::uint64_t));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (!tallies.empty()) tallies_.download(tallies.data(), tallies.size() * sizeof(std::uint64_t));
    return tallies;
}

void ReceiverMaps::uploadTallies(const std::vector<std::uint64_t>& tallies) {
    EIKON_CHECK_MSG(tallies.size() * sizeof(std::uint64_t) == tallies_.bytes(), "receiver tallies of another size");
    if (!tallies.empty()) tallies_.upload(tallies.data(), tallies.size() * sizeof(std::uint64_t));
}

std::vector<float> ReceiverMaps::download(unsigned receiver) const {
    const auto& map = receivers_.at(receiver).map;
    std::vector<float> irradiance(3 * std::size_t{map.y} * map.y);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    maps_.download(irradiance.data(), irradiance.size() * sizeof(float), 3 * std::size_t{map.x} * sizeof(float));
    return irradiance;
}

}  // namespace eikon::render
