// The GPU linear solvers of the fluid (sim/gpu/GpuPressureSolver.h,
// GpuMultigrid.h, GpuDiffusion.h) against the CPU solvers they port
// (sim/fluid/PressureSolver.h, Multigrid.h, Diffusion.h), on the same
// float32-rounded inputs: the same discretisation must give the same fields
// to the solvers' tolerances and float32 rounding.
#include "sim/fluid/Diffusion.h"
#include "sim/fluid/ParallelOps.h"
#include "sim/fluid/PressureSolver.h"
#include "sim/gpu/GpuDiffusion.h"
#include "sim/gpu/GpuMultigrid.h"
#include "sim/gpu/GpuPressureSolver.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>

namespace eikon::sim::gpu {
namespace {

using Boundary = SimDesc::Boundary;

// The value a float32 field holds for v.
double roundedToFloat(double v) { return static_cast<double>(static_cast<float>(v)); }

void roundToFloat(GridField& field) {
    for (double& v : field.values) v = roundedToFloat(v);
}

std::array<GpuField, 3> uploadVelocity(const MacGrid& mac) {
    return {GpuField(mac.velocity[0], solverResource("velocity u", mac.velocity[0].size)),
            GpuField(mac.velocity[1], solverResource("velocity v", mac.velocity[1].size)),
            GpuField(mac.velocity[2], solverResource("velocity w", mac.velocity[2].size))};
}

// max|a − b| / max|b|
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
    EXPECT_EQ(a.size(), b.size());
    double difference = 0.0;
    for (std::size_t s = 0; s < a.size(); ++s) difference = std::max(difference, std::abs(a[s] - b[s]));
    return difference / maxAbs(b);
}

double maxDivergence(const MacGrid& mac, const FluidDomain& domain) {
    double largest = 0.0;
    const glm::ivec3 n = mac.grid.resolution;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (!domain.isSolid(i, j, k)) largest = std::max(largest, std::abs(mac.divergence(i, j, k)));
    return largest;
}

// A random velocity field, fixed faces at 0, rounded to float32 as both solvers see it.
MacGrid randomFlow(const GridSpec& grid, const FluidDomain& domain, unsigned seed) {
    MacGrid mac(grid);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (GridField& u : mac.velocity)
        for (double& v : u.values) v = uniform(rng);
    enforceVelocityBoundaries(mac, domain);
    for (GridField& u : mac.velocity) roundToFloat(u);
    return mac;
}

// Projects the same flow on both sides at the default pressure tolerance and
// compares: the divergence left, the fields and the iterations.
void projectOnBothSides(const GridSpec& grid, const FluidDomain& domain, const char* figurePrefix) {
    constexpr double kTolerance = 1e-6;  // the simulation's default pressure tolerance
    constexpr int kMaxIterations = 200;
    const MacGrid initial = randomFlow(grid, domain, 11);
    const double initialDivergence = maxDivergence(initial, domain);

    MacGrid cpu = initial;
    GridField cpuPressure = cpu.cellField(0.0);
    const SolveStats cpuStats = PressureSolver(domain, cpu.h).project(cpu, cpuPressure, kTolerance, kMaxIterations);

    std::array<GpuField, 3> velocity = uploadVelocity(initial);
    GpuField pressure(initial.cellField(0.0), solverResource("pressure", grid.resolution));
    GpuPressureSolver solver(domain, initial.h);
    const SolveStats gpuStats = solver.project(velocity, pressure, kTolerance, kMaxIterations);
    MacGrid gpu = initial;
    for (int axis = 0; axis < 3; ++axis) velocity[axis].download(gpu.velocity[axis]);
    GridField gpuPressure;
    pressure.download(gpuPressure);

    // CG stops at max|r| <= tolerance · max|b|, r = −∇·u on the unknowns; the
    // float32 velocity adds its rounding, at most 2^-24 of each of a cell's
    // six faces, divided by h.
    double largestVelocity = 0.0;
    for (const GridField& u : gpu.velocity) largestVelocity = std::max(largestVelocity, maxAbs(u.values));
    const double h = std::min({gpu.h.x, gpu.h.y, gpu.h.z});
    const double roundingAllowance = 6.0 * std::ldexp(1.0, -24) * largestVelocity / h;
    const double divergence = maxDivergence(gpu, domain);
    EXPECT_LE(gpuStats.relativeResidual, kTolerance);
    EXPECT_LE(divergence, kTolerance * initialDivergence + roundingAllowance);

    double velocityDifference = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        velocityDifference =
            std::max(velocityDifference, relativeDifference(gpu.velocity[axis].values, cpu.velocity[axis].values));
    const double pressureDifference = relativeDifference(gpuPressure.values, cpuPressure.values);
    // Both solves stop within 1e-6 of the residual; their iterates differ by
    // the float32 V-cycle's rounding, amplified by at most the few CG steps.
    EXPECT_LE(velocityDifference, 1e-4);
    EXPECT_LE(pressureDifference, 1e-4);
    // The float32 preconditioner may cost CG an iteration or two.
    EXPECT_LE(std::abs(gpuStats.iterations - cpuStats.iterations), 2);

    const std::string prefix(figurePrefix);
    eikon::test::reportFigure((prefix + "_divergence_over_initial").c_str(), divergence / initialDivergence);
    eikon::test::reportFigure((prefix + "_velocity_relative_difference").c_str(), velocityDifference);
    eikon::test::reportFigure((prefix + "_pressure_relative_difference").c_str(), pressureDifference);
    eikon::test::reportFigure((prefix + "_cpu_iterations").c_str(), cpuStats.iterations);
    eikon::test::reportFigure((prefix + "_gpu_iterations").c_str(), gpuStats.iterations);
    eikon::test::reportFigure((prefix + "_bytes_read_back").c_str(), static_cast<double>(solver.bytesReadBack()));
    eikon::test::reportFigure((prefix + "_vcycle_dispatches").c_str(), solver.multigrid().dispatchesPerCycle());
}

// 13×10×9 cells, a solid block, the y max face open, the other walls closed.
TEST(GpuLinearSolvers, ProjectionMatchesCpuAroundAnObstacleWithAnOpenFace) {
    eikon::test::glContext();
    const GridSpec grid{glm::ivec3(13, 10, 9), glm::dvec3(0.0), glm::dvec3(1.3, 1.0, 1.08)};
    std::array<Boundary, 6> faces{};
    faces[3] = Boundary::Open;
    FluidDomain domain(grid.resolution, faces);
    for (int k = 2; k < 6; ++k)
        for (int j = 3; j < 6; ++j)
            for (int i = 4; i < 7; ++i) domain.solid[domain.cellIndex(i, j, k)] = 1;
    projectOnBothSides(grid, domain, "open_face");
}

// A closed 12×9×7 box: the singular pure-Neumann problem, solved with zero mean.
TEST(GpuLinearSolvers, ProjectionMatchesCpuInAClosedBox) {
    eikon::test::glContext();
    const GridSpec grid{glm::ivec3(12, 9, 7), glm::dvec3(0.0), glm::dvec3(1.2, 0.9, 0.84)};
    FluidDomain domain(grid.resolution, {});
    for (int k = 1; k < 4; ++k) domain.solid[domain.cellIndex(6, 4, k)] = 1;
    projectOnBothSides(grid, domain, "closed_box");
}

// float32 keeps values of magnitude below 1 to within 2^-25 ≈ 3e-8, the
// solves converge to 1e-12: the hand-computed answers hold to 1e-7.
constexpr double kFloatAnswer = 1e-7;

// tests/unit/test_fluid_pressure.cpp's two cells between open x faces with
// u = 1 on the middle face: p = (−1/3, 1/3), and u = 1/3 on all three x faces.
TEST(GpuLinearSolvers, TwoCellSolveMatchesHandComputedAnswer) {
    eikon::test::glContext();
    const GridSpec grid{glm::ivec3(2, 1, 1), glm::dvec3(0.0), glm::dvec3(2.0, 1.0, 1.0)};
    std::array<Boundary, 6> faces{};
    faces[0] = faces[1] = Boundary::Open;
    const FluidDomain domain(grid.resolution, faces);
    MacGrid mac(grid);
    mac.velocity[0](1, 0, 0) = 1.0;
    std::array<GpuField, 3> velocity = uploadVelocity(mac);
    GpuField pressure(mac.cellField(0.0), solverResource("pressure", grid.resolution));
    GpuPressureSolver solver(domain, mac.h);
    const SolveStats stats = solver.project(velocity, pressure, 1e-12, 10);
    EXPECT_LE(stats.relativeResidual, 1e-12);
    GridField p;
    pressure.download(p);
    velocity[0].download(mac.velocity[0]);
    EXPECT_NEAR(p(0, 0, 0), -1.0 / 3.0, kFloatAnswer);
    EXPECT_NEAR(p(1, 0, 0), 1.0 / 3.0, kFloatAnswer);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mac.velocity[0](i, 0, 0), 1.0 / 3.0, kFloatAnswer) << "face " << i;
}

