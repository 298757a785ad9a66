#include "io/scene/MeshObjectParser.h"

#include "io/scene/ComputeDeviceParser.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>

namespace eikon {
namespace {

constexpr int kMaxWaterCells = 4096;
constexpr int kMaxArapIterations = 1000;
constexpr long long kMaxSeed = 4294967295LL;
const NumberRange kPositive = NumberRange::above(0.0);
const NumberRange kNonNegative = NumberRange::atLeast(0.0);

glm::dvec2 readVec2(const JsonReader& node) {
    const std::vector<JsonReader> elements = node.array();
    if (elements.size() != 2) node.fail("an array of 2 numbers [x, z]");
    return {elements[0].number(), elements[1].number()};
}

glm::dvec3 readUnit(const JsonReader& node) {
    const glm::dvec3 v = node.vec3();
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) node.fail("a non-zero vector");
    return v / length;
}

Placement readPlacement(const JsonObjectReader& fields) {
    Placement placement;
    if (auto v = fields.optional("translate")) placement.translate = v->vec3(kCoordinateRange);
    if (auto v = fields.optional("rotate_deg")) placement.rotateDeg = v->vec3();
    if (auto v = fields.optional("scale")) placement.scale = v->number(kLengthRange);
    return placement;
}

// Times must strictly increase along a key list.
template <class Key>
void requireIncreasingTimes(const std::vector<Key>& keys, const std::vector<JsonReader>& nodes) {
    for (std::size_t k = 1; k < keys.size(); ++k)
        if (!(keys[k].time > keys[k - 1].time))
            nodes[k].member("time").fail("a time > " + formatNumber(keys[k - 1].time) + " (keys in increasing time)",
                                         formatNumber(keys[k].time));
}

std::vector<PoseKey> readPoseKeys(const JsonReader& node) {
    std::vector<PoseKey> keys;
    const std::vector<JsonReader> nodes = node.array();
    if (nodes.empty()) node.fail("an array of at least one key");
    for (const JsonReader& element : nodes) {
        const auto fields = element.object({"time", "translate", "rotate_deg", "scale"});
        keys.push_back({fields.member("time").number(), readPlacement(fields)});
    }
    requireIncreasingTimes(keys, nodes);
    return keys;
}

std::vector<AmountKey> readAmountKeys(const JsonReader& node) {
    std::vector<AmountKey> keys;
    const std::vector<JsonReader> nodes = node.array();
    if (nodes.empty()) node.fail("an array of at least one key");
    for (const JsonReader& element : nodes) {
        const auto fields = element.object({"time", "deg_per_m"});
        keys.push_back({fields.member("time").number(), fields.member("deg_per_m").number()});
    }
    requireIncreasingTimes(keys, nodes);
    return keys;
}

void requireNonEmptyBox(const JsonObjectReader& fields, const glm::dvec3& min, const glm::dvec3& max) {
    for (int axis = 0; axis < 3; ++axis)
        if (!(max[axis] > min[axis]))
            fields.member("max").element(axis).fail("a number > min = " + formatNumber(min[axis]),
                                                    formatNumber(max[axis]));
}

DeformerDesc readDeformer(const JsonReader& node) {
    DeformerDesc deformer;
    const std::string type = node.member("type").oneOf({"rigid", "twist", "bend", "arap"});
    if (type == "rigid") {
        const auto fields = node.object({"type", "keys"});
        deformer.kind = DeformerDesc::Kind::Rigid;
        deformer.keys = readPoseKeys(fields.member("keys"));
    } else if (type == "twist" || type == "bend") {
        const bool bend = type == "bend";
        const auto fields = bend ? node.object({"type", "origin", "axis", "toward", "keys"})
                                 : node.object({"type", "origin", "axis", "keys"});
        deformer.kind = bend ? DeformerDesc::Kind::Bend : DeformerDesc::Kind::Twist;
        if (auto v = fields.optional("origin")) deformer.origin = v->vec3();
        if (auto v = fields.optional("axis")) deformer.axis = readUnit(*v);
        if (bend) {
            const JsonReader towardNode = fields.member("toward");
            const glm::dvec3 toward = towardNode.vec3();
            const glm::dvec3 across = toward - glm::dot(toward, deformer.axis) * deformer.axis;
            if (!(glm::length(across) > 1e-9 * glm::length(toward)))
                towardNode.fail("a direction not parallel to the axis", formatNumber(toward.x) + ", " +
                                                                            formatNumber(toward.y) + ", " +
                                                                            formatNumber(toward.z));
            deformer.toward = glm::normalize(across);
        }
        deformer.amount = readAmountKeys(fields.member("keys"));
    } else {
        const auto fields = node.object({"type", "handles", "iterations"});
        deformer.kind = DeformerDesc::Kind::Arap;
        if (auto v = fields.optional("iterations")) deformer.iterations = static_cast<int>(v->integer(1, kMaxArapIterations));
        const JsonReader handlesNode = fields.member("handles");
        for (const JsonReader& element : handlesNode.array()) {
            const auto handle = element.object({"min", "max", "keys"});
            HandleDesc desc{handle.member("min").vec3(), handle.member("max").vec3(), {}};
            requireNonEmptyBox(handle, desc.regionMin, desc.regionMax);
            if (auto keys = handle.optional("keys")) desc.keys = readPoseKeys(*keys);
            deformer.handles.push_back(desc);
        }
        if (deformer.handles.empty()) handlesNode.fail("an array of at least one handle");
    }
    return deformer;
}

WaterDesc readWater(const JsonObjectReader& fields) {
    WaterDesc water;
    const auto basin = fields.member("basin").object({"min", "max"});
    water.basinMin = basin.member("min").vec3();
    water.basinMax = basin.member("max").vec3();
    requireNonEmptyBox(basin, water.basinMin, water.basinMax);
    if (auto v = fields.optional("cells")) {
        const std::vector<JsonReader> n = v->array();
        if (n.size() != 2) v->fail("an array of 2 integers [along x, along z]");
        water.cells = glm::ivec2(n[0].integer(3, kMaxWaterCells), n[1].integer(3, kMaxWaterCells));
    }
    if (auto v = fields.optional("wave_speed")) water.waveSpeed = v->number(kPositive);
    if (auto v = fields.optional("damping")) water.damping = v->number(kNonNegative);
    if (auto swell = fields.optional("swell")) {
        const auto s = swell->object({"amplitude", "wavelength", "waves", "seed"});
        water.swellAmplitude = s.member("amplitude").number(kNonNegative);
        water.swellWavelength = s.member("wavelength").number(kPositive);
        if (auto v = s.optional("waves")) water.swellWaves = static_cast<int>(v->integer(1, 1000));
        if (auto v = s.optional("seed")) water.seed = static_cast<unsigned>(v->integer(0, kMaxSeed));
    }
    if (auto drops = fields.optional("drops"))
        for (const JsonReader& element : drops->array()) {
            const auto d = element.object({"time", "position", "amplitude", "radius"});
            WaterDrop drop;
            drop.time = d.member("time").number(kNonNegative);
            drop.position = readVec2(d.member("position"));
            if (auto v = d.optional("amplitude")) drop.amplitude = v->number();
            if (auto v = d.optional("radius")) drop.radius = v->number(kPositive);
            water.drops.push_back(drop);
        }
    if (auto movers = fields.optional("disturbances"))
        for (const JsonReader& element : movers->array()) {
            const auto d = element.object({"start", "velocity", "from", "until", "strength", "radius"});
            WaterDisturbance mover;
            mover.start = readVec2(d.member("start"));
            if (auto v = d.optional("velocity")) mover.velocity = readVec2(*v);
            if (auto v = d.optional("from")) mover.from = v->number(kNonNegative);
            if (auto v = d.optional("until")) {
                mover.until = v->number();
                if (!(mover.until > mover.from)) v->fail("a time > from = " + formatNumber(mover.from), formatNumber(mover.until));
            }
            if (auto v = d.optional("strength")) mover.strength = v->number();
            if (auto v = d.optional("radius")) mover.radius = v->number(kPositive);
            water.disturbances.push_back(mover);
        }
    if (auto v = fields.optional("device")) water.device = readComputeDevice(*v);
    return water;
}

}  // namespace

