// The library's GPU path (eikon::Field::buffer): each field the path takes
// (δn, index, temperature in each unit, a density, extinction and
// scattering in RGB and grey), handed
// as an OpenGL buffer made in the renderer's context, renders as the same
// field handed from host memory, bit for bit, and no byte of it crosses to
// the host (the report's host_bytes_copied); each wrong buffer, each value
// the host path refuses and each split of fields mapped together is
// refused. On llvmpipe the "GPU" is the same memory, but the path — buffer
// objects mapped by a compute pass and copied into the textures by the
// driver, never read by eikon — is the one a GPU takes.
#include "eikon/eikon.h"
#include "tests/integration/LibraryRefusals.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>  // getpid

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

// One field of a frame: its name, unit and channels, and its values at frame f.
struct Input {
    Input(std::string name_, int channels_, std::function<std::vector<float>(int)> values_, std::string unit_ = {})
        : name(std::move(name_)), channels(channels_), values(std::move(values_)), unit(std::move(unit_)) {}
    std::string name;
    int channels = 1;
    std::function<std::vector<float>(int)> values;
    std::string unit;
};

eikon::Field fieldOf(const eikon::Renderer& renderer, const Input& input, const std::vector<float>* host,
                     unsigned buffer) {
    eikon::Field field = deltaIndex(renderer, host, buffer);
    field.name = input.name;
    field.channels = input.channels;
    field.unit = input.unit;
    return field;
}

// Two frames of `inputs` rendered from host arrays and from GL buffers
// (written anew for the second, as a solver's next step): the same bytes,
// and the buffers' second frame copies no host byte. The radiance the same
// too, or within `radianceTolerance` of its largest value where two renders
// of the scene from host arrays differ.
void expectSameFramesFromBuffers(const std::function<eikon::Renderer()>& makeRenderer, const std::vector<Input>& inputs,
                                 double radianceTolerance = 0.0) {
    eikon::Renderer host = makeRenderer();
    eikon::Renderer device = makeRenderer();
    std::vector<GLuint> buffers;
    for (int frame = 0; frame < 2; ++frame) {
        std::vector<std::vector<float>> values;
        for (const Input& input : inputs) values.push_back(input.values(frame));
        std::vector<eikon::Field> hostFields, deviceFields;
        for (std::size_t f = 0; f < inputs.size(); ++f) {
            if (frame == 0) {
                buffers.push_back(bufferOf(device, values[f]));
            } else {
                device.makeContextCurrent();
                glNamedBufferSubData(buffers[f], 0, static_cast<GLsizeiptr>(values[f].size() * sizeof(float)),
                                     values[f].data());
            }
            hostFields.push_back(fieldOf(host, inputs[f], &values[f], 0));
            deviceFields.push_back(fieldOf(device, inputs[f], nullptr, buffers[f]));
        }
        host.setFields(hostFields);
        host.render();
        device.setFields(deviceFields);
        device.render();
        EXPECT_EQ(device.image().values, host.image().values) << "frame " << frame;
        const std::vector<float> deviceRadiance = device.radiance().values, hostRadiance = host.radiance().values;
        if (radianceTolerance == 0.0) {
            EXPECT_EQ(deviceRadiance, hostRadiance) << "frame " << frame;
        } else {
            ASSERT_EQ(deviceRadiance.size(), hostRadiance.size());
            const float largest = *std::max_element(hostRadiance.begin(), hostRadiance.end());
            for (std::size_t i = 0; i < hostRadiance.size(); ++i)
                ASSERT_NEAR(deviceRadiance[i], hostRadiance[i], radianceTolerance * largest) << "frame " << frame;
        }
        EXPECT_EQ(device.receiver(0).values, host.receiver(0).values) << "frame " << frame;
        EXPECT_EQ(report(device).at("photons"), report(host).at("photons")) << "frame " << frame;
    }
    const nlohmann::json fromHost = report(host), fromBuffer = report(device);
    std::printf("%s, second frame: host arrays %llu host bytes; GL buffers %llu host bytes, %llu GPU bytes\n",
                inputs.front().name.c_str(), fromHost.at("host_bytes_copied").get<unsigned long long>(),
                fromBuffer.at("host_bytes_copied").get<unsigned long long>(),
                fromBuffer.at("gpu_bytes_copied").get<unsigned long long>());
    EXPECT_GT(fromHost.at("host_bytes_copied").get<std::uint64_t>(), 0u);
    EXPECT_EQ(fromBuffer.at("host_bytes_copied").get<std::uint64_t>(), 0u);
    EXPECT_GT(fromBuffer.at("gpu_bytes_copied").get<std::uint64_t>(), 0u);
    EXPECT_EQ(fromBuffer.at("caller_fields").at("host_bytes_copied").get<std::uint64_t>(), 0u);
    device.makeContextCurrent();
    glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
}