// tests/unit/test_fluid_pressure.cpp's closed 2×2×1 box of half-metre cells
// with u = 1 on the face between the two lower cells: p = ∓3/16 below,
// ∓1/16 above, and a loop of 1/4 m/s around the box.
TEST(GpuLinearSolvers, ClosedFourCellBoxMatchesHandComputedAnswer) {
    eikon::test::glContext();
    const GridSpec grid{glm::ivec3(2, 2, 1), glm::dvec3(0.0), glm::dvec3(1.0, 1.0, 0.5)};
    const FluidDomain domain(grid.resolution, {});
    MacGrid mac(grid);
    mac.velocity[0](1, 0, 0) = 1.0;
    std::array<GpuField, 3> velocity = uploadVelocity(mac);
    GpuField pressure(mac.cellField(0.0), solverResource("pressure", grid.resolution));
    GpuPressureSolver solver(domain, mac.h);
    const SolveStats stats = solver.project(velocity, pressure, 1e-12, 20);
    EXPECT_LE(stats.relativeResidual, 1e-12);
    GridField p;
    pressure.download(p);
    for (int axis = 0; axis < 3; ++axis) velocity[axis].download(mac.velocity[axis]);
    EXPECT_NEAR(p(0, 0, 0), -3.0 / 16.0, kFloatAnswer);
    EXPECT_NEAR(p(1, 0, 0), 3.0 / 16.0, kFloatAnswer);
    EXPECT_NEAR(p(0, 1, 0), -1.0 / 16.0, kFloatAnswer);
    EXPECT_NEAR(p(1, 1, 0), 1.0 / 16.0, kFloatAnswer);
    EXPECT_NEAR(mac.velocity[0](1, 0, 0), 0.25, kFloatAnswer);
    EXPECT_NEAR(mac.velocity[0](1, 1, 0), -0.25, kFloatAnswer);
    EXPECT_NEAR(mac.velocity[1](0, 1, 0), -0.25, kFloatAnswer);
    EXPECT_NEAR(mac.velocity[1](1, 1, 0), 0.25, kFloatAnswer);
}

