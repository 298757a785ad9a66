// Measures whether a sparse refractive-index field is sampled faster from a
// NanoVDB tree (PNanoVDB in GLSL, grid in an SSBO) or from the dense R32F 3D
// texture the photon tracer uses today (issue: "for sparse scenes, keep
// whichever is faster"). Both kernels march the same rays (random starts and
// directions, half-voxel steps, periodic in the domain) and take one trilinear
// sample per step; their sums are compared so both do the same work. The scene
// is a few smooth δn blobs in an N³ domain, built with OpenVDB.
#include "gl/GlContext.h"
#include "gl/GlObjects.h"

#include <benchmark/benchmark.h>
#include <nanovdb/util/OpenToNanoVDB.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using eikon::gl::Buffer;
using eikon::gl::Program;
using eikon::gl::Texture3D;

constexpr int kRays = 1 << 18;
constexpr int kSteps = 128;
constexpr double kSamplesPerDispatch = double(kRays) * kSteps;
constexpr double kTolerance = 1e-3;

// --- scene -------------------------------------------------------------------

// `blobs` balls of radius N/16 voxels, δn = 0.01·(1 − r²/R²)² inside (active),
// background 0 elsewhere; centres from a fixed seed, clear of the faces.
openvdb::FloatGrid::Ptr makeBlobs(int n, int blobs) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    auto accessor = grid->getAccessor();
    const int radius = n / 16;
    std::mt19937 rng(12345);
    std::uniform_int_distribution<int> centre(radius, n - 1 - radius);
    for (int b = 0; b < blobs; ++b) {
        const openvdb::Coord c(centre(rng), centre(rng), centre(rng));
        for (int z = -radius; z <= radius; ++z)
            for (int y = -radius; y <= radius; ++y)
                for (int x = -radius; x <= radius; ++x) {
                    const float q = float(x * x + y * y + z * z) / float(radius * radius);
                    if (q >= 1.0f) continue;
                    const openvdb::Coord ijk = c.offsetBy(x, y, z);
                    accessor.setValue(ijk, accessor.getValue(ijk) + 0.01f * (1.0f - q) * (1.0f - q));
                }
    }
    return grid;
}

// x fastest, as glTextureSubImage3D expects.
std::vector<float> toDense(const openvdb::FloatGrid& grid, int n) {
    openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(
        openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(n - 1)), 0.0f);
    openvdb::tools::copyToDense(grid, dense);
    return {dense.data(), dense.data() + dense.valueCount()};
}

// --- GLSL ----------------------------------------------------------------------

std::string readFile(const char* path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(std::string("cannot read ") + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string shaderHeader() {
    return "#version 450 core\n#define RAYS " + std::to_string(kRays) + "u\n#define STEPS " +
           std::to_string(kSteps) + "\n";
}

// Defines `Sampler makeSampler()` and `float sampleField(inout Sampler, vec3 p)`
// with p in voxel-index space (voxel i centred at i).
const char* const kDenseSampler = R"(
layout(binding = 0) uniform sampler3D uField;
uniform float uInvSize;
struct Sampler { int unused; };
Sampler makeSampler() { return Sampler(0); }
float sampleField(inout Sampler s, vec3 p) { return textureLod(uField, (p + 0.5) * uInvSize, 0.0).r; }
)";

const char* const kNanoSamplerPrefix = R"(
layout(std430, binding = 1) readonly buffer NanoGrid { uint pnanovdb_buf_data[]; };
#define PNANOVDB_GLSL
)";

