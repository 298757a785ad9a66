#include "io/vdb/VdbFrameWriter.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"
#include "io/files/FileBytes.h"
#include "io/vdb/VdbFileCheck.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace eikon::io {

namespace fs = std::filesystem;

namespace {

openvdb::math::Transform::Ptr cellTransform(const GridSpec& grid) {
    const glm::dvec3 h = grid.voxelSize();
    const glm::dvec3 centre = grid.boundsMin + 0.5 * h;
    const openvdb::Vec3d translation(centre.x, centre.y, centre.z);
    if (h.x == h.y && h.y == h.z) {
        auto transform = openvdb::math::Transform::createLinearTransform(h.x);
        transform->postTranslate(translation);
        return transform;
    }
    return std::make_shared<openvdb::math::Transform>(
        std::make_shared<openvdb::math::ScaleTranslateMap>(openvdb::Vec3d(h.x, h.y, h.z), translation));
}

// Values closer to the background than this share of the array's largest
// distance from it are background too (inactive): float noise around the
// value outside the grid does not keep a region dense.
constexpr float kBackgroundTolerance = 1e-6f;

// A sparse grid from x-fastest values, inactive where they are the
// background (within `tolerance`): OpenVDB's Dense with LayoutXYZ has x as
// its fastest index too.
template <class GridT>
typename GridT::Ptr sparseGrid(std::vector<typename GridT::ValueType>& values, const GridSpec& spec,
                               const typename GridT::ValueType& background, const typename GridT::ValueType& tolerance) {
    const glm::ivec3 r = spec.resolution;
    const openvdb::CoordBBox box(openvdb::Coord(0, 0, 0), openvdb::Coord(r.x - 1, r.y - 1, r.z - 1));
    openvdb::tools::Dense<typename GridT::ValueType, openvdb::tools::LayoutXYZ> dense(box, values.data());
    auto grid = GridT::create(background);
    openvdb::tools::copyFromDense(dense, *grid, tolerance);
    return grid;
}

// The largest |value − background| of an array, times kBackgroundTolerance.
float toleranceOf(const NamedArray& array) {
    float largest = 0.0f;
    for (std::size_t i = 0; i < array.values.size(); ++i) {
        const float background = array.components == 1 ? array.meaning.background : 0.0f;
        largest = std::max(largest, std::abs(array.values[i] - background));
    }
    return kBackgroundTolerance * largest;
}

// How Blender and Houdini should treat a grid: density-like scalars are fog
// volumes; velocities and directions turn with the grid (contravariant,
// relative); other vectors (RGB extinction, fluence) are per-channel values.
void describeGrid(openvdb::GridBase& grid, const NamedArray& array) {
    const ArrayRole role = array.meaning.role;
    if (array.components == 1) {
        grid.setGridClass(role == ArrayRole::Density ? openvdb::GRID_FOG_VOLUME : openvdb::GRID_UNKNOWN);
    } else {
        grid.setVectorType(role == ArrayRole::Velocity || role == ArrayRole::Direction
                               ? openvdb::VEC_CONTRAVARIANT_RELATIVE
                               : openvdb::VEC_INVARIANT);
    }
    if (!array.meaning.unit.empty()) grid.insertMeta("units", openvdb::StringMetadata(array.meaning.unit));
}

}  // namespace

VdbFrameWriter::VdbFrameWriter(const fs::path& outputFolder, std::string baseName, std::string sceneName, bool zUp)
    : directory_(outputFolder / "vdb"), baseName_(std::move(baseName)), sceneName_(std::move(sceneName)), zUp_(zUp) {
    const bool safe = !baseName_.empty() && baseName_ != "." && baseName_ != ".." &&
                      std::all_of(baseName_.begin(), baseName_.end(), [](char c) {
                          return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
                      });
    if (!safe) throw InputError("OpenVDB export base name", "letters, digits, '_', '-' or '.'", "\"" + baseName_ + "\"");
    std::error_code error;
    fs::create_directories(directory_, error);
    if (error || !fs::is_directory(directory_))
        throw InputError(directory_.string() + ": cannot create the OpenVDB export folder (" + error.message() + ")");
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

fs::path VdbFrameWriter::framePath(int frame) const {
    char number[16];
    std::snprintf(number, sizeof number, "%05d", frame);
    return directory_ / (baseName_ + "_" + number + ".vdb");
}

void VdbFrameWriter::writeFrame(int frame, double time, const ExportFrame& arrays) const {
    EIKON_CHECK_MSG(frame >= 0, "frame " + std::to_string(frame));
    EIKON_CHECK_MSG(std::isfinite(time), "time of frame " + std::to_string(frame));
    const std::size_t cells = arrays.grid.cellCount();
    const auto transform = cellTransform(arrays.grid);
    // Z-up: a quarter turn about x after the placement, (x, y, z) → (x, −z, y).
    if (zUp_) transform->postRotate(0.5 * openvdb::math::pi<double>(), openvdb::math::X_AXIS);
    openvdb::GridPtrVec grids;
    for (const NamedArray& array : arrays.arrays) {
        EIKON_CHECK_MSG((array.components == 1 || array.components == 3) &&
                            array.values.size() == static_cast<std::size_t>(array.components) * cells,
                        "OpenVDB array \"" + array.name + "\" size");
        openvdb::GridBase::Ptr grid;
        const float tolerance = toleranceOf(array);
        if (array.components == 1) {
            std::vector<float> values = array.values;
            grid = sparseGrid<openvdb::FloatGrid>(values, arrays.grid, array.meaning.background, tolerance);
        } else {
            std::vector<openvdb::Vec3s> values(cells);
            const ArrayRole role = array.meaning.role;
            const bool turns = zUp_ && (role == ArrayRole::Velocity || role == ArrayRole::Direction);
            for (std::size_t c = 0; c < cells; ++c) {
                const float x = array.values[3 * c], y = array.values[3 * c + 1], z = array.values[3 * c + 2];
                values[c] = turns ? openvdb::Vec3s(x, -z, y) : openvdb::Vec3s(x, y, z);
            }
            grid = sparseGrid<openvdb::Vec3SGrid>(values, arrays.grid, openvdb::Vec3s(0.0f),
                                                  openvdb::Vec3s(tolerance));
        }
        if (grid->activeVoxelCount() == 0) continue;  // all background: nothing a reader would not assume
        describeGrid(*grid, array);
        grid->setName(array.name);
        grid->setTransform(transform->copy());
        grids.push_back(grid);
    }
    openvdb::MetaMap meta;
    meta.insertMeta("frame", openvdb::Int32Metadata(frame));
    meta.insertMeta("time", openvdb::DoubleMetadata(time));
    if (!sceneName_.empty()) meta.insertMeta("scene", openvdb::StringMetadata(sceneName_));

    const fs::path path = framePath(frame);
    const fs::path temporary = temporaryPathFor(path);
    bool written = true;
    try {
        openvdb::io::File file(temporary.string());
        file.write(grids, meta);
        file.close();
    } catch (const openvdb::Exception&) {
        written = false;
    }
    // openvdb::io::File does not report a failed write: on a full disk it
    // closed a truncated file as if whole. So the file is walked as a reader
    // will walk it (VdbFileCheck.h) before it may take its final name.
    if (written) {
        try {
            const std::string bytes = readFileBytes(temporary);
            for (const VdbGridEntry& grid : checkVdbHeader(bytes, temporary.string()).grids)
                if (!grid.instance) checkVdbGrid(bytes, grid, temporary.string());
        } catch (const InputError&) {
            written = false;
        }
    }
    commitTemporary(temporary, path, written);
}

}  // namespace eikon::io
