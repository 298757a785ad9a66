#include "sim/gpu/GpuWaterBody.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::sim::gpu {

namespace {

// A buffer holding `values`, whose bytes are added to `uploaded`.
template <typename T>
gl::Buffer bufferOf(const std::vector<T>& values, const char* what, std::uint64_t& uploaded) {
    uploaded += values.size() * sizeof(T);
    return gl::Buffer(std::max<std::size_t>(values.size(), 1) * sizeof(T), values.empty() ? nullptr : values.data(),
                      GL_DYNAMIC_STORAGE_BIT, {"objects", what});
}

void setDouble3(const gl::Program& program, const char* name, const glm::dvec3& v) {
    glProgramUniform3d(program.id(), program.uniform(name), v.x, v.y, v.z);
}

std::string flag(bool on) { return on ? "1" : "0"; }

}  // namespace

std::string GpuWaterBody::unfit(const Scene& scene) {
    if (scene.objects.size() != 1 || scene.objects[0].kind != ObjectDesc::Kind::Water)
        return "the water is not the scene's only object";
    if (!scene.objects[0].hasTriangleSurface()) return "its surface is smooth (voxelized into the index)";
    if (scene.objects[0].water.disturbances.size() > static_cast<std::size_t>(kMaxMovers))
        return "it has more than " + std::to_string(kMaxMovers) + " disturbances";
    if (scene.sim || scene.volume) return "a fluid solver or a volume is under it";
    if (!scene.paint.empty()) return "paint strokes go over it";
    if (scene.exports.vtk.enabled || scene.exports.vdb.enabled) return "fields are exported (from the host)";
    return "";
}