// The float32 V-cycle against the CPU's, on tests/unit/test_fluid_pressure.cpp's
// lattice (solids, one open face, uneven sizes): the same operator to float32
// rounding over its ~40 passes, and symmetric and positive as CG needs.
TEST(GpuLinearSolvers, MultigridVCycleMatchesCpuAndIsSymmetric) {
    eikon::test::glContext();
    const glm::ivec3 n(20, 13, 9);
    std::vector<std::uint8_t> active(static_cast<std::size_t>(n.x) * n.y * n.z, 1);
    for (int k = 2; k < 6; ++k)
        for (int j = 3; j < 8; ++j) active[5 + n.x * (j + n.y * k)] = 0;
    const bool open[6] = {false, false, false, true, false, false};
    const glm::dvec3 h(0.1, 0.1, 0.12);
    const MultigridPreconditioner cpu(n, h, active, open);
    const GpuMultigrid gpu(n, h, active, open);
    EXPECT_EQ(gpu.levelCount(), cpu.levelCount());

    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    std::vector<double> x(active.size()), y(active.size());
    for (std::size_t c = 0; c < x.size(); ++c) {
        // float32 values, so that both cycles start from the same numbers
        x[c] = active[c] ? roundedToFloat(normal(rng)) : 0.0;
        y[c] = active[c] ? roundedToFloat(normal(rng)) : 0.0;
    }
    const auto applyOnGpu = [&](const std::vector<double>& r) {
        const GpuStencilOperator& a = gpu.fineOperator();
        gl::Buffer rBuffer = a.newVector("test r", sizeof(double));
        gl::Buffer zBuffer = a.newVector("test z", sizeof(double));
        rBuffer.upload(r.data(), r.size() * sizeof(double));
        gpu.apply(rBuffer, zBuffer);
        return zBuffer.downloadAll<double>();
    };
    const std::vector<double> mx = applyOnGpu(x), my = applyOnGpu(y);
    std::vector<double> cpuMx;
    cpu.apply(x, cpuMx);

    const double difference = relativeDifference(mx, cpuMx);
    const double xMy = dot(x, my);
    const double asymmetry = std::abs(xMy - dot(y, mx)) / std::abs(xMy);
    // float32 rounding, 6e-8 per operation, accumulated over the cycle's
    // passes and the sums of its stencils and transfers.
    EXPECT_LE(difference, 1e-5);
    EXPECT_LE(asymmetry, 1e-5);
    EXPECT_GT(dot(x, mx), 0.0);
    eikon::test::reportFigure("vcycle_relative_difference_to_cpu", difference);
    eikon::test::reportFigure("vcycle_relative_asymmetry", asymmetry);
}

// A 12×9×7 lattice with an excluded block (a solid), fixed samples (held
// values) and a random field: the roles of ImplicitDiffusion.
struct DiffusionCase {
    glm::ivec3 size{12, 9, 7};
    glm::dvec3 h{0.1, 0.1, 0.12};
    std::vector<DiffusionRole> roles;
    GridField field;

