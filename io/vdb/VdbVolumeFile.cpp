#include "io/vdb/VdbVolumeFile.h"

#include "bridge/core/Error.h"
#include "bridge/core/MemoryLimit.h"
#include "bridge/core/NumberFormat.h"
#include "io/vdb/VdbFileCheck.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <mutex>

namespace eikon::io {

namespace fs = std::filesystem;

struct VdbVolumeFile::Grids {
    std::string bytes;  // the whole file, as checked
    VdbFileLayout layout;
    std::unique_ptr<openvdb::io::File> file;
};

namespace {

void initializeOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

std::string readWholeFile(const fs::path& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw InputError(path.string(), "an OpenVDB file", "no such file");
    const std::uintmax_t size = fs::file_size(path, error);
    if (error) throw InputError(path.string(), "a readable OpenVDB file", error.message());
    if (size > VdbVolumeFile::maxFileBytes)
        throw InputError(path.string(), "an OpenVDB file of at most 2 GiB", std::to_string(size) + " bytes");
    std::ifstream in(path, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    if (!in) throw InputError(path.string(), "a readable OpenVDB file", "a read error");
    return bytes;
}

std::string quotedNames(const std::vector<std::string>& names) {
    if (names.empty()) return "no grids";
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
    return list;
}

InputError noGridNamed(const fs::path& path, const std::string& name, const std::vector<std::string>& names) {
    return InputError(path.string(), "a grid named \"" + name + "\"", "the grids " + quotedNames(names));
}

// The metadata of the grid `name` among `names` (its transform, its file's
// bounding box and resolution), without its voxels.
openvdb::GridBase::Ptr gridMetadata(openvdb::io::File& file, const fs::path& path, const std::string& name,
                                    const std::vector<std::string>& names) {
    if (std::find(names.begin(), names.end(), name) == names.end()) throw noGridNamed(path, name, names);
    try {
        return file.readGridMetadata(name);
    } catch (const std::exception& error) {
        throw InputError(path.string() + ": grid \"" + name + "\"", "readable metadata",
                         std::string("OpenVDB: ") + error.what());
    }
}

// Samples `grid` trilinearly at each render cell centre (x fastest),
// through one accessor per z slice (accessors are not thread-safe).
template <class GridT, class Sampler, class Store>
void sampleGrid(const GridT& grid, const GridSpec& spec, const glm::dmat4& sceneToFile, Store store) {
    const openvdb::math::Transform& transform = grid.transform();
    tbb::parallel_for(0, spec.resolution.z, [&](int k) {
        auto accessor = grid.getConstAccessor();
        for (int j = 0; j < spec.resolution.y; ++j)
            for (int i = 0; i < spec.resolution.x; ++i) {
                const glm::dvec3 x = glm::dvec3(sceneToFile * glm::dvec4(spec.cellCentre(i, j, k), 1.0));
                const openvdb::Vec3d index = transform.worldToIndex(openvdb::Vec3d(x.x, x.y, x.z));
                store(spec.linearIndex(i, j, k), Sampler::sample(accessor, index));
            }
    });
}

constexpr double kMaxIndexCoordinate = 1073741824.0;  // 2^30, half of OpenVDB's int32 Coord range

}  // namespace

VdbVolumeFile::VdbVolumeFile(const fs::path& path) : path_(path), grids_(std::make_unique<Grids>()) {
    initializeOpenVdb();
    grids_->bytes = readWholeFile(path);
    grids_->layout = checkVdbHeader(grids_->bytes, path.string());
    try {
        grids_->file = std::make_unique<openvdb::io::File>(path.string());
        grids_->file->open(/*delayLoad=*/false);
    } catch (const std::exception& error) {
        throw InputError(path.string(), "a valid OpenVDB file", std::string("OpenVDB: ") + error.what());
    }
}

VdbVolumeFile::~VdbVolumeFile() = default;
VdbVolumeFile::VdbVolumeFile(VdbVolumeFile&&) noexcept = default;
VdbVolumeFile& VdbVolumeFile::operator=(VdbVolumeFile&&) noexcept = default;

std::vector<std::string> VdbVolumeFile::gridNames() const {
    std::vector<std::string> names;
    for (const VdbGridEntry& grid : grids_->layout.grids) names.push_back(grid.name);
    return names;
}

int VdbVolumeFile::componentsOf(const std::string& name) const {
    for (const VdbGridEntry& grid : grids_->layout.grids)
        if (grid.name == name) return grid.valueType == "vec3s" ? 3 : 1;
    return 1;
}

VdbVolumeFile::GridFrame VdbVolumeFile::gridFrame(const std::string& name) const {
    const openvdb::GridBase::Ptr grid = gridMetadata(*grids_->file, path_, name, gridNames());
    GridFrame frame;
    const openvdb::Vec3d voxel = grid->voxelSize();
    frame.voxelSize = glm::dvec3(voxel[0], voxel[1], voxel[2]);
    if (const auto resolution = grid->getMetadata<openvdb::Vec3IMetadata>("file_base_resolution"))
        frame.baseResolution = glm::ivec3(resolution->value()[0], resolution->value()[1], resolution->value()[2]);
    return frame;
}

std::optional<std::vector<glm::dvec3>> VdbVolumeFile::activeBoxCorners(const std::string& name) const {
    const openvdb::GridBase::Ptr grid = gridMetadata(*grids_->file, path_, name, gridNames());
    const auto low = grid->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    const auto high = grid->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    if (!low || !high) return std::nullopt;
    const openvdb::Vec3i lo = low->value(), hi = high->value();
    if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) return std::nullopt;  // OpenVDB's empty box
    std::vector<glm::dvec3> corners;
    for (int corner = 0; corner < 8; ++corner) {
        const openvdb::Vec3d index(corner & 1 ? hi[0] + 0.5 : lo[0] - 0.5, corner & 2 ? hi[1] + 0.5 : lo[1] - 0.5,
                                   corner & 4 ? hi[2] + 0.5 : lo[2] - 0.5);
        const openvdb::Vec3d world = grid->transform().indexToWorld(index);
        corners.emplace_back(world[0], world[1], world[2]);
    }
    return corners;
}

std::vector<float> VdbVolumeFile::sample(const std::string& name, int components, const GridSpec& spec,
                                         const glm::dvec3& offset) const {
    return sample(name, components, spec, glm::translate(glm::dmat4(1.0), offset));
}

namespace {

// The render grid, mapped by `toIndex` (scene world to the grid's index
// coordinates, affine), must lie well within OpenVDB's 32-bit index
// coordinates (a voxel of 1e-220 m put cells at index 1e222; found by
// fuzz_vdb). The map is affine, so the grid's corners bound it.
template <typename ToIndex>
void checkIndexRange(const GridSpec& spec, ToIndex toIndex, const std::string& where) {
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 index = toIndex(glm::dvec3(corner & 1 ? spec.boundsMax.x : spec.boundsMin.x,
                                                    corner & 2 ? spec.boundsMax.y : spec.boundsMin.y,
                                                    corner & 4 ? spec.boundsMax.z : spec.boundsMin.z));
        for (int axis = 0; axis < 3; ++axis)
            if (!(std::abs(index[axis]) < kMaxIndexCoordinate))
                throw InputError(where,
                                 "a voxel size and placement (the scene's volume.transform, offset and up_axis) "
                                 "that map the render grid within OpenVDB's index range (|index| < 2^30)",
                                 "index " + formatRounded(index[axis]) + " at a corner of grid.bounds");
    }
}

[[noreturn]] void refuseTransform(const std::string& where, bool linear) {
    throw InputError(where, "an affine, invertible transform",
                     linear ? "a singular or non-finite one" : "a non-linear (frustum) one");
}

}  // namespace