GpuWaterBody::GpuWaterBody(const ObjectDesc& object, const WaterSurface& water, const SharpSurfaceTopology& surface,
                           const FieldSet& frame0, const FieldSet& medium)
    : desc_(water.desc()), material_(object.material), grid_(frame0.grid), stableStep_(water.stableStep()),
      dropApplied_(desc_.drops.size(), false), nodeCount_(desc_.cells.x * desc_.cells.y),
      triangleCount_(static_cast<int>(surface.bvh.order().size())),
      step_(gl::compileComputeProgram("sim/water_step.comp", {{"EIKON_PASS", "0"},
                                                              {"EIKON_MAX_WATER_MOVERS", std::to_string(kMaxMovers)}})),
      drop_(gl::compileComputeProgram("sim/water_step.comp", {{"EIKON_PASS", "1"},
                                                              {"EIKON_MAX_WATER_MOVERS", std::to_string(kMaxMovers)}})),
      faces_(gl::compileComputeProgram("sim/water_surface.comp", {{"EIKON_PASS", "0"}})),
      cornerNormals_(gl::compileComputeProgram("sim/water_surface.comp", {{"EIKON_PASS", "1"}})),
      refit_(gl::compileComputeProgram("sim/water_surface.comp", {{"EIKON_PASS", "2"}})),
      coverage_(gl::compileComputeProgram("sim/water_coverage.comp",
                                          {{"EIKON_HAS_EXTINCTION", flag(frame0.hasExtinction())},
                                           {"EIKON_HAS_SCATTERING", flag(frame0.hasScattering())},
                                           {"EIKON_HAS_ANISOTROPY", flag(frame0.hasAnisotropy())}})) {
    EIKON_CHECK_MSG(water.time() == 0.0, "the GPU takes a water surface over before its first step");
    EIKON_CHECK_MSG(frame0.surfaceTriangles.size() == surface.bvh.order().size() * kSurfaceTriangleFloats,
                    "the water is the scene's only sharp surface");
    height_[0] = bufferOf(water.heights(), "the water's heights", setupBytes_);
    height_[1] = bufferOf(water.heights(), "the water's heights", setupBytes_);
    velocity_ = bufferOf(std::vector<double>(static_cast<std::size_t>(nodeCount_), 0.0), "the water's velocities",
                         setupBytes_);
    for (const WaterDrop& drop : desc_.drops) {  // WaterSurface::applyDrop's dip
        std::vector<double> dip(static_cast<std::size_t>(nodeCount_));
        for (int k = 0; k < desc_.cells.y; ++k)
            for (int i = 0; i < desc_.cells.x; ++i) {
                const glm::dvec2 d = water.nodePosition(i, k) - drop.position;
                dip[static_cast<std::size_t>(k) * desc_.cells.x + i] =
                    drop.amplitude * std::exp(-glm::dot(d, d) / (2.0 * drop.radius * drop.radius));
            }
        drops_.push_back(bufferOf(dip, "a drop's dip", setupBytes_));
    }

    // The water body's vertices as WaterSurface::mesh makes them: the
    // surface's nodes (rising with their heights), then the floor's ring and
    // centre.
    const TriangleMesh rest = water.mesh();
    std::vector<glm::dvec4> vertices(rest.vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        const bool node = v < static_cast<std::size_t>(nodeCount_);
        const glm::dvec3 x = rest.vertices[v];
        vertices[v] = node ? glm::dvec4(x.x, desc_.basinMax.y, x.z, static_cast<double>(v)) : glm::dvec4(x, -1.0);
    }
    vertices_ = bufferOf(vertices, "the water body's vertices", setupBytes_);
    std::vector<glm::ivec4> triangles;
    for (const glm::ivec3& t : rest.triangles) triangles.emplace_back(t, 0);
    triangles_ = bufferOf(triangles, "the water body's triangles", setupBytes_);
    slots_ = bufferOf(surface.bvh.order(), "the water tree's leaf order", setupBytes_);
    cornerStart_ = bufferOf(surface.cornerStart, "the water's corner lists", setupBytes_);
    corners_ = bufferOf(surface.cornerTriangles, "the water's corner lists", setupBytes_);
    faceNormals_ = gl::Buffer(static_cast<std::size_t>(triangleCount_) * sizeof(glm::dvec4), {"objects", "face normals"});
    faceAngles_ = gl::Buffer(static_cast<std::size_t>(triangleCount_) * sizeof(glm::dvec4), {"objects", "face angles"});

    // The tree, grouped by depth, deepest first. As the scene's only sharp
    // surface, its nodes keep their numbers in FieldSet's nodes (the root,
    // node 0, is the only root; the others follow from node 1, as
    // SceneFields lays them out) and its triangles their leaf order.
    const std::vector<TriangleBvh::Node>& tree = surface.bvh.nodes();
    std::vector<glm::ivec4> nodes(tree.size());
    std::vector<int> depth(tree.size(), 0);
    for (std::size_t n = 0; n < tree.size(); ++n) {
        const TriangleBvh::Node& node = tree[n];
        if (node.count == 0)  // children follow their parent
            depth[static_cast<std::size_t>(node.first)] = depth[static_cast<std::size_t>(node.first) + 1] = depth[n] + 1;
        nodes[n] = glm::ivec4(static_cast<int>(n), node.count, node.first, node.count > 0 ? 0 : node.first + 1);
    }
    const int deepest = *std::max_element(depth.begin(), depth.end());
    std::vector<int> byLevel;
    for (int d = deepest; d >= 0; --d) {
        levelFirst_.push_back(static_cast<int>(byLevel.size()));
        for (std::size_t n = 0; n < tree.size(); ++n)
            if (depth[n] == d) byLevel.push_back(static_cast<int>(n));
    }
    levelFirst_.push_back(static_cast<int>(byLevel.size()));
    treeNodes_ = bufferOf(nodes, "the water tree's nodes", setupBytes_);
    levelNodes_ = bufferOf(byLevel, "the water tree's levels", setupBytes_);
    surfaceNodes_ = bufferOf(frame0.surfaceNodes, "the water's tree for the tracers", setupBytes_);
    surfaceTriangles_ = bufferOf(frame0.surfaceTriangles, "the water's triangles for the tracers", setupBytes_);

    // κ, σs and g, each where the scene has it: the medium's values under
    // the water (zero where the medium has none), and the painted ones.
    const std::size_t cells = grid_.cellCount();
    auto paints = [&](PaintedField& field, bool present, const std::vector<float>& under, std::size_t perCell,
                      const char* what, GLuint baseBinding, GLuint paintedBinding) {
        if (!present) return;
        field.base = bufferOf(under.empty() ? std::vector<float>(perCell * cells, 0.0f) : under, what, setupBytes_);
        field.painted = gl::Buffer(perCell * cells * sizeof(float), {"objects", what});
        field.baseBinding = baseBinding;
        field.paintedBinding = paintedBinding;
    };
    paints(painted_[0], frame0.hasExtinction(), medium.extinction, 3, "the water's extinction",
           layout::kWaterBaseExtinction, layout::kOpticsExtinction);
    paints(painted_[1], frame0.hasScattering(), medium.scattering, 3, "the water's scattering",
           layout::kWaterBaseScattering, layout::kOpticsScattering);
    paints(painted_[2], frame0.hasAnisotropy(), medium.anisotropy, 1, "the water's anisotropy",
           layout::kWaterBaseAnisotropy, layout::kOpticsAnisotropy);
    if (frame0.hasExtinction())
        setDouble3(coverage_, "water_extinction", {material_.extinction.r, material_.extinction.g, material_.extinction.b});
    if (frame0.hasScattering())
        setDouble3(coverage_, "water_scattering", {material_.scattering.r, material_.scattering.g, material_.scattering.b});
    if (frame0.hasAnisotropy())
        glProgramUniform1d(coverage_.id(), coverage_.uniform("water_anisotropy"), material_.anisotropy);

    // Uniforms that hold for every frame.
    const double dx = water.spacingX(), dz = water.spacingZ();
    glProgramUniform2i(step_.id(), step_.uniform("nodes"), desc_.cells.x, desc_.cells.y);
    glProgramUniform1d(step_.id(), step_.uniform("weight_x"), 1.0 / (dx * dx));
    glProgramUniform1d(step_.id(), step_.uniform("weight_z"), 1.0 / (dz * dz));
    glProgramUniform1d(step_.id(), step_.uniform("wave_speed_squared"), desc_.waveSpeed * desc_.waveSpeed);
    glProgramUniform2d(step_.id(), step_.uniform("basin_min"), desc_.basinMin.x, desc_.basinMin.z);
    glProgramUniform2d(step_.id(), step_.uniform("spacing"), dx, dz);
    glProgramUniform1i(drop_.id(), drop_.uniform("node_count"), nodeCount_);
    glProgramUniform1i(faces_.id(), faces_.uniform("triangle_count"), triangleCount_);
    glProgramUniform1i(cornerNormals_.id(), cornerNormals_.uniform("triangle_count"), triangleCount_);
    glProgramUniform1i(cornerNormals_.id(), cornerNormals_.uniform("root_node"), 0);
    glProgramUniform1d(cornerNormals_.id(), cornerNormals_.uniform("crease_cosine"), surface.creaseCosine);
    glProgramUniform3i(coverage_.id(), coverage_.uniform("cells"), grid_.resolution.x, grid_.resolution.y,
                       grid_.resolution.z);
    setDouble3(coverage_, "grid_min", grid_.boundsMin);
    setDouble3(coverage_, "voxel", grid_.voxelSize());
    setDouble3(coverage_, "basin_min", desc_.basinMin);
    setDouble3(coverage_, "basin_max", desc_.basinMax);
    glProgramUniform2i(coverage_.id(), coverage_.uniform("nodes"), desc_.cells.x, desc_.cells.y);

    glGenQueries(static_cast<GLsizei>(timestamps_.size()), timestamps_.data());
    writeSurface();
    writeCoverage();
}