void expectSameFramesFromBuffers(const std::string& scene, const std::vector<Input>& inputs,
                                 double radianceTolerance = 0.0) {
    expectSameFramesFromBuffers([&] { return eikon::Renderer::fromJson(scene); }, inputs, radianceTolerance);
}

// The bump as `base` + `scale`·bump, per frame a stronger one, in `channels`
// channels (channel c scaled by 1, 0.8, 0.6).
std::function<std::vector<float>(int)> bumpOf(float base, float scale, int channels = 1) {
    return [=](int frame) {
        const std::vector<float> shape = bump(scale * (frame == 0 ? 1.0 : 1.5));
        std::vector<float> values;
        for (const float v : shape)
            for (int c = 0; c < channels; ++c) values.push_back((base + v) * (1.0f - 0.2f * static_cast<float>(c)));
        return values;
    };
}

TEST(LibraryGpu, AnIndexBufferRendersAsTheSameHostArray) {
    expectSameFramesFromBuffers(kScene, {{"index", 1, bumpOf(1.0f, 0.01f)}});
}

TEST(LibraryGpu, ATemperatureBufferIsMappedOnTheGpuAsOnTheHostInEachUnit) {
    // A 600 K plume in 300 K air: n − 1 by Gladstone–Dale, δn ≈ −1.5e-4.
    expectSameFramesFromBuffers(kScene, {{"temperature", 1, bumpOf(300.0f, 300.0f), "kelvin"}});
    expectSameFramesFromBuffers(kScene, {{"temperature", 1, bumpOf(26.85f, 300.0f), "celsius"}});
    expectSameFramesFromBuffers(kScene, {{"temperature", 1, bumpOf(0.0f, 300.0f)}});  // above ambient, undeclared
    // With an index beside it: both mapped together.
    expectSameFramesFromBuffers(kScene,
                                {{"temperature", 1, bumpOf(0.0f, 300.0f)}, {"delta_index", 1, bumpOf(0.0f, 0.002f)}});
}

// Two renders of the same host arrays of a scattering medium (a smoke, grey
// or RGB scattering) may differ in a radiance value's last bits (one or two
// of 3840 by 1.9e-9, 6e-8 of the largest, in about half the runs on
// llvmpipe): there the radiance is compared to 1e-6 of its largest, the
// image's bytes, the receiver maps and the photon figures exactly.
constexpr double kScatteringRadianceTolerance = 1e-6;

TEST(LibraryGpu, ExtinctionAndScatteringBuffersRenderAsTheSameHostArrays) {
    expectSameFramesFromBuffers(kScene, {{"extinction", 3, bumpOf(0.0f, 4.0f, 3)}});
    expectSameFramesFromBuffers(kScene, {{"extinction", 3, bumpOf(0.1f, 4.0f, 3)},
                                         {"scattering", 3, bumpOf(0.05f, 2.0f, 3)},
                                         {"delta_index", 1, bumpOf(0.0f, 0.01f)}},
                                kScatteringRadianceTolerance);
}

// A renderer of kScene with a smoke whose density absorbs and scatters
// (volume.density_*). A volume names its file: a legacy VTK image of a
// temperature 0 K above ambient on the render cells, which the fields
// handed replace. The folder is the test's and the process's own, so that
// tests run in parallel never read each other's half-written file.
eikon::Renderer smokeRenderer() {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() /
        ("eikon_library_gpu_smoke_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
         "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    {
        std::ofstream file(folder / "smoke.vtk", std::ios::binary);
        file << "# vtk DataFile Version 3.0\nsmoke\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 33 33 33\n"
                "ORIGIN 0 0 0\nSPACING 0.015625 0.015625 0.015625\nCELL_DATA "
             << kCount << "\nSCALARS T float 1\nLOOKUP_TABLE default\n";
        const std::vector<char> zeros(kCount * sizeof(float), 0);  // 0.0f in either byte order
        file.write(zeros.data(), static_cast<std::streamsize>(zeros.size()));
        file << "\n";
    }
    std::string scene = kScene;
    scene.insert(scene.rfind('}'), R"(, "volume": {"path": "smoke.vtk", "density_extinction": [8, 6, 4],
                                                   "density_scattering": [4, 3, 2],
                                                   "fields": {"temperature": "T",
                                                              "temperature_unit": "kelvin_above_ambient"}})");
    return eikon::Renderer::fromJson(scene, folder.string());
}

