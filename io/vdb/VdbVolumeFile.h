// One OpenVDB file, read defensively, whose grids are sampled onto a dense
// render grid. Sparse grids stay sparse: each render cell centre is looked
// up in the tree (trilinear, OpenVDB's BoxSampler in the grid's index
// space, StaggeredBoxSampler for staggered vector grids), never by copying
// the file's grids into dense arrays.
//
// Debian's OpenVDB 10.0.1 trusts sizes it reads from a file. Before OpenVDB
// sees a byte, the header and the table of grids are checked here (magic,
// version, every string and metadata size, grid offsets within the file);
// OpenVDB then reads from an in-memory stream that throws at its end, so a
// truncated or corrupted file ends in an InputError naming the file, never
// in a crash or a read past the end. The header is OpenVDB's file format
// (openvdb/io/Archive.cc, GridDescriptor.cc, MetaMap.cc).
//
// The header keeps OpenVDB out of its includes; only the .cpp sees it.
#pragma once

#include <glm/mat4x4.hpp>

#include "bridge/grid/GridSpec.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon::io {

class VdbVolumeFile {
public:
    // Reads every grid of the file. InputError naming the file when it is
    // missing, larger than maxFileBytes, or not a valid OpenVDB file.
    explicit VdbVolumeFile(const std::filesystem::path& path);
    ~VdbVolumeFile();
    VdbVolumeFile(VdbVolumeFile&&) noexcept;
    VdbVolumeFile& operator=(VdbVolumeFile&&) noexcept;

    static constexpr std::uintmax_t maxFileBytes = std::uintmax_t{2} << 30;  // 2 GiB

    const std::filesystem::path& path() const { return path_; }
    std::vector<std::string> gridNames() const;  // in file order

    // The grid called `name` sampled at the centre of each cell of `grid`
    // (x fastest), shifted by −offset into the file's world frame:
    // `components` = 1 needs a float grid (half-float on disk reads as
    // float), 3 a vec3s grid. Outside the grid's active voxels the sample is
    // the grid's background. InputError naming the file and grid when the
    // file has no grid of that name (listing the grids it has), the grid has
    // another type, a transform that is not affine and invertible, or a
    // sample that is not finite.
    std::vector<float> sample(const std::string& name, int components, const GridSpec& grid,
                              const glm::dvec3& offset) const;
    // The same through `placement`, an affine map of the file's world into
    // the render grid's: each cell centre x is looked up at placement⁻¹·x.
    // Vector values come as stored, in the file's frame.
    std::vector<float> sample(const std::string& name, int components, const GridSpec& grid,
                              const glm::dmat4& placement) const;
    // What sample refuses before it reads a value: a missing grid, another
    // type, a damaged tree (every node, size and compressed chunk, as
    // VdbFileCheck walks them), a transform that is not affine and
    // invertible or that maps the render grid outside OpenVDB's index range.
    // Walks the file's bytes only, building no tree: a few milliseconds for
    // a file whose grids take a second to sample (bench/vdb_check_bench.cpp).
    void check(const std::string& name, int components, const GridSpec& grid, const glm::dmat4& placement) const;
    // Grid `name`'s voxel size (its transform's, per axis) and Mantaflow's
    // `file_base_resolution` metadata (the domain's cells per axis), absent
    // where the grid lacks it. InputError as sample's for a missing grid.
    struct GridFrame {
        glm::dvec3 voxelSize{0.0};
        std::optional<glm::ivec3> baseResolution;
    };
    GridFrame gridFrame(const std::string& name) const;
    // The eight corners, in the file's world, of the box of grid `name`'s
    // active voxels (whole voxels: index box ± ½), from the statistics
    // OpenVDB writes beside each grid (file_bbox_min, file_bbox_max):
    // nullopt where the file lacks them or the grid has no active voxel.
    // InputError as sample's for a missing grid.
    std::optional<std::vector<glm::dvec3>> activeBoxCorners(const std::string& name) const;
    // 3 when the file's grid `name` is a vec3s grid, else 1 (sample then
    // says what it found, or that there is no such grid).
    int componentsOf(const std::string& name) const;

private:
    struct Grids;
    std::filesystem::path path_;
    std::unique_ptr<Grids> grids_;
};

}  // namespace eikon::io