ObjectDesc readMeshOrWaterObject(const JsonReader& node, const std::string& type, const std::string& sceneFolder,
                                 const PropertiesReader& readProperties) {
    ObjectDesc object;
    if (type == "mesh") {
        const auto fields =
            node.object({"type", "mesh", "deformer", "index", "extinction", "scattering", "anisotropy", "surface",
                                    "fresnel"});
        object.kind = ObjectDesc::Kind::Mesh;
        const auto mesh = fields.member("mesh").object({"path", "translate", "rotate_deg", "scale"});
        const JsonReader pathNode = mesh.member("path");
        const std::filesystem::path path = pathNode.string();
        object.mesh.path = (path.is_absolute() ? path : std::filesystem::path(sceneFolder) / path).string();
        if (!std::filesystem::is_regular_file(object.mesh.path))
            pathNode.fail("an existing mesh file (relative paths start at the scene file's folder)",
                          "\"" + object.mesh.path + "\", which does not exist");
        object.mesh.placement = readPlacement(mesh);
        if (auto deformer = fields.optional("deformer")) object.mesh.deformer = readDeformer(*deformer);
        readProperties(fields, object);
    } else {
        const auto fields = node.object({"type", "basin", "cells", "wave_speed", "damping", "swell", "drops",
                                         "disturbances", "device", "index", "extinction", "scattering", "anisotropy",
                                         "surface", "fresnel"});
        object.kind = ObjectDesc::Kind::Water;
        object.water = readWater(fields);
        readProperties(fields, object);
    }
    return object;
}

}  // namespace eikon
