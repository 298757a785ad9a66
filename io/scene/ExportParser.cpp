#include "io/scene/ExportParser.h"

#include "bridge/core/Error.h"
#include "io/export/ExportArrays.h"
#include "io/scene/VolumeFieldsParser.h"
#include "io/vtk/VtkVolumeSource.h"
#include "io/vdb/VolumeFramePath.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace eikon {
namespace {

constexpr long long kMaxEvery = 1000000;
constexpr long long kMaxDownsample = 64;
constexpr long long kMaxFrameNumber = 99999999;
constexpr long long kMaxPaths = 100000;
constexpr long long kMaxPathVertices = 4096;
constexpr long long kMaxRecordedVertices = 1LL << 22;

const NumberRange kPositive = NumberRange::above(0.0);
const NumberRange kNonNegative = NumberRange::atLeast(0.0);

std::string quotedFieldNames() {
    std::string list;
    for (const char* name : kExportFieldNames) list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    return list;
}

std::vector<std::string> readFieldNames(const JsonReader& node) {
    std::vector<std::string> names;
    const std::vector<JsonReader> elements = node.array();
    if (elements.empty()) node.fail("a non-empty array of field names (leave the key out for every field)", "[]");
    for (const JsonReader& element : elements) {
        const std::string name = element.string();
        if (std::find(kExportFieldNames.begin(), kExportFieldNames.end(), name) == kExportFieldNames.end())
            element.fail("one of " + quotedFieldNames(), "\"" + name + "\"");
        if (std::find(names.begin(), names.end(), name) != names.end())
            element.fail("each field listed once", "\"" + name + "\" again");
        names.push_back(name);
    }
    return names;
}

ExportRegion readRegion(const JsonReader& node) {
    const auto corners = node.object({"min", "max"});
    ExportRegion region{corners.member("min").vec3(), corners.member("max").vec3()};
    for (int axis = 0; axis < 3; ++axis) {
        if (region.max[axis] > region.min[axis]) continue;
        corners.member("max").element(axis).fail("a number > " + corners.member("min").element(axis).path() + " = " +
                                                      formatNumber(region.min[axis]) + " (the region must not be empty)",
                                                  formatNumber(region.max[axis]));
    }
    return region;
}

void readSelection(const JsonObjectReader& fields, ExportSelection& selection) {
    selection.enabled = true;
    if (auto enabled = fields.optional("enabled")) selection.enabled = enabled->boolean();
    if (auto names = fields.optional("fields")) selection.fields = readFieldNames(*names);
    if (auto every = fields.optional("every")) selection.every = static_cast<int>(every->integer(1, kMaxEvery));
    if (auto region = fields.optional("region")) selection.region = readRegion(*region);
    if (auto d = fields.optional("downsample")) selection.downsample = static_cast<int>(d->integer(1, kMaxDownsample));
}

VtkExportDesc readVtk(const JsonReader& node) {
    VtkExportDesc vtk;
    const auto fields = node.object({"enabled", "fields", "every", "region", "downsample", "compression", "receivers",
                                     "meshes", "photon_paths", "path_vertices"});
    readSelection(fields, vtk);
    if (auto receivers = fields.optional("receivers")) vtk.receivers = receivers->boolean();
    if (auto meshes = fields.optional("meshes")) vtk.meshes = meshes->boolean();
    if (auto paths = fields.optional("photon_paths")) vtk.photonPaths = static_cast<int>(paths->integer(0, kMaxPaths));
    if (auto vertices = fields.optional("path_vertices"))
        vtk.pathVertices = static_cast<int>(vertices->integer(2, kMaxPathVertices));
    const long long recorded = static_cast<long long>(vtk.photonPaths) * vtk.pathVertices;
    if (recorded > kMaxRecordedVertices)
        fields.member("photon_paths").fail("photon_paths × path_vertices <= " + std::to_string(kMaxRecordedVertices) +
                                               " (32 bytes of GPU memory each)",
                                           std::to_string(recorded));
    if (auto compression = fields.optional("compression")) {
        const std::string name = compression->oneOf({"zlib", "lz4", "none"});
        vtk.compression = name == "zlib" ? VtkExportDesc::Compression::Zlib
                          : name == "lz4" ? VtkExportDesc::Compression::Lz4
                                          : VtkExportDesc::Compression::None;
    }
    return vtk;
}

VdbExportDesc readVdb(const JsonReader& node) {
    VdbExportDesc vdb;
    const auto fields = node.object({"enabled", "fields", "every", "region", "downsample", "up_axis"});
    readSelection(fields, vdb);
    if (auto up = fields.optional("up_axis"))
        vdb.upAxis = up->oneOf({"y", "z"}) == "z" ? VdbExportDesc::UpAxis::Z : VdbExportDesc::UpAxis::Y;
    return vdb;
}

const NumberRange kTurnRange = NumberRange::closed(-3600.0, 3600.0);

// Blender's object matrix: scale, then turns about x, y and z in that order
// (XYZ Euler), then the translation.
glm::dmat4 objectMatrix(const glm::dvec3& translate, const glm::dvec3& turnsDeg, const glm::dvec3& scale) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
    m = glm::rotate(m, glm::radians(turnsDeg.z), glm::dvec3(0.0, 0.0, 1.0));
    m = glm::rotate(m, glm::radians(turnsDeg.y), glm::dvec3(0.0, 1.0, 0.0));
    m = glm::rotate(m, glm::radians(turnsDeg.x), glm::dvec3(1.0, 0.0, 0.0));
    return glm::scale(m, scale);
}