const char* const kNanoSampler = R"(
const pnanovdb_buf_t kBuf = pnanovdb_buf_t(0u);
struct Sampler { pnanovdb_readaccessor_t acc; };
Sampler makeSampler() {
    pnanovdb_grid_handle_t grid = pnanovdb_grid_handle_t(pnanovdb_address_t(0u));
    pnanovdb_root_handle_t root = pnanovdb_tree_get_root(kBuf, pnanovdb_grid_get_tree(kBuf, grid));
    Sampler s;
    pnanovdb_readaccessor_init(s.acc, root);
    return s;
}
float voxel(inout Sampler s, ivec3 ijk) {
    return pnanovdb_read_float(kBuf, pnanovdb_readaccessor_get_value_address(PNANOVDB_GRID_TYPE_FLOAT, kBuf, s.acc, ijk));
}
float sampleField(inout Sampler s, vec3 p) {
    vec3 f = floor(p);
    ivec3 i = ivec3(f);
    vec3 w = p - f;
    float x00 = mix(voxel(s, i), voxel(s, i + ivec3(1, 0, 0)), w.x);
    float x10 = mix(voxel(s, i + ivec3(0, 1, 0)), voxel(s, i + ivec3(1, 1, 0)), w.x);
    float x01 = mix(voxel(s, i + ivec3(0, 0, 1)), voxel(s, i + ivec3(1, 0, 1)), w.x);
    float x11 = mix(voxel(s, i + ivec3(0, 1, 1)), voxel(s, i + ivec3(1, 1, 1)), w.x);
    return mix(mix(x00, x10, w.y), mix(x01, x11, w.y), w.z);
}
)";

// One ray per invocation; positions wrap in [0, N−1)³ so every trilinear
// footprint lies inside the grid and both representations see the same data.
const char* const kMarch = R"(
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Sums { float raySums[]; };
uniform float uExtent;

uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
float random01(inout uint state) {
    state = pcgHash(state);
    return float(state >> 8) * (1.0 / 16777216.0);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= RAYS) return;
    uint rng = id;
    vec3 p = vec3(random01(rng), random01(rng), random01(rng)) * uExtent;
    float cosTheta = 1.0 - 2.0 * random01(rng);
    float phi = 6.28318530718 * random01(rng);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    vec3 delta = 0.5 * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
    Sampler s = makeSampler();
    float sum = 0.0;
    for (int k = 0; k < STEPS; ++k) {
        sum += sampleField(s, p);
        p = mod(p + delta, uExtent);
    }
    raySums[id] = sum;
}
)";

