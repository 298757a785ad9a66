// The physics math of shaders/common is written once and compiled both as
// GLSL and as C++ (shaders/common/cpp_shim.h). This runs the same functions
// on random inputs in a compute shader and on the CPU and compares.
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"
#include "shaders/common/cpp_shim.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace eikon {
namespace {

constexpr unsigned kCases = 512;
constexpr GLuint kProbeBinding = 0;  // the probe's one buffer; no production program runs beside it

// The probe is a test shader, read from the source tree: production embeds
// only shaders/.
gl::Program compileProbe() {
    const std::string name = "tests/integration/shaders/shared_math_probe.comp";
    std::ifstream file(std::string(EIKON_SOURCE_DIR) + "/" + name);
    if (!file) throw std::runtime_error("cannot read " + name);
    std::ostringstream text;
    text << file.rdbuf();
    return gl::compileComputeProgramFromSource(name, text.str(),
                                               {{"EIKON_PROBE_BINDING", std::to_string(kProbeBinding)}});
}

struct ProbeCase {
    glm::vec4 in[4];
    glm::vec4 out[4];
};

std::vector<ProbeCase> randomCases() {
    std::mt19937 random(12345);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f), index(1.0f, 2.5f), step(1e-4f, 0.05f),
        gradient(-5.0f, 5.0f), g(-0.9f, 0.9f), kappa(0.0f, 40.0f), cosine(-1.0f, 1.0f);
    std::vector<ProbeCase> cases(kCases);
    for (auto& c : cases) {
        c.in[0] = glm::vec4(coordinate(random), coordinate(random), coordinate(random), index(random));
        c.in[1] = glm::vec4(coordinate(random), coordinate(random), coordinate(random), step(random));
        c.in[2] = glm::vec4(gradient(random), gradient(random), gradient(random), g(random));
        c.in[3] = glm::vec4(kappa(random), kappa(random) * 1e-4f, kappa(random), cosine(random));
    }
    return cases;
}

// The C++ twin of tests/integration/shaders/shared_math_probe.comp.
void evaluateOnCpu(ProbeCase& c, unsigned i) {
    using namespace eikon::shader;
    vec3 x = vec3(c.in[0]);
    vec3 v = vec3(c.in[1]);
    vec3 x_lost = vec3(0.0f);
    eikonal_euler_step(x, x_lost, v, c.in[0].w, vec3(c.in[2]), c.in[1].w);
    c.out[0] = vec4(x, eikonal_invariant_error(v, c.in[0].w));
    c.out[1] = vec4(v, henyey_greenstein(c.in[3].w, c.in[2].w));
    c.out[2] = vec4(beer_lambert_transmittance(vec3(c.in[3]), c.in[1].w), random_uniform(i, 7u, 3u));
    vec3 axis = normalize(vec3(c.in[2]) + vec3(0.0f, 0.0f, 1e-3f));
    vec3 tangent = normalize(cross(axis, abs(axis.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
    vec3 cone = sample_cone(axis, tangent, cross(axis, tangent), 0.5f, fract(c.in[0].x), fract(c.in[0].y));
    c.out[3] = vec4(attenuated_track_length(vec3(c.in[3]), c.in[1].w).x, cone.x, cone.y, cone.z);
}

TEST(SharedMath, GlslAndCppAgree) {
    test::glContext();
    std::vector<ProbeCase> gpu = randomCases();
    gl::Buffer buffer(gpu.size() * sizeof(ProbeCase), gpu.data());
    const gl::Program program = compileProbe();
    buffer.bindStorage(kProbeBinding);
    program.use();
    glUniform1ui(program.uniform("case_count"), kCases);
    program.dispatchCovering(kCases);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    buffer.download(gpu.data(), gpu.size() * sizeof(ProbeCase));

    std::vector<ProbeCase> cpu = randomCases();
    const char* names[4][4] = {{"x.x", "x.y", "x.z", "invariant"},
                               {"v.x", "v.y", "v.z", "henyey_greenstein"},
                               {"T.r", "T.g", "T.b", "random_uniform"},
                               {"track_length", "cone.x", "cone.y", "cone.z"}};
    double worstRelative = 0.0;
    for (unsigned i = 0; i < kCases; ++i) {
        evaluateOnCpu(cpu[i], i);
        for (int o = 0; o < 4; ++o)
            for (int k = 0; k < 4; ++k)
                worstRelative = std::max(worstRelative, std::abs(double{gpu[i].out[o][k]} - cpu[i].out[o][k]) /
                                                            std::max(1.0, std::abs(double{cpu[i].out[o][k]})));
        for (int o = 0; o < 4; ++o)
            for (int k = 0; k < 4; ++k) {
                const float expected = cpu[i].out[o][k];
                // GLSL 4.50 allows exp/pow/sin/cos a few ulp of error; 2e-6 relative covers them.
                const float tolerance = 2e-6f * std::max(1.0f, std::abs(expected));
                ASSERT_NEAR(gpu[i].out[o][k], expected, tolerance) << names[o][k] << " in case " << i;
            }
        // The random stream must be exactly the same bits on both sides.
        ASSERT_EQ(gpu[i].out[2].w, cpu[i].out[2].w) << "random_uniform differs in case " << i;
    }
    test::reportFigure("shared_math_worst_relative_difference", worstRelative);
}

TEST(SharedMath, HenyeyGreensteinIntegratesToOne) {
    for (float g : {-0.8f, 0.0f, 0.5f, 0.9f}) {
        double integral = 0.0;
        constexpr int kSteps = 200000;
        for (int i = 0; i < kSteps; ++i) {
            const double mu = -1.0 + (i + 0.5) * 2.0 / kSteps;
            integral += 2.0 * 3.14159265358979 * shader::henyey_greenstein(static_cast<float>(mu), g) * 2.0 / kSteps;
        }
        EXPECT_NEAR(integral, 1.0, 1e-3) << "g = " << g;
    }
}

TEST(SharedMath, TrackLengthMatchesClosedForm) {
    EXPECT_NEAR(shader::attenuated_track_length(glm::vec3(0.0f), 0.3f).x, 0.3f, 1e-7f);
    EXPECT_NEAR(shader::attenuated_track_length(glm::vec3(2.0f), 0.5f).x, (1.0f - std::exp(-1.0f)) / 2.0f, 1e-6f);
    EXPECT_NEAR(shader::attenuated_track_length(glm::vec3(1e-5f), 1.0f).x, (1.0 - std::exp(-1e-5)) / 1e-5, 1e-6);
}

}  // namespace
}  // namespace eikon
