// The library's GPU path (eikon::Field::buffer): δn handed as an OpenGL
// buffer made in the renderer's context renders as the same δn handed from
// host memory, bit for bit, and no byte of it crosses to the host (the
// report's host_bytes_copied); each wrong buffer is refused. On llvmpipe the
// "GPU" is the same memory, but the path — a buffer object copied into the
// texture by the driver, never read by eikon — is the one a GPU takes.
#include "eikon/eikon.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

constexpr int kCells = 32;
constexpr std::size_t kCount = std::size_t{kCells} * kCells * kCells;

const char* const kScene = R"({
  "grid": {"bounds": {"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}, "resolution": [32, 32, 32]},
  "lights": [{"type": "directional", "direction": [0.1, -1, 0.05], "irradiance": [1, 1, 1]}],
  "receivers": [{"type": "plane", "point": [0.25, -0.05, 0.25], "normal": [0, 1, 0], "albedo": 0.8,
                 "size": 0.6, "resolution": 24}],
  "camera": {"position": [0.25, 0.6, 1.4], "target": [0.25, 0.1, 0.25], "fov_deg": 40},
  "render": {"width": 40, "height": 32, "photons": 20000, "seed": 3}
})";

// A lens-like bump of δn about the grid's centre, scaled by `strength`.
std::vector<float> bump(double strength) {
    std::vector<float> values;
    const double h = 0.5 / kCells;
    for (int k = 0; k < kCells; ++k)
        for (int j = 0; j < kCells; ++j)
            for (int i = 0; i < kCells; ++i) {
                const double x = (i + 0.5) * h - 0.25, y = (j + 0.5) * h - 0.25, z = (k + 0.5) * h - 0.25;
                values.push_back(static_cast<float>(strength * std::exp(-(x * x + y * y + z * z) / 0.0064)));
            }
    return values;
}

eikon::Field deltaIndex(const eikon::Renderer& renderer, const std::vector<float>* host, unsigned buffer) {
    const eikon::Grid grid = renderer.grid();
    eikon::Field field{"delta_index", host ? host->data() : nullptr, {kCells, kCells, kCells}, 1,
                       grid.boundsMin, grid.boundsMax};
    field.buffer = buffer;
    return field;
}

// A buffer object in the renderer's context holding `values`: the caller's
// (its solver's) own upload, as a GPU solver's output would lie there.
GLuint bufferOf(const eikon::Renderer& renderer, const std::vector<float>& values) {
    renderer.makeContextCurrent();
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferData(buffer, static_cast<GLsizeiptr>(values.size() * sizeof(float)), values.data(), GL_DYNAMIC_DRAW);
    return buffer;
}

nlohmann::json report(const eikon::Renderer& renderer) { return nlohmann::json::parse(renderer.report()); }

TEST(LibraryGpu, ABufferRendersAsTheSameHostArrayWithoutAHostCopy) {
    eikon::Renderer host = eikon::Renderer::fromJson(kScene);
    eikon::Renderer device = eikon::Renderer::fromJson(kScene);
    std::vector<float> values = bump(0.01);
    const GLuint buffer = bufferOf(device, values);

    for (int frame = 0; frame < 2; ++frame) {  // the second: a solver's next step, written in place
        if (frame == 1) {
            values = bump(0.02);
            device.makeContextCurrent();
            glNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(kCount * sizeof(float)), values.data());
        }
        host.setFields({deltaIndex(host, &values, 0)});
        host.render();
        device.setFields({deltaIndex(device, nullptr, buffer)});
        device.render();
        EXPECT_EQ(device.image().values, host.image().values) << "frame " << frame;
        EXPECT_EQ(device.radiance().values, host.radiance().values) << "frame " << frame;
        EXPECT_EQ(device.receiver(0).values, host.receiver(0).values) << "frame " << frame;
        EXPECT_EQ(report(device).at("photons"), report(host).at("photons")) << "frame " << frame;
    }
    // The steady frame: the host array's δn crosses the bus, the buffer's stays on the GPU.
    const nlohmann::json fromHost = report(host), fromBuffer = report(device);
    std::printf("second frame: host array %llu host bytes, %llu GPU bytes; GL buffer %llu host bytes, %llu GPU bytes\n",
                fromHost.at("host_bytes_copied").get<unsigned long long>(),
                fromHost.at("gpu_bytes_copied").get<unsigned long long>(),
                fromBuffer.at("host_bytes_copied").get<unsigned long long>(),
                fromBuffer.at("gpu_bytes_copied").get<unsigned long long>());
    EXPECT_GE(fromHost.at("host_bytes_copied").get<std::uint64_t>(), kCount * sizeof(float));
    EXPECT_EQ(fromBuffer.at("host_bytes_copied").get<std::uint64_t>(), 0u);
    EXPECT_GE(fromBuffer.at("gpu_bytes_copied").get<std::uint64_t>(), kCount * sizeof(float));
    EXPECT_EQ(fromBuffer.at("caller_fields").at("host_bytes_copied").get<std::uint64_t>(), 0u);

    // Not two empty frames: the bump's caustic lies on the receiver.
    const std::vector<float> map = device.receiver(0).values;
    float lo = map[0], hi = map[0];
    for (std::size_t t = 0; t < map.size(); t += 3) lo = std::min(lo, map[t]), hi = std::max(hi, map[t]);
    EXPECT_GT(hi / lo, 1.2f);
    device.makeContextCurrent();
    glDeleteBuffers(1, &buffer);
}

void expectRefused(eikon::Renderer& renderer, const eikon::Field& field, const std::vector<std::string>& words) {
    try {
        renderer.setFields({field});
        FAIL() << "accepted";
    } catch (const eikon::Error& error) {
        for (const std::string& word : words)
            EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what() << " lacks " << word;
    }
}

TEST(LibraryGpu, AWrongBufferIsRefused) {
    eikon::Renderer renderer = eikon::Renderer::fromJson(kScene);
    const std::vector<float> values = bump(0.01);
    const GLuint small = bufferOf(renderer, std::vector<float>(kCount / 2));
    expectRefused(renderer, deltaIndex(renderer, nullptr, small), {"\"delta_index\"", "131072 bytes", "65536 bytes"});
    expectRefused(renderer, deltaIndex(renderer, nullptr, small + 1000), {"\"delta_index\"", "naming none"});
    expectRefused(renderer, deltaIndex(renderer, &values, small), {"\"delta_index\"", "not both"});
    eikon::Field temperature = deltaIndex(renderer, nullptr, small);
    temperature.name = "temperature";
    expectRefused(renderer, temperature, {"\"temperature\"", "host memory", "delta_index only"});
    std::string withObject = kScene;
    withObject.insert(withObject.rfind('}'),
                      R"(, "objects": [{"type": "sphere", "center": [0.25, 0.25, 0.25], "radius": 0.1,
                                       "index": 1.5}])");
    eikon::Renderer objects = eikon::Renderer::fromJson(withObject);
    const GLuint whole = bufferOf(objects, values);
    expectRefused(objects, deltaIndex(objects, nullptr, whole), {"\"delta_index\"", "objects or paint"});
    renderer.makeContextCurrent();
    glDeleteBuffers(1, &small);
    glDeleteBuffers(1, &whole);
}

}  // namespace