TEST(LibraryGpu, ADensityBufferIsMappedOnTheGpuAsOnTheHost) {
    // Below 0 at the grid's edges: clamped to 0 on both paths.
    expectSameFramesFromBuffers(smokeRenderer, {{"density", 1, bumpOf(-0.05f, 2.0f)}}, kScatteringRadianceTolerance);
    // With the extinction and scattering it adds to (grey and RGB), and the index beside.
    expectSameFramesFromBuffers(smokeRenderer,
                                {{"density", 1, bumpOf(0.0f, 1.0f)},
                                 {"extinction", 3, bumpOf(0.2f, 1.0f, 3)},
                                 {"scattering", 1, bumpOf(0.1f, 0.5f)},
                                 {"delta_index", 1, bumpOf(0.0f, 0.01f)}},
                                kScatteringRadianceTolerance);
}

TEST(LibraryGpu, GreyExtinctionAndScatteringBuffersRenderAsTheSameHostArrays) {
    expectSameFramesFromBuffers(kScene, {{"extinction", 1, bumpOf(0.0f, 4.0f)}});
    expectSameFramesFromBuffers([] { return eikon::Renderer::fromJson(kScene); },
                                {{"extinction", 1, bumpOf(0.1f, 4.0f)}, {"scattering", 1, bumpOf(0.05f, 2.0f)}},
                                kScatteringRadianceTolerance);
}

using ::expectRefused;  // the list of fields (LibraryRefusals.h), beside one field here
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
    eikon::Field flame = deltaIndex(renderer, nullptr, small);
    flame.name = "flame";
    expectRefused(renderer, flame,
                  {"\"flame\"", "host memory", "delta_index, index, temperature, density, extinction, scattering"});
    eikon::Field rgbExtinction = deltaIndex(renderer, nullptr, small);
    rgbExtinction.name = "extinction";
    rgbExtinction.channels = 3;
    expectRefused(renderer, rgbExtinction, {"\"extinction\"", "393216 bytes", "65536 bytes"});
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

