// What a scene exports per frame for analysis (docs/scene-format.md,
// `export`): VTK ImageData for ParaView and OpenVDB grids for DCC tools.
// Plain data after validation, like the rest of Scene.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace eikon {

// Every array a frame can export, by the name it carries in the files.
// index and delta_index: n and δn = n − n_ref; extinction, scattering: κ, σs
// (RGB, 1/m); anisotropy: HG g; fluence: φ (RGB, W/m²); photon_direction: the
// power-weighted mean photon direction; velocity (m/s), temperature (K),
// concentration, dye: the simulation's (or an imported volume's) fields on
// the render grid; density, flame: an imported volume's grids; emission: ε
// (RGB, W/(m³·sr)) of a glowing volume.
inline constexpr std::array<const char*, 14> kExportFieldNames{
    "index",    "delta_index", "extinction",    "scattering", "anisotropy", "fluence", "photon_direction",
    "velocity", "temperature", "concentration", "dye",        "density",    "flame",   "emission"};

// An axis-aligned box in metres, max > min on every axis.
struct ExportRegion {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
};

// Which frames and arrays go out, and on which cells.
struct ExportSelection {
    bool enabled = false;
    std::vector<std::string> fields;    // names from kExportFieldNames; empty: every array the frame has
    int every = 1;                      // frames 0, k, 2k, … (>= 1)
    std::optional<ExportRegion> region;  // cells whose centres lie inside; absent: the whole grid
    int downsample = 1;                 // average d×d×d blocks of cells (>= 1)

    bool wants(const std::string& field) const {  // fields empty, or listed
        return fields.empty() || std::find(fields.begin(), fields.end(), field) != fields.end();
    }
    bool exportsFrame(int frame) const { return enabled && frame % every == 0; }
};

struct VtkExportDesc : ExportSelection {
    enum class Compression { Zlib, Lz4, None } compression = Compression::Zlib;
    bool receivers = true;   // DIR/vtk/receivers_NNNNN.vtp when the scene has receivers
    bool meshes = true;      // DIR/vtk/meshes_NNNNN.vtp: each frame's mesh and water surfaces, when the scene has any
    int photonPaths = 0;     // photons whose paths go to DIR/vtk/photon_paths_NNNNN.vtp (0: none)
    int pathVertices = 256;  // most vertices recorded per path, >= 2
};

struct VdbExportDesc : ExportSelection {
    // "z": files in a Z-up world (Blender's), eikon's (x, y, z) written as
    // (x, −z, y), velocities and directions turned with it; "y": as eikon's.
    enum class UpAxis { Y, Z } upAxis = UpAxis::Y;
};

struct ExportDesc {
    VtkExportDesc vtk;
    VdbExportDesc vdb;
};

}  // namespace eikon