void VdbVolumeFile::check(const std::string& name, int components, const GridSpec& spec,
                          const glm::dmat4& placement) const {
    EIKON_CHECK(components == 1 || components == 3);
    const std::string where = path_.string() + ": grid \"" + name + "\"";
    const VdbGridEntry* entry = nullptr;
    for (const VdbGridEntry& grid : grids_->layout.grids)
        if (grid.name == name && !entry) entry = &grid;
    if (!entry) throw noGridNamed(path_, name, gridNames());
    const std::string wanted = components == 1 ? "float" : "vec3s";
    if (entry->valueType != wanted)
        throw InputError(where, "a " + wanted + " grid", "a grid of type \"" + entry->treeType + "\"");
    // The map as the file stores it, which OpenVDB will apply unchecked, and
    // the tree's nodes, which OpenVDB allocates whole however few of their
    // voxels are active: a sparse file of scattered voxels holds a few bytes
    // for each 2 KiB leaf.
    const VdbGridCheck checked = checkVdbGrid(grids_->bytes, *entry, path_.string());
    const VdbTreeSize& tree = checked.tree;
    const MemoryLimit limit = machineMemoryLimit();
    if (limit.bytes && grids_->bytes.size() + tree.memoryBytes() > limit.bytes)
        throw InputError(where, "a grid whose tree fits " + limit.source + " as OpenVDB reads it (volume.path)",
                         std::to_string(tree.leaves) + " leaves and " +
                             std::to_string(tree.lowerNodes + tree.upperNodes) + " internal nodes, " +
                             mebibytes(tree.memoryBytes()) + " beside the file's " + mebibytes(grids_->bytes.size()));
    const glm::dmat4& worldToIndex = checked.worldToIndex;
    const double determinant = glm::determinant(worldToIndex);
    if (!std::isfinite(determinant) || determinant == 0.0) refuseTransform(where, true);
    const glm::dmat4 sceneToIndex = worldToIndex * glm::inverse(placement);
    checkIndexRange(spec, [&](const glm::dvec3& x) { return glm::dvec3(sceneToIndex * glm::dvec4(x, 1.0)); }, where);
}