    explicit DiffusionCase(double reference) : field(size, glm::dvec3(0.5)) {
        roles.assign(field.count(), DiffusionRole::Free);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        for (int k = 0; k < size.z; ++k)
            for (int j = 0; j < size.y; ++j)
                for (int i = 0; i < size.x; ++i) {
                    const std::size_t c = field.index(i, j, k);
                    field.values[c] = reference + uniform(rng) + 0.1 * i;
                    if (i >= 3 && i < 6 && j >= 2 && j < 5 && k >= 1 && k < 4) roles[c] = DiffusionRole::Excluded;
                    if (i == 9 && j >= 4 && k == 3) {
                        roles[c] = DiffusionRole::Fixed;
                        field.values[c] = reference + 2.0;
                    }
                }
        // As the GPU field holds it: float32 values relative to the reference.
        for (double& v : field.values) v = reference + roundedToFloat(v - reference);
    }
};

// Diffuses on both sides with Δt·D = dtTimesD and compares.
void diffuseOnBothSides(double dtTimesD, double reference, const char* figurePrefix) {
    constexpr double kTolerance = 1e-8;  // the simulation's default diffusion tolerance
    constexpr int kMaxIterations = 200;
    const DiffusionCase setup(reference);
    GridField cpuField = setup.field;
    ImplicitDiffusion cpu(setup.size, setup.roles);
    const SolveStats cpuStats = cpu.diffuse(cpuField, setup.h, dtTimesD, kTolerance, kMaxIterations);

    GpuField field(setup.field, solverResource("diffused field", setup.size), reference);
    GpuDiffusion gpu(setup.size, setup.roles);
    const SolveStats gpuStats = gpu.diffuse(field, setup.h, dtTimesD, kTolerance, kMaxIterations);
    GridField gpuField;
    field.download(gpuField);

    // Relative to the largest stored value, φ − reference; the fields agree
    // to the solves' 1e-8 and float32's 6e-8 rounding of the result.
    double difference = 0.0, largest = 0.0;
    for (std::size_t c = 0; c < cpuField.count(); ++c) {
        difference = std::max(difference, std::abs(gpuField.values[c] - cpuField.values[c]));
        largest = std::max(largest, std::abs(cpuField.values[c] - reference));
        if (setup.roles[c] != DiffusionRole::Free) {
            EXPECT_EQ(gpuField.values[c], setup.field.values[c]) << "a held or excluded sample changed";
        }
    }
    EXPECT_GT(cpuStats.iterations, 0);
    EXPECT_LE(gpuStats.relativeResidual, kTolerance);
    EXPECT_LE(difference / largest, 1e-5);
    EXPECT_LE(std::abs(gpuStats.iterations - cpuStats.iterations), 1);  // both in float64
    const std::string prefix(figurePrefix);
    eikon::test::reportFigure((prefix + "_relative_difference").c_str(), difference / largest);
    eikon::test::reportFigure((prefix + "_cpu_iterations").c_str(), cpuStats.iterations);
    eikon::test::reportFigure((prefix + "_gpu_iterations").c_str(), gpuStats.iterations);
    eikon::test::reportFigure((prefix + "_bytes_read_back").c_str(), static_cast<double>(gpu.bytesReadBack()));
}

// Δt·D/h² ≈ 0.1: 2Σw/(1 + 2Σw) ≈ 0.35, under kGaussSeidelBelow (0.5).
TEST(GpuLinearSolvers, DiffusionMatchesCpuInTheGaussSeidelRegime) {
    eikon::test::glContext();
    diffuseOnBothSides(1e-3, 0.0, "diffusion_gauss_seidel");
}

// Δt·D/h² ≈ 5: Jacobi-preconditioned CG; a temperature-like field stored
// relative to its reference.
TEST(GpuLinearSolvers, DiffusionMatchesCpuInTheConjugateGradientRegime) {
    eikon::test::glContext();
    diffuseOnBothSides(0.05, 293.15, "diffusion_cg");
}

// A uniform field is steady in both regimes: no iteration, not a bit changed.
TEST(GpuLinearSolvers, UniformFieldIsUnchangedWithoutIterations) {
    eikon::test::glContext();
    const DiffusionCase setup(0.0);
    const GridField uniform(setup.size, glm::dvec3(0.5), 0.375);
    for (const double dtTimesD : {1e-3, 0.05}) {
        GpuField field(uniform, solverResource("uniform field", setup.size));
        GpuDiffusion gpu(setup.size, setup.roles);
        const SolveStats stats = gpu.diffuse(field, setup.h, dtTimesD, 1e-8, 200);
        EXPECT_EQ(stats.iterations, 0);
        GridField after;
        field.download(after);
        EXPECT_EQ(after.values, uniform.values);
    }
}

}  // namespace
}  // namespace eikon::sim::gpu