GpuWaterBody::~GpuWaterBody() { glDeleteQueries(static_cast<GLsizei>(timestamps_.size()), timestamps_.data()); }

void GpuWaterBody::step(double dt) {
    for (std::size_t d = 0; d < desc_.drops.size(); ++d)
        if (!dropApplied_[d] && desc_.drops[d].time <= time_) {
            height_[current_].bindStorage(layout::kWaterHeight);
            drops_[d].bindStorage(layout::kWaterDrop);
            dispatchOverEntries(drop_, static_cast<std::size_t>(nodeCount_));
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            dropApplied_[d] = true;
        }
    int movers = 0;
    for (const WaterDisturbance& mover : desc_.disturbances) {
        if (time_ < mover.from || time_ >= mover.until) continue;
        const glm::dvec2 centre = mover.start + (time_ - mover.from) * mover.velocity;
        const std::string name = "mover[" + std::to_string(movers++) + "]";
        glProgramUniform4d(step_.id(), step_.uniform(name.c_str()), centre.x, centre.y, mover.strength, mover.radius);
    }
    glProgramUniform1i(step_.id(), step_.uniform("movers"), movers);
    glProgramUniform1d(step_.id(), step_.uniform("step_seconds"), dt);
    glProgramUniform1d(step_.id(), step_.uniform("half_damping"), 0.5 * desc_.damping * dt);
    height_[current_].bindStorage(layout::kWaterHeight);
    height_[1 - current_].bindStorage(layout::kWaterNextHeight);
    velocity_.bindStorage(layout::kWaterVelocity);
    dispatchOverEntries(step_, static_cast<std::size_t>(nodeCount_));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    current_ = 1 - current_;
    time_ += dt;
}