// volume.transform: {"translate", "rotate_deg", "scale"} in Blender's order
// (scale, then turns about x, y and z in that order, then the translation:
// its object transform with the XYZ Euler rotation) or {"matrix"}: 16
// numbers row by row, affine (last row 0 0 0 1) and invertible.
glm::dmat4 readVolumeTransform(const JsonReader& node) {
    const auto fields = node.object({"translate", "rotate_deg", "scale", "matrix"});
    if (auto matrix = fields.optional("matrix")) {
        for (const char* key : {"translate", "rotate_deg", "scale"})
            if (fields.optional(key)) fields.member(key).fail("nothing but the matrix beside a matrix", "\"" + std::string(key) + "\"");
        const std::vector<JsonReader> entries = matrix->array();
        if (entries.size() != 16) matrix->fail("16 numbers, row by row", std::to_string(entries.size()) + " elements");
        glm::dmat4 m(1.0);
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column)
                m[column][row] = entries[static_cast<std::size_t>(4 * row + column)].number(kCoordinateRange);
        if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
            matrix->fail("an affine matrix (last row 0, 0, 0, 1)", "a last row of " + formatNumber(m[0][3]) + ", " +
                                                                       formatNumber(m[1][3]) + ", " +
                                                                       formatNumber(m[2][3]) + ", " + formatNumber(m[3][3]));
        const double determinant = glm::determinant(glm::dmat3(m));
        if (!(std::abs(determinant) > 1e-30))
            matrix->fail("an invertible matrix", "determinant " + formatNumber(determinant));
        return m;
    }
    glm::dvec3 translate(0.0), turns(0.0), scale(1.0);
    if (auto t = fields.optional("translate")) translate = t->vec3(kCoordinateRange);
    if (auto r = fields.optional("rotate_deg")) turns = r->vec3(kTurnRange);
    if (auto s = fields.optional("scale")) scale = glm::dvec3(s->rgb(kLengthRange));
    return objectMatrix(translate, turns, scale);
}

// A Z-up file's world (Blender's) in eikon's Y-up one: (x, y, z) → (x, z, −y).
glm::dmat4 zUpToYUp() {
    glm::dmat4 m(1.0);
    m[1] = glm::dvec4(0.0, 0.0, -1.0, 0.0);
    m[2] = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    return m;
}

// Blender's grid names: its data cache (fluid_data_####.vdb) holds density,
// temperature (heat), flame and velocity; its noise cache
// (fluid_noise_####.vdb, what Blender renders when Noise is on, as Quick
// Smoke sets it) holds density_noise (and flame_noise for a fire) — its
// heat and velocity stay in the data cache, at the base resolution.
void useBlenderGridNames(const std::filesystem::path& path, VolumeDesc& volume) {
    const bool noise = path.filename().string().rfind("fluid_noise_", 0) == 0;
    volume.densityGrid = noise ? "density_noise" : "density";
    volume.temperatureGrid = noise ? "" : "temperature";
    volume.flameGrid = noise ? "" : "flame";
    volume.velocityGrid = noise ? "" : "velocity";
}