std::vector<float> VdbVolumeFile::sample(const std::string& name, int components, const GridSpec& spec,
                                         const glm::dmat4& placement) const {
    check(name, components, spec, placement);
    const std::string where = path_.string() + ": grid \"" + name + "\"";
    openvdb::GridBase::Ptr base;
    try {
        base = grids_->file->readGrid(name);
    } catch (const std::exception& error) {
        throw InputError(where, "a readable grid", std::string("OpenVDB: ") + error.what());
    }
    // The transform as OpenVDB read it and samples by (check saw the same
    // bytes; OpenVDB's readGridMetadata can return another grid's in a
    // damaged file, found by fuzz_vdb).
    const openvdb::math::Transform& transform = base->transform();
    const openvdb::Vec3d voxel = transform.voxelSize();
    if (!transform.isLinear() || !std::isfinite(voxel[0] * voxel[1] * voxel[2]) ||
        !(std::abs(transform.baseMap()->determinant()) > 0.0) || !std::isfinite(transform.baseMap()->determinant()))
        refuseTransform(where, transform.isLinear());
    const glm::dmat4 sceneToFile = glm::inverse(placement);
    checkIndexRange(spec, [&](const glm::dvec3& x) {
        const glm::dvec3 world(sceneToFile * glm::dvec4(x, 1.0));
        const openvdb::Vec3d index = transform.worldToIndex(openvdb::Vec3d(world.x, world.y, world.z));
        return glm::dvec3(index[0], index[1], index[2]);
    }, where);
    std::vector<float> values(static_cast<std::size_t>(components) * spec.cellCount());
    if (components == 1) {
        const auto grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(base);
        EIKON_CHECK(grid != nullptr);
        sampleGrid<openvdb::FloatGrid, openvdb::tools::BoxSampler>(
            *grid, spec, sceneToFile, [&](std::size_t cell, float v) { values[cell] = v; });
    } else {
        const auto grid = openvdb::gridConstPtrCast<openvdb::Vec3SGrid>(base);
        EIKON_CHECK(grid != nullptr);
        auto store = [&](std::size_t cell, const openvdb::Vec3s& v) {
            for (int a = 0; a < 3; ++a) values[3 * cell + static_cast<std::size_t>(a)] = v[a];
        };
        if (grid->getGridClass() == openvdb::GRID_STAGGERED)
            sampleGrid<openvdb::Vec3SGrid, openvdb::tools::StaggeredBoxSampler>(*grid, spec, sceneToFile, store);
        else
            sampleGrid<openvdb::Vec3SGrid, openvdb::tools::BoxSampler>(*grid, spec, sceneToFile, store);
    }
    const auto bad = std::find_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); });
    if (bad != values.end()) {
        const auto cell = static_cast<std::size_t>(bad - values.begin()) / static_cast<std::size_t>(components);
        const auto nx = static_cast<std::size_t>(spec.resolution.x), ny = static_cast<std::size_t>(spec.resolution.y);
        const glm::dvec3 at = spec.cellCentre(static_cast<int>(cell % nx), static_cast<int>(cell / nx % ny),
                                              static_cast<int>(cell / (nx * ny)));
        throw InputError(where, "finite values", "a non-finite value sampled at " + formatPosition(at) +
                                                     " (the render grid's cell centre, in the scene's world)");
    }
    return values;
}

}  // namespace eikon::io