GpuWaterBody::PassTimes GpuWaterBody::advanceTo(double time, bool coverage) {
    glQueryCounter(timestamps_[0], GL_TIMESTAMP);
    const double remaining = time - time_;
    if (remaining > 0.0) {  // WaterSurface::advanceTo's steps
        const int steps = static_cast<int>(std::ceil(remaining / stableStep_));
        for (int s = 0; s < steps; ++s) step(remaining / steps);
    }
    writeSurface();
    glQueryCounter(timestamps_[1], GL_TIMESTAMP);
    if (coverage) writeCoverage();
    glQueryCounter(timestamps_[2], GL_TIMESTAMP);
    std::array<GLuint64, 3> ns{};
    for (std::size_t q = 0; q < ns.size(); ++q) glGetQueryObjectui64v(timestamps_[q], GL_QUERY_RESULT, &ns[q]);
    return {1e-6 * static_cast<double>(ns[1] - ns[0]), 1e-6 * static_cast<double>(ns[2] - ns[1])};
}

void GpuWaterBody::writeSurface() {
    height_[current_].bindStorage(layout::kWaterHeight);
    vertices_.bindStorage(layout::kWaterVertices);
    triangles_.bindStorage(layout::kWaterTriangles);
    faceNormals_.bindStorage(layout::kWaterFaceNormals);
    faceAngles_.bindStorage(layout::kWaterFaceAngles);
    dispatchOverEntries(faces_, static_cast<std::size_t>(triangleCount_));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    slots_.bindStorage(layout::kWaterSlots);
    cornerStart_.bindStorage(layout::kWaterCornerStart);
    corners_.bindStorage(layout::kWaterCorners);
    surfaceTriangles_.bindStorage(layout::kWaterSurfaceTriangles);
    dispatchOverEntries(cornerNormals_, static_cast<std::size_t>(triangleCount_));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    treeNodes_.bindStorage(layout::kWaterNodes);
    levelNodes_.bindStorage(layout::kWaterLevelNodes);
    surfaceNodes_.bindStorage(layout::kWaterSurfaceNodes);
    for (std::size_t level = 0; level + 1 < levelFirst_.size(); ++level) {
        const int count = levelFirst_[level + 1] - levelFirst_[level];
        glProgramUniform1i(refit_.id(), refit_.uniform("level_first"), levelFirst_[level]);
        glProgramUniform1i(refit_.id(), refit_.uniform("level_count"), count);
        dispatchOverEntries(refit_, static_cast<std::size_t>(count));
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
}

void GpuWaterBody::writeCoverage() {
    if (std::none_of(painted_.begin(), painted_.end(), [](const PaintedField& field) { return field.painted.id(); }))
        return;
    height_[current_].bindStorage(layout::kWaterHeight);
    for (const PaintedField& field : painted_) {
        if (!field.painted.id()) continue;
        field.base.bindStorage(field.baseBinding);
        field.painted.bindStorage(field.paintedBinding);
    }
    coverage_.use();
    coverage_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

std::vector<double> GpuWaterBody::downloadHeights() const { return height_[current_].downloadAll<double>(); }

}  // namespace eikon::sim::gpu