// A grid name: any non-empty string (spaces allowed), "" to skip the grid.
std::string readGridName(const JsonReader& node) { return node.string(); }

void readGridNames(const JsonReader& node, VolumeDesc& volume) {
    const auto fields = node.object({"density", "temperature", "flame", "velocity", "index", "delta_index",
                                     "extinction", "scattering", "anisotropy", "emission"});
    for (const auto& [key, name] : {std::pair{"density", &volume.densityGrid}, {"temperature", &volume.temperatureGrid},
                                    {"flame", &volume.flameGrid}, {"velocity", &volume.velocityGrid},
                                    {"index", &volume.indexGrid}, {"delta_index", &volume.deltaIndexGrid},
                                    {"extinction", &volume.extinctionGrid}, {"scattering", &volume.scatteringGrid},
                                    {"anisotropy", &volume.anisotropyGrid}, {"emission", &volume.emissionGrid}})
        if (auto grid = fields.optional(key)) *name = readGridName(*grid);
    if (!volume.indexGrid.empty() && !volume.deltaIndexGrid.empty())
        fields.member("delta_index").fail("\"\" when `index` names a grid (both would set the index)",
                                          "\"" + volume.deltaIndexGrid + "\"");
}

// volume.emission, emission_scale, flame_absorption, emission_lights: each
// refused where it could have no effect.
void readVolumeEmission(const JsonObjectReader& fields, VolumeDesc& volume) {
    if (auto v = fields.optional("flame_absorption")) {
        volume.flameAbsorption = v->number(kAttenuationRange);
        if (volume.flameGrid.empty()) v->fail("no flame_absorption without a flame grid (grids.flame)", "a flame_absorption");
    }
    if (auto v = fields.optional("emission"))
        volume.emission = v->oneOf({"none", "blackbody"}) == "blackbody" ? VolumeDesc::Emission::Blackbody
                                                                         : VolumeDesc::Emission::None;
    const bool blackbody = volume.emission == VolumeDesc::Emission::Blackbody;
    if (auto v = fields.optional("emission_scale")) {
        volume.emissionScale = v->number(kNonNegative);
        if (!blackbody) v->fail("no emission_scale without emission \"blackbody\"", formatNumber(volume.emissionScale));
    }
    if (blackbody) {
        const JsonReader node = fields.member("emission");
        if (volume.temperatureGrid.empty() && volume.flameGrid.empty())
            node.fail("a temperature or flame grid for emission \"blackbody\" (it glows by temperature)",
                      "neither grids.temperature nor grids.flame");
        const bool absorbs = volume.flameAbsorption > 0.0 || !volume.extinctionGrid.empty() ||
                             (!volume.densityGrid.empty() && volume.densityExtinction != volume.densityScattering);
        if (!absorbs)
            node.fail("something that absorbs for emission \"blackbody\" (Kirchhoff: ε = κa·B(T); set "
                      "flame_absorption, density_extinction above density_scattering, or grids.extinction)",
                      "no absorption");
    }
    if (auto v = fields.optional("emission_lights")) {
        volume.emissionLights = v->boolean();
        if (volume.emissionLights && !blackbody && volume.emissionGrid.empty())
            v->fail("no emission_lights without emission (emission \"blackbody\" or grids.emission)", "true");
    }
}

// Exported fields that only some scenes have, and what provides them.
bool sceneProvides(const Scene& scene, const std::string& field) {
    const bool sim = scene.sim.has_value();
    const bool volume = scene.volume.has_value();
    if (field == "velocity") return sim || (volume && !scene.volume->velocityGrid.empty());
    if (field == "temperature") return sim || (volume && !scene.volume->temperatureGrid.empty());
    if (field == "concentration" || field == "dye") return sim;
    if (field == "density") return volume && !scene.volume->densityGrid.empty();
    if (field == "flame") return volume && !scene.volume->flameGrid.empty();
    if (field == "emission")
        return volume && (scene.volume->emission == VolumeDesc::Emission::Blackbody || !scene.volume->emissionGrid.empty());
    return true;
}