Program compileCompute(const std::vector<std::string>& parts) {
    std::vector<const char*> strings;
    for (const auto& part : parts) strings.push_back(part.c_str());
    const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
    glShaderSource(shader, GLsizei(strings.size()), strings.data(), nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    std::string log(4096, '\0');
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    if (!ok) {
        glDeleteShader(shader);
        throw std::runtime_error("compute shader failed to compile:\n" + log);
    }
    Program program(glCreateProgram());
    glAttachShader(program.id(), shader);
    glLinkProgram(program.id());
    glDeleteShader(shader);
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    glGetProgramInfoLog(program.id(), GLsizei(log.size()), nullptr, log.data());
    if (!ok) throw std::runtime_error("compute program failed to link:\n" + log);
    program.readWorkGroupSize();
    return program;
}

// --- benchmark state -------------------------------------------------------------

enum class Kernel { DenseTexture, NanoVdb };

struct GpuScene {
    int n = 0;
    double occupancy = 0.0;  // active voxels / N³
    std::size_t denseBytes = 0;
    std::size_t nanoBytes = 0;
    Texture3D texture;
    Buffer nanoGrid;
    double relativeDifference = 0.0;  // |sum_A − sum_B| / |sum_A|
};

class SparseSamplingBench {
public:
    SparseSamplingBench()
        : dense_(compileCompute({shaderHeader(), kDenseSampler, kMarch})),
          nano_(compileCompute({shaderHeader(), kNanoSamplerPrefix, readFile(EIKON_PNANOVDB_HEADER), kNanoSampler,
                                kMarch})),
          sums_(sizeof(float) * kRays, nullptr, 0) {}

    // Builds (once) the scene, runs both kernels and compares their sums.
    const GpuScene& scene(int n, int blobs) {
        auto& slot = scenes_[{n, blobs}];
        if (!slot) {
            slot = buildScene(n, blobs);
            const double a = dispatchAndSum(Kernel::DenseTexture, *slot);
            const double b = dispatchAndSum(Kernel::NanoVdb, *slot);
            slot->relativeDifference = std::abs(a - b) / std::abs(a);
            std::fprintf(stderr, "N=%d blobs=%d: sum dense %.9g, NanoVDB %.9g, relative difference %.3g\n", n, blobs,
                         a, b, slot->relativeDifference);
        }
        return *slot;
    }

    // One dispatch of `kernel` over all rays, waited for with glFinish.
    double timedDispatch(Kernel kernel, const GpuScene& scene) {
        const Program& program = bind(kernel, scene);
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        program.dispatchCovering(kRays);
        glFinish();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

private:
    static std::unique_ptr<GpuScene> buildScene(int n, int blobs) {
        const auto grid = makeBlobs(n, blobs);
        const std::vector<float> dense = toDense(*grid, n);
        const auto handle = nanovdb::openToNanoVDB(*grid);
        auto scene = std::make_unique<GpuScene>();
        scene->n = n;
        scene->occupancy = double(grid->activeVoxelCount()) / std::pow(double(n), 3);
        scene->denseBytes = dense.size() * sizeof(float);
        scene->nanoBytes = handle.size();
        scene->texture = Texture3D(GL_R32F, n, n, n, eikon::gl::gridResource("the benchmark field", n, n, n));
        scene->texture.upload(GL_RED, GL_FLOAT, dense.data());
        scene->nanoGrid = Buffer(handle.size(), handle.data(), 0);
        return scene;
    }

    const Program& bind(Kernel kernel, const GpuScene& scene) const {
        const Program& program = kernel == Kernel::DenseTexture ? dense_ : nano_;
        program.use();
        glUniform1f(program.uniform("uExtent"), float(scene.n - 1));
        if (kernel == Kernel::DenseTexture) {
            glUniform1f(program.uniform("uInvSize"), 1.0f / float(scene.n));
            scene.texture.bindSampler(0);
        } else {
            scene.nanoGrid.bindStorage(1);
        }
        sums_.bindStorage(0);
        return program;
    }

    double dispatchAndSum(Kernel kernel, const GpuScene& scene) {
        timedDispatch(kernel, scene);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<float> sums(kRays);
        sums_.download(sums.data(), sums.size() * sizeof(float));
        return std::accumulate(sums.begin(), sums.end(), 0.0);
    }

    Program dense_;
    Program nano_;
    Buffer sums_;
    std::map<std::pair<int, int>, std::unique_ptr<GpuScene>> scenes_;
};

void runKernel(benchmark::State& state, SparseSamplingBench& bench, Kernel kernel) {
    const GpuScene& scene = bench.scene(int(state.range(0)), int(state.range(1)));
    if (!(scene.relativeDifference <= kTolerance)) {
        state.SkipWithError("dense and NanoVDB sums differ by more than 1e-3");
        return;
    }
    double seconds = 0.0;
    for (auto _ : state) {
        const double t = bench.timedDispatch(kernel, scene);
        state.SetIterationTime(t);
        seconds += t;
    }
    state.counters["samples_per_s"] = kSamplesPerDispatch * double(state.iterations()) / seconds;
    state.counters["occupancy"] = scene.occupancy;
    state.counters["bytes"] = double(kernel == Kernel::DenseTexture ? scene.denseBytes : scene.nanoBytes);
    state.counters["rel_diff"] = scene.relativeDifference;
}

void registerKernel(const char* name, SparseSamplingBench& bench, Kernel kernel) {
    benchmark::RegisterBenchmark(name, [&bench, kernel](benchmark::State& state) { runKernel(state, bench, kernel); })
        ->ArgNames({"N", "blobs"})
        ->ArgsProduct({{128, 256}, {8, 64}})
        ->UseManualTime()
        ->MinTime(6.0)
        ->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    const auto context = eikon::gl::createHeadlessContext();
    benchmark::AddCustomContext("gl_renderer", context->info().renderer);
    benchmark::AddCustomContext("rays x steps", std::to_string(kRays) + " x " + std::to_string(kSteps));
    openvdb::initialize();
    SparseSamplingBench bench;
    registerKernel("dense_texture", bench, Kernel::DenseTexture);
    registerKernel("nanovdb", bench, Kernel::NanoVdb);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