// Values the host path refuses are refused on the GPU, naming the field
// and the cell; fields mapped together are taken on one side. A refused
// frame leaves the last one: the renderer renders it again, the same.
TEST(LibraryGpu, ValuesAndSplitsTheHostPathRefusesAreRefused) {
    eikon::Renderer renderer = eikon::Renderer::fromJson(kScene);
    const auto field = [&](const char* name, std::vector<float> values, int channels = 1, std::string unit = {}) {
        eikon::Field f = deltaIndex(renderer, nullptr, bufferOf(renderer, values));
        f.name = name;
        f.channels = channels;
        f.unit = std::move(unit);
        return f;
    };
    const std::vector<float> lens = bump(0.01);
    renderer.setFields({field("delta_index", lens)});
    renderer.render();
    const std::vector<std::uint8_t> before = renderer.image().values;

    std::vector<float> values(kCount, 20.0f);
    values[5 + 32 * (6 + 32 * 7)] = std::nanf("");
    expectRefused(renderer, field("temperature", values), {"\"temperature\"", "finite values", "NaN", "(5, 6, 7)"});
    std::vector<float> cold(kCount, 20.0f);
    cold[3] = -300.0f;
    expectRefused(renderer, field("temperature", cold, 1, "celsius"),
                  {"\"temperature\"", "> 0 K", "-26.85 K", "(3, 0, 0)"});
    expectRefused(renderer, field("temperature", std::vector<float>(kCount, 300.0f)),
                  {"\"temperature\"", "declare its unit", "at least 300"});
    std::vector<float> index(kCount, 1.0f);
    index[kCount - 1] = 0.0f;
    expectRefused(renderer, field("index", index), {"\"index\"", "n > 0", "(31, 31, 31)"});
    std::vector<float> kappa(3 * kCount, 1.0f), sigma(3 * kCount, 0.5f);
    sigma[3 * 40 + 2] = 2.0f;
    expectRefused(renderer, {field("extinction", kappa, 3), field("scattering", sigma, 3)},
                  {"\"scattering\"", "scattering <= extinction", "(8, 1, 0)"});
    kappa[3 * 9] = -1.0f;
    expectRefused(renderer, field("extinction", kappa, 3), {"\"extinction\"", ">= 0", "-1 /m", "(9, 0, 0)"});

    const eikon::Field hostLens = deltaIndex(renderer, &lens, 0);
    eikon::Field temperature = field("temperature", std::vector<float>(kCount, 20.0f));
    expectRefused(renderer, {temperature, hostLens}, {"\"delta_index\"", "a GL buffer as \"temperature\""});
    eikon::Field flame = hostLens;
    flame.name = "flame";
    expectRefused(renderer, {temperature, flame}, {"\"temperature\"", "beside a flame"});
    eikon::Field scattering = field("scattering", sigma, 3);
    expectRefused(renderer, scattering, {"\"scattering\"", "an extinction or density GL buffer"});
    eikon::Field extinction = field("extinction", std::vector<float>(3 * kCount, 1.0f), 3);
    eikon::Field density = hostLens;
    density.name = "density";
    expectRefused(renderer, {extinction, density}, {"\"density\"", "a GL buffer as \"extinction\"", "mapped together"});
    expectRefused(renderer, {field("density", lens), flame}, {"\"density\"", "beside \"flame\""});

    // A density and grey coefficients, checked on the GPU as the host checks them.
    eikon::Renderer smoky = smokeRenderer();
    const auto smokyField = [&](const char* name, std::vector<float> samples) {
        eikon::Field f = deltaIndex(smoky, nullptr, bufferOf(smoky, samples));
        f.name = name;
        return f;
    };
    std::vector<float> rho(kCount, 0.5f);
    rho[5 + 32 * (6 + 32 * 7)] = std::nanf("");
    expectRefused(smoky, smokyField("density", rho), {"\"density\"", "finite values", "NaN", "(5, 6, 7)"});
    rho[5 + 32 * (6 + 32 * 7)] = -std::numeric_limits<float>::infinity();
    expectRefused(smoky, smokyField("density", rho), {"\"density\"", "an infinity", "(5, 6, 7)"});
    rho[5 + 32 * (6 + 32 * 7)] = 1e38f;  // κ = 8·1e38 /m, past float32
    expectRefused(smoky, smokyField("density", rho), {"\"density\"", "a finite extinction", "(5, 6, 7)"});
    std::vector<float> greyKappa(kCount, 1.0f), greySigma(kCount, 0.5f);
    greyKappa[2 + 32 * 3] = -2.0f;
    expectRefused(smoky, smokyField("extinction", greyKappa), {"\"extinction\"", ">= 0", "-2 /m", "(2, 3, 0)"});
    greyKappa[2 + 32 * 3] = 1.0f;
    greySigma[kCount - 2] = 1.5f;
    expectRefused(smoky, {smokyField("extinction", greyKappa), smokyField("scattering", greySigma)},
                  {"\"scattering\"", "scattering <= extinction", "(30, 31, 31)"});
    // Beside a density of 0.1 the scattering 0.5 + 4·0.1 = 0.9 /m lies within κ = 1 + 8·0.1 = 1.8 /m, and
    // 1.5 + 0.4 = 1.9 /m does not.
    expectRefused(smoky,
                  {smokyField("density", std::vector<float>(kCount, 0.1f)), smokyField("extinction", greyKappa),
                   smokyField("scattering", greySigma)},
                  {"\"scattering\"", "scattering <= extinction", "(30, 31, 31)", "σs (1.9"});

    std::string absorbing = kScene;
    absorbing.insert(absorbing.rfind('}'), R"(, "medium": {"index": 1.0, "extinction": [0.5, 0.5, 0.5]})");
    eikon::Renderer murky = eikon::Renderer::fromJson(absorbing);
    eikon::Field murkyExtinction = deltaIndex(murky, nullptr, bufferOf(murky, std::vector<float>(3 * kCount, 1.0f)));
    murkyExtinction.name = "extinction";
    murkyExtinction.channels = 3;
    expectRefused(murky, murkyExtinction, {"\"extinction\"", "medium absorbs or scatters"});

    renderer.render();  // the last frame taken, unchanged
    EXPECT_EQ(renderer.image().values, before);
}

}  // namespace