void resolveSelection(const JsonReader& node, const ExportSelection& selection, Scene& scene) {
    if (!selection.enabled) return;
    if (selection.region) {
        const GridSpec grid = scene.grid.spec();
        if (!io::cellsInRegion(grid, *selection.region))
            node.member("region").fail("a box holding at least one cell centre of the grid", "a box outside the grid");
    }
    for (std::size_t i = 0; i < selection.fields.size(); ++i) {
        const std::string& field = selection.fields[i];
        if (!sceneProvides(scene, field))
            node.member("fields").element(i).fail(
                "a field this scene has (\"" + field + "\" needs a `sim` section or a `volume` grid for it, "
                "emission a glowing volume)",
                "\"" + field + "\"");
        if (field == "fluence" || field == "photon_direction") scene.tracer.storeFluence = true;
    }
}

}  // namespace

void readExport(const JsonReader& node, Scene& scene) {
    const auto fields = node.object({"vtk", "vdb"});
    if (auto vtk = fields.optional("vtk")) {
        scene.exports.vtk = readVtk(*vtk);
        resolveSelection(*vtk, scene.exports.vtk, scene);
    }
    if (auto vdb = fields.optional("vdb")) {
        scene.exports.vdb = readVdb(*vdb);
        resolveSelection(*vdb, scene.exports.vdb, scene);
    }
}

VolumeDesc readVolume(const JsonReader& node, const std::string& sceneFolder) {
    VolumeDesc volume;
    const auto fields = node.object({"path", "frame_start", "frame_time", "preset", "blender_domain", "grids",
                                     "offset", "up_axis", "transform",
                                     "density_extinction",
                                     "density_scattering", "anisotropy", "ambient_temperature", "temperature_scale",
                                     "flame_temperature", "refractivity", "reference_temperature", "pressure",
                                     "emission", "emission_scale", "flame_absorption", "emission_lights", "fields",
                                     "gladstone_dale"});
    const JsonReader pathNode = fields.member("path");
    const std::filesystem::path path = pathNode.string();
    volume.path = (path.is_absolute() ? path : std::filesystem::path(sceneFolder) / path).string();
    const std::string name = path.filename().string();
    const std::size_t first = name.find('#');
    if (first != std::string::npos) {
        const std::size_t last = name.find_last_of('#');
        if (name.find_first_not_of('#', first) < last)
            pathNode.fail("a file name with at most one run of '#' (the frame number)", "\"" + name + "\"");
        if (path.parent_path().string().find('#') != std::string::npos)
            pathNode.fail("'#' only in the file name, not in its folders", "\"" + path.string() + "\"");
        volume.sequence = true;
    }
    if (io::isVtkVolumePath(volume.path)) volume.format = VolumeDesc::Format::Vtk;
    checkVolumeReaderKeys(fields, volume);
    if (auto start = fields.optional("frame_start")) volume.frameStart = static_cast<int>(start->integer(0, kMaxFrameNumber));
    if (auto time = fields.optional("frame_time")) volume.frameTime = time->number(kPositive);
    // Presets: the grid names and axes of a Blender (Mantaflow) or Houdini
    // cache; the explicit keys below still override them.
    const std::string preset = fields.optional("preset") ? fields.member("preset").oneOf({"none", "blender", "houdini"})
                                                         : std::string("none");
    bool zUp = preset == "blender";
    glm::dmat4 transform(1.0);
    if (preset == "blender") {
        useBlenderGridNames(path, volume);
        if (fields.optional("transform"))
            fields.member("transform").fail("no `transform` with preset \"blender\" (blender_domain places the cache)",
                                            "a transform");
        const JsonReader domain = fields.member("blender_domain");
        // The cache's box goes centred on `center`, the domain's bounding-box
        // centre in Blender's world, or on `location`, the object's origin,
        // which is that centre only while the origin was not moved.
        const auto keys = domain.object({"location", "center", "rotation_deg", "dimensions"});
        if (keys.optional("location") && keys.optional("center"))
            keys.member("center").fail("either `center` or `location` (the origin, where it is the box's centre)",
                                       "both");
        const glm::dvec3 location = keys.member(keys.optional("center") ? "center" : "location").vec3(kCoordinateRange);
        const glm::dvec3 rotation = keys.optional("rotation_deg") ? keys.member("rotation_deg").vec3(kTurnRange)
                                                                  : glm::dvec3(0.0);
        volume.blenderDomainDimensions = keys.member("dimensions").vec3(kLengthRange);
        transform = objectMatrix(location, rotation, glm::dvec3(1.0));
    } else {
        if (fields.optional("blender_domain"))
            fields.member("blender_domain").fail("no `blender_domain` without preset \"blender\"", "a domain");
        if (preset == "houdini") {
            volume.flameGrid = "flame";
            volume.velocityGrid = "vel";
        }
        if (fields.optional("transform")) transform = readVolumeTransform(fields.member("transform"));
    }
    if (auto grids = fields.optional("grids")) readGridNames(*grids, volume);
    if (auto declared = fields.optional("fields")) readVolumeFields(*declared, volume);
    glm::dvec3 offset(0.0);
    if (auto v = fields.optional("offset")) offset = v->vec3(kCoordinateRange);
    if (fields.optional("up_axis")) zUp = fields.member("up_axis").oneOf({"y", "z"}) == "z";
    volume.placement = glm::translate(glm::dmat4(1.0), offset) * (zUp ? zUpToYUp() : glm::dmat4(1.0)) * transform;
    if (auto v = fields.optional("density_extinction")) volume.densityExtinction = v->rgb(kAttenuationRange);
    if (auto v = fields.optional("density_scattering")) {
        volume.densityScattering = v->rgb(kNonNegative);
        for (int channel = 0; channel < 3; ++channel) {
            if (volume.densityScattering[channel] <= volume.densityExtinction[channel]) continue;
            v->fail("density_scattering <= density_extinction in every channel",
                    formatNumber(volume.densityScattering[channel]) + " in channel " + std::to_string(channel));
        }
    }
    if (auto v = fields.optional("anisotropy")) {
        volume.anisotropy = v->number(kAnisotropyRange);
        if (!volume.anisotropyGrid.empty())
            v->fail("no value when grids.anisotropy names a grid (both would set g)", formatNumber(volume.anisotropy));
    }
    if (auto v = fields.optional("ambient_temperature")) volume.ambientTemperature = v->number(kPositive);
    if (auto v = fields.optional("temperature_scale")) volume.temperatureScale = v->number(kNonNegative);
    if (auto v = fields.optional("flame_temperature")) volume.flameTemperature = v->number(kNonNegative);
    if (auto v = fields.optional("refractivity")) volume.refractivity = v->number(kPositive);
    if (auto v = fields.optional("reference_temperature")) volume.referenceTemperature = v->number(kPositive);
    if (auto v = fields.optional("pressure")) volume.pressure = v->number(kPositive);
    if (auto v = fields.optional("gladstone_dale")) volume.gladstoneDale = v->number(kPositive);
    checkVolumeFieldKeys(fields, volume);
    if (volume.densityGrid.empty() && volume.temperatureGrid.empty() && volume.flameGrid.empty() &&
        volume.gasDensityGrid.empty() && volume.pressureGrid.empty() &&
        volume.indexGrid.empty() && volume.deltaIndexGrid.empty() && volume.extinctionGrid.empty() &&
        volume.scatteringGrid.empty() && volume.emissionGrid.empty())
        fields.member("grids").fail("at least one grid named (density, temperature, flame, or an optical grid)",
                                    "every grid left empty");
    readVolumeEmission(fields, volume);

    if (volume.format == VolumeDesc::Format::Vtk) {
        if (!std::filesystem::exists(volume.path))
            pathNode.fail("an existing VTK file or OpenFOAM case folder (relative paths start at the scene file's folder)",
                          "\"" + volume.path + "\", which does not exist");
        return volume;
    }
    const std::string firstFile = volumeFramePath(volume, volume.frameStart);
    if (!std::filesystem::is_regular_file(firstFile))
        pathNode.fail(std::string("an existing .vdb file") + (volume.sequence ? " for frame_start" : "") +
                          " (relative paths start at the scene file's folder)",
                      "\"" + firstFile + "\", which does not exist");
    return volume;
}

}  // namespace eikon
