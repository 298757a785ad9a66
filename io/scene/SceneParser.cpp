#include "io/scene/SceneParser.h"

#include "bridge/core/Error.h"
#include "bridge/core/MemoryLimit.h"
#include "bridge/layout/GpuLayouts.h"
#include "io/files/FileBytes.h"
#include "io/image/ImageIo.h"
#include "io/scene/CameraProjectionParser.h"
#include "io/scene/DiagnosticParser.h"
#include "io/scene/DuplicateKeyCheck.h"
#include "io/scene/JsonErrorPosition.h"
#include "io/scene/ExportParser.h"
#include "io/scene/GridFit.h"
#include "io/scene/JsonReader.h"
#include "io/scene/MeshObjectParser.h"
#include "io/scene/PaintParser.h"
#include "io/scene/ComputeDeviceParser.h"
#include "io/scene/RenderMethodParser.h"
#include "io/scene/SceneOverride.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace eikon {
namespace {

constexpr long long kMaxGridCells = 512LL * 512 * 512;
constexpr long long kMaxPhotons = 2147483647LL;  // 2^31 - 1
constexpr int kMaxImageEdge = 16384;
constexpr long long kMaxSamplesPerPixel = 1024;  // camera rays a pixel, 32²
constexpr int kMaxReceiverResolution = 4096;
constexpr int kMaxSupersampling = 16;
constexpr long long kMaxSeed = 4294967295LL;  // 2^32 - 1
constexpr int kMaxSmoothingWindow = 63;
constexpr long long kMaxTracerSteps = 2147483647LL;  // 2^31 - 1
constexpr long long kMaxSubsteps = 10000;
constexpr long long kMaxSubstepLimit = 1000000;  // sim.max_substeps: a frame of a million substeps is hours

const NumberRange kPositive = NumberRange::above(0.0);
const NumberRange kNonNegative = NumberRange::atLeast(0.0);
// Light powers (W) and irradiances (W/m²) whose sums over photons and
// channels stay far from a double's overflow (the Sun emits 3.8e26 W).
const NumberRange kLightPower = NumberRange::closed(0.0, 1e30);
// Refractive indices: the fields hold n − n_ref in float32, which must leave
// n > 0 (an index of 1e-300 became 0 at some cell).
const NumberRange kRefractiveIndex = NumberRange::closed(1e-3, 1e3);

std::string formatVector(const glm::dvec3& v) {
    return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}

// v / |v|, or zero for the zero vector; pre-scaled so that |v| cannot overflow.
glm::dvec3 normalizedOrZero(const glm::dvec3& v) {
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest == 0.0 ? glm::dvec3(0.0) : glm::normalize(v / largest);
}

// A non-zero vector, scaled to unit length.
glm::dvec3 readDirection(const JsonReader& node) {
    const glm::dvec3 v = node.vec3();
    const glm::dvec3 unit = normalizedOrZero(v);
    if (unit == glm::dvec3(0.0)) node.fail("a non-zero vector", formatVector(v));
    return unit;
}

// Checks max > min on every axis; the error points at the offending max element.
void requireNonEmpty(const JsonReader& minNode, const glm::dvec3& min, const JsonReader& maxNode,
                     const glm::dvec3& max) {
    for (int axis = 0; axis < 3; ++axis) {
        if (max[axis] > min[axis]) continue;
        maxNode.element(axis).fail("a number > " + minNode.element(axis).path() + " = " + formatNumber(min[axis]) +
                                       " (the bounds must not be empty)",
                                   formatNumber(max[axis]));
    }
}

// Optional extinction and scattering (default 0), with scattering <= extinction.
void readAttenuation(const JsonObjectReader& fields, Material& material) {
    if (auto node = fields.optional("extinction")) material.extinction = node->rgb(kAttenuationRange);
    if (auto node = fields.optional("anisotropy")) material.anisotropy = node->number(kAnisotropyRange);
    if (auto node = fields.optional("scattering")) {
        material.scattering = node->rgb(kAttenuationRange);
        for (int channel = 0; channel < 3; ++channel) {
            if (material.scattering[channel] <= material.extinction[channel]) continue;
            node->fail("scattering <= extinction " + formatVector(material.extinction) + " in every channel",
                       formatVector(material.scattering));
        }
    }
}

// An odd kernel width; absence (not 0) in the file means automatic.
int readOddWindow(const JsonReader& node) {
    const int window = static_cast<int>(node.integer(1, kMaxSmoothingWindow));
    if (window % 2 == 0) {
        node.fail("an odd integer in [1, " + std::to_string(kMaxSmoothingWindow) + "] (the kernel has a centre voxel)",
                  std::to_string(window));
    }
    return window;
}

GridDesc readGrid(const JsonReader& node) {
    GridDesc grid;
    const auto fields =
        node.object({"resolution", "bounds", "fit", "smoothing_sigma_voxels", "smoothing_window_voxels", "supersampling"});
    if (auto resolution = fields.optional("resolution")) {
        grid.resolution = resolution->ivec3(1, static_cast<int>(kMaxGridCells));
        const glm::ivec3 n = grid.resolution;
        const double cells = static_cast<double>(n.x) * n.y * n.z;  // a 64-bit integer product could overflow
        if (cells > static_cast<double>(kMaxGridCells)) {
            const std::string found =
                std::to_string(n.x) + " x " + std::to_string(n.y) + " x " + std::to_string(n.z) + " cells";
            resolution->fail("at most " + std::to_string(kMaxGridCells) + " cells (512^3) in total", found);
        }
    }
    if (auto bounds = fields.optional("bounds")) {
        const auto corners = bounds->object({"min", "max"});
        grid.boundsMin = corners.member("min").vec3(kCoordinateRange);
        grid.boundsMax = corners.member("max").vec3(kCoordinateRange);
        requireNonEmpty(corners.member("min"), grid.boundsMin, corners.member("max"), grid.boundsMax);
    }
    grid.fitVolume = readGridFit(fields);
    if (auto sigma = fields.optional("smoothing_sigma_voxels")) grid.smoothingSigmaVoxels = sigma->number(kNonNegative);
    if (auto window = fields.optional("smoothing_window_voxels")) grid.smoothingWindowVoxels = readOddWindow(*window);
    if (auto samples = fields.optional("supersampling")) {
        grid.supersampling = static_cast<int>(samples->integer(1, kMaxSupersampling));
    }
    return grid;
}

AirTemperatureProfile readAirProfile(const JsonReader& node) {
    const auto fields = node.object({"ground_height", "ground_temperature", "air_temperature", "scale_height", "pressure"});
    AirTemperatureProfile profile;
    if (auto v = fields.optional("ground_height")) profile.groundHeight = v->number();
    profile.groundTemperature = fields.member("ground_temperature").number(kPositive);
    profile.airTemperature = fields.member("air_temperature").number(kPositive);
    profile.scaleHeight = fields.member("scale_height").number(kPositive);
    if (auto v = fields.optional("pressure")) profile.pressure = v->number(kPositive);
    return profile;
}

void readMedium(const JsonReader& node, Scene& scene) {
    Material& medium = scene.medium;
    const auto fields = node.object({"index", "extinction", "scattering", "anisotropy", "air_temperature_profile"});
    if (auto index = fields.optional("index")) medium.index = index->number(kRefractiveIndex);
    readAttenuation(fields, medium);
    if (auto profile = fields.optional("air_temperature_profile")) scene.airProfile = readAirProfile(*profile);
}

// `surface` (sharp | smooth) and `fresnel` of an object.
void readSurface(const JsonObjectReader& fields, ObjectDesc& object) {
    if (auto surface = fields.optional("surface"))
        object.surface = surface->oneOf({"sharp", "smooth"}) == "sharp" ? ObjectDesc::Surface::Sharp
                                                                        : ObjectDesc::Surface::Smooth;
    if (auto fresnel = fields.optional("fresnel")) object.fresnel = fresnel->boolean();
}

ObjectDesc readObject(const JsonReader& node, const std::string& sceneFolder) {
    ObjectDesc object;
    const std::string type = node.member("type").oneOf({"sphere", "box", "mesh", "water"});
    if (type == "mesh" || type == "water") {
        return readMeshOrWaterObject(node, type, sceneFolder, [](const JsonObjectReader& fields, ObjectDesc& shaped) {
            shaped.material.index = fields.member("index").number(kRefractiveIndex);
            readAttenuation(fields, shaped.material);
            readSurface(fields, shaped);
        });
    }
    if (type == "sphere") {
        const auto fields = node.object(
            {"type", "center", "radius", "index", "extinction", "scattering", "anisotropy", "surface", "fresnel"});
        object.kind = ObjectDesc::Kind::Sphere;
        object.sphere.center = fields.member("center").vec3(kCoordinateRange);
        object.sphere.radius = fields.member("radius").number(kLengthRange);
        object.material.index = fields.member("index").number(kRefractiveIndex);
        readAttenuation(fields, object.material);
        readSurface(fields, object);
    } else {
        const auto fields = node.object(
            {"type", "min", "max", "index", "extinction", "scattering", "anisotropy", "surface", "fresnel"});
        object.kind = ObjectDesc::Kind::Box;
        object.box.min = fields.member("min").vec3(kCoordinateRange);
        object.box.max = fields.member("max").vec3(kCoordinateRange);
        requireNonEmpty(fields.member("min"), object.box.min, fields.member("max"), object.box.max);
        object.material.index = fields.member("index").number(kRefractiveIndex);
        readAttenuation(fields, object.material);
        readSurface(fields, object);
    }
    return object;
}

// Cone half-angle in (0, 180) and a soft edge in [0, cone]; the default edge
// shrinks to fit a cone narrower than it.
void readSpotCone(const JsonObjectReader& fields, LightDesc& light) {
    if (auto cone = fields.optional("cone_angle_deg")) light.coneAngleDeg = cone->number(NumberRange::open(0.0, 180.0));
    light.falloffDeg = std::min(light.falloffDeg, light.coneAngleDeg);
    if (auto falloff = fields.optional("falloff_deg")) {
        light.falloffDeg = falloff->number(kNonNegative);
        if (light.falloffDeg > light.coneAngleDeg) {
            falloff->fail("a number in [0, " + fields.member("cone_angle_deg").path() + " = " +
                              formatNumber(light.coneAngleDeg) + "] (the soft edge lies inside the cone)",
                          formatNumber(light.falloffDeg));
        }
    }
}

LightDesc readLight(const JsonReader& node) {
    LightDesc light;
    const std::string type = node.member("type").oneOf({"point", "spot", "directional"});
    if (type == "point") {
        const auto fields = node.object({"type", "position", "power"});
        light.kind = LightDesc::Kind::Point;
        light.position = fields.member("position").vec3(kCoordinateRange);
        light.power = fields.member("power").rgb(kLightPower);
    } else if (type == "spot") {
        const auto fields =
            node.object({"type", "position", "direction", "power", "cone_angle_deg", "falloff_deg"});
        light.kind = LightDesc::Kind::Spot;
        light.position = fields.member("position").vec3(kCoordinateRange);
        light.direction = readDirection(fields.member("direction"));
        light.power = fields.member("power").rgb(kLightPower);
        readSpotCone(fields, light);
    } else {
        const auto fields = node.object({"type", "direction", "irradiance"});
        light.kind = LightDesc::Kind::Directional;
        light.direction = readDirection(fields.member("direction"));
        light.irradiance = fields.member("irradiance").rgb(kLightPower);
    }
    return light;
}

// The wavefront estimator's maps need no filter (and it traces no bounces):
// its receivers default to "none" and refuse "bounce".
ReceiverDesc readReceiver(const JsonReader& node, TracerDesc::Estimator estimator) {
    const bool wavefront = estimator == TracerDesc::Estimator::Wavefront;
    ReceiverDesc receiver;
    if (wavefront) receiver.filter = ReceiverDesc::Filter::None;
    node.member("type").oneOf({"plane"});
    const auto fields = node.object({"type", "point", "normal", "albedo", "size", "resolution", "bounce", "filter"});
    receiver.point = fields.member("point").vec3(kCoordinateRange);
    receiver.normal = readDirection(fields.member("normal"));
    if (auto albedo = fields.optional("albedo")) receiver.albedo = albedo->rgb(NumberRange::closed(0.0, 1.0));
    if (auto size = fields.optional("size")) receiver.size = size->number(kLengthRange);
    if (auto resolution = fields.optional("resolution")) {
        receiver.resolution = static_cast<int>(resolution->integer(1, kMaxReceiverResolution));
    }
    if (auto bounce = fields.optional("bounce")) {
        receiver.bounce = bounce->boolean();
        if (receiver.bounce && wavefront)
            bounce->fail("false with tracer.estimator \"wavefront\" (it traces no bounces; \"photons\" does)", "true");
    }
    if (auto filter = fields.optional("filter")) {
        const std::string name = filter->oneOf({"binomial", "none", "adaptive"});
        receiver.filter = name == "none"       ? ReceiverDesc::Filter::None
                          : name == "adaptive" ? ReceiverDesc::Filter::Adaptive
                                               : ReceiverDesc::Filter::Binomial;
    }
    return receiver;
}

CameraDesc readCamera(const JsonReader& node) {
    CameraDesc camera;
    const auto fields = node.object({"position", "target", "up", "fov_deg", "projection", "width_m"});
    if (auto position = fields.optional("position")) camera.position = position->vec3(kCoordinateRange);
    if (auto target = fields.optional("target")) camera.target = target->vec3(kCoordinateRange);
    if (auto up = fields.optional("up")) camera.up = up->vec3();
    if (auto fov = fields.optional("fov_deg")) camera.fovDeg = fov->number(NumberRange::open(0.0, 180.0));
    readCameraProjection(fields, camera);

    const glm::dvec3 view = normalizedOrZero(camera.target - camera.position);
    if (view == glm::dvec3(0.0)) {
        fields.member("target").fail("a point other than camera.position " + formatVector(camera.position),
                                     formatVector(camera.target));
    }
    const double sine = glm::length(glm::cross(normalizedOrZero(camera.up), view));
    if (sine < 1e-6) {
        fields.member("up").fail("a non-zero vector not parallel to the view direction " + formatVector(view),
                                 formatVector(camera.up));
    }
    return camera;
}

EnvironmentDesc readEnvironment(const JsonReader& node, const std::string& sceneFolder) {
    EnvironmentDesc environment;
    const std::string type = node.member("type").oneOf({"uniform", "sky", "hdr"});
    if (type == "uniform") {
        const auto fields = node.object({"type", "radiance"});
        if (auto radiance = fields.optional("radiance")) environment.radiance = radiance->rgb(kNonNegative);
    } else if (type == "sky") {
        environment.kind = EnvironmentDesc::Kind::Sky;
        const auto fields = node.object(
            {"type", "zenith", "horizon", "ground_a", "ground_b", "ground_height", "checker_size"});
        if (auto value = fields.optional("zenith")) environment.zenith = value->rgb(kNonNegative);
        if (auto value = fields.optional("horizon")) environment.horizon = value->rgb(kNonNegative);
        if (auto value = fields.optional("ground_a")) environment.groundA = value->rgb(kNonNegative);
        if (auto value = fields.optional("ground_b")) environment.groundB = value->rgb(kNonNegative);
        if (auto value = fields.optional("ground_height")) environment.groundHeight = value->number();
        if (auto value = fields.optional("checker_size")) environment.checkerSize = value->number(kPositive);
    } else {
        environment.kind = EnvironmentDesc::Kind::Hdr;
        const auto fields = node.object({"type", "path", "intensity", "rotation_deg"});
        const JsonReader pathNode = fields.member("path");
        const std::filesystem::path path = pathNode.string();
        environment.path = (path.is_absolute() ? path : std::filesystem::path(sceneFolder) / path).string();
        if (!std::filesystem::is_regular_file(environment.path))
            pathNode.fail("an existing .hdr file (relative paths start at the scene file's folder)",
                          "\"" + environment.path + "\", which does not exist");
        const MemoryLimit limit = machineMemoryLimit();  // checked before the image is decoded
        const std::uint64_t decoding = io::floatImageDecodingBytes(environment.path);
        if (limit.bytes && decoding > limit.bytes)
            pathNode.fail("an image whose decoding fits " + limit.source,
                          "\"" + environment.path + "\", " + mebibytes(decoding) + " to decode");
        environment.image = std::make_shared<const FloatImage>(io::readFloatImage(environment.path));
        if (auto value = fields.optional("intensity")) environment.intensity = value->number(kNonNegative);
        if (auto value = fields.optional("rotation_deg")) environment.rotationDeg = value->number();
    }
    return environment;
}

RenderDesc readRender(const JsonReader& node, const std::string& sceneFolder) {
    RenderDesc render;
    const auto fields = node.object({"photons", "width", "height", "seed", "exposure_ev", "step_voxels", "background",
                                     "environment", "write_hdr", "surface_depth", "samples_per_pixel", "error_estimate",
                                     "warn_error", "method", "method_fallback", "caustic_map_texels", "device"});
    if (auto photons = fields.optional("photons")) render.photons = photons->integer(1, kMaxPhotons);
    if (auto width = fields.optional("width")) render.width = static_cast<int>(width->integer(1, kMaxImageEdge));
    if (auto height = fields.optional("height")) render.height = static_cast<int>(height->integer(1, kMaxImageEdge));
    if (auto seed = fields.optional("seed")) render.seed = static_cast<unsigned>(seed->integer(0, kMaxSeed));
    if (auto exposure = fields.optional("exposure_ev")) render.exposureEv = exposure->number();
    if (auto step = fields.optional("step_voxels")) render.stepVoxels = step->number(kPositive);
    if (auto background = fields.optional("background")) {
        if (fields.optional("environment")) background->fail("either background or environment, not both", "both");
        render.environment.radiance = background->rgb(kNonNegative);
    }
    if (auto environment = fields.optional("environment")) render.environment = readEnvironment(*environment, sceneFolder);
    if (auto writeHdr = fields.optional("write_hdr")) render.writeHdr = writeHdr->boolean();
    if (auto depth = fields.optional("surface_depth"))
        render.surfaceDepth = static_cast<int>(depth->integer(0, 8));
    if (auto samples = fields.optional("samples_per_pixel")) {
        render.samplesPerPixel = static_cast<int>(samples->integer(1, kMaxSamplesPerPixel));
        const auto side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(render.samplesPerPixel))));
        if (side * side != render.samplesPerPixel)
            samples->fail("a square number (the rays pass through a k × k grid of the pixel): 1, 4, 9, 16, ...",
                          std::to_string(render.samplesPerPixel));
    }
    if (auto estimate = fields.optional("error_estimate")) render.errorEstimate = estimate->boolean();
    if (auto warn = fields.optional("warn_error")) render.warnError = warn->number(kPositive);
    if (auto device = fields.optional("device")) render.device = readComputeDevice(*device);
    readRenderMethod(fields, render);
    return render;
}

// A number >= `low`, the value already read for the key `lowKey` of the same
// object (low > 0); absent, the larger of `fallback` and `low`.
double readAtLeast(const JsonObjectReader& fields, const std::string& key, double fallback, const std::string& lowKey,
                   double low) {
    const auto node = fields.optional(key);
    if (!node) return std::max(fallback, low);
    const double value = node->number();
    if (value < low) {
        node->fail("a number >= " + fields.member(lowKey).path() + " = " + formatNumber(low), formatNumber(value));
    }
    return value;
}

TracerDesc::Integrator readIntegrator(const JsonReader& node) {
    const std::string name = node.oneOf({"euler", "leapfrog", "rk4"});
    if (name == "euler") return TracerDesc::Integrator::Euler;
    return name == "leapfrog" ? TracerDesc::Integrator::Leapfrog : TracerDesc::Integrator::Rk4;
}

TracerDesc::StepPolicy readStepPolicy(const JsonReader& node) {
    return node.oneOf({"uniform", "octree"}) == "uniform" ? TracerDesc::StepPolicy::Uniform
                                                          : TracerDesc::StepPolicy::Octree;
}

TracerDesc readTracer(const JsonReader& node) {
    TracerDesc tracer;
    const auto fields = node.object({"integrator", "step_policy", "step_voxels", "max_step_voxels", "epsilon",
                                     "epsilon_prime", "renormalize", "power_cutoff", "max_steps", "dispersion",
                                     "store_fluence", "estimator", "wavefront", "multiple_scattering", "lbm_directions",
                                     "lbm_tolerance", "lbm_max_iterations"});
    if (auto integrator = fields.optional("integrator")) tracer.integrator = readIntegrator(*integrator);
    if (auto policy = fields.optional("step_policy")) tracer.stepPolicy = readStepPolicy(*policy);
    if (auto step = fields.optional("step_voxels")) tracer.stepVoxels = step->number(kPositive);
    tracer.maxStepVoxels =
        readAtLeast(fields, "max_step_voxels", tracer.maxStepVoxels, "step_voxels", tracer.stepVoxels);
    if (auto epsilon = fields.optional("epsilon")) tracer.epsilon = epsilon->number(kPositive);
    tracer.epsilonPrime = readAtLeast(fields, "epsilon_prime", tracer.epsilonPrime, "epsilon", tracer.epsilon);
    if (auto renormalize = fields.optional("renormalize")) tracer.renormalize = renormalize->boolean();
    if (auto cutoff = fields.optional("power_cutoff")) {
        tracer.powerCutoff = cutoff->number(NumberRange{0.0, 1.0, true, false});
    }
    if (auto steps = fields.optional("max_steps")) tracer.maxSteps = steps->integer(0, kMaxTracerSteps);
    if (auto dispersion = fields.optional("dispersion")) tracer.dispersion = dispersion->rgb(kPositive);
    if (auto store = fields.optional("store_fluence")) tracer.storeFluence = store->boolean();
    if (auto estimator = fields.optional("estimator"))
        tracer.estimator = estimator->oneOf({"photons", "wavefront"}) == "wavefront" ? TracerDesc::Estimator::Wavefront
                                                                                     : TracerDesc::Estimator::Photons;
    if (auto multiple = fields.optional("multiple_scattering"))
        tracer.multipleScattering = multiple->oneOf({"none", "lbm"}) == "lbm" ? TracerDesc::MultipleScattering::Lbm
                                                                              : TracerDesc::MultipleScattering::None;
    if (auto directions = fields.optional("lbm_directions")) {
        const long long count = directions->integer(6, 18);
        if (count != 6 && count != 14 && count != 18) directions->fail("6, 14 or 18", std::to_string(count));
        tracer.lattice.directions = static_cast<int>(count);
    }
    if (auto tolerance = fields.optional("lbm_tolerance"))
        tracer.lattice.tolerance = tolerance->number(NumberRange::open(0.0, 1.0));
    if (auto cap = fields.optional("lbm_max_iterations"))
        tracer.lattice.maxIterations = static_cast<int>(cap->integer(1, 1000000));
    if (auto wavefront = fields.optional("wavefront")) {
        const auto keys = wavefront->object({"grid_cells", "max_depth", "split_texels", "tear_texels", "min_power", "max_patches",
                                             "reflections", "reflection_split", "split_voxels"});
        TracerDesc::Wavefront& w = tracer.wavefront;
        if (auto cells = keys.optional("grid_cells")) w.gridCells = static_cast<int>(cells->integer(1, 1024));
        if (auto depth = keys.optional("max_depth")) w.maxDepth = static_cast<int>(depth->integer(0, 20));
        if (auto split = keys.optional("split_texels")) w.splitTexels = split->number(NumberRange::closed(0.05, 1e6));
        if (auto tear = keys.optional("tear_texels")) w.tearTexels = tear->number(NumberRange::closed(0.01, 1e6));
        if (auto split = keys.optional("split_voxels")) w.splitVoxels = split->number(NumberRange::closed(0.05, 1e6));
        if (auto power = keys.optional("min_power")) w.minPower = power->number(NumberRange::closed(0.0, 1.0));
        if (auto reflections = keys.optional("reflections"))
            w.reflections = static_cast<int>(reflections->integer(0, 16));
        if (auto split = keys.optional("reflection_split"))
            w.reflectionSplit = split->number(NumberRange::closed(0.0, 1.0));
        if (auto patches = keys.optional("max_patches")) w.maxPatches = patches->integer(1024, 1 << 24);
    }
    return tracer;
}

template <class Item, class ReadItem>
std::vector<Item> readList(const JsonObjectReader& fields, const std::string& key, ReadItem readItem) {
    std::vector<Item> items;
    if (auto list = fields.optional(key)) {
        for (const JsonReader& element : list->array()) items.push_back(readItem(element));
    }
    return items;
}

BoxShape readRegion(const JsonObjectReader& fields) {
    BoxShape box{fields.member("min").vec3(), fields.member("max").vec3()};
    requireNonEmpty(fields.member("min"), box.min, fields.member("max"), box.max);
    return box;
}

SimDesc::Obstacle readSimObstacle(const JsonReader& node) {
    SimDesc::Obstacle obstacle;
    if (node.member("type").oneOf({"box", "sphere"}) == "box") {
        obstacle.kind = SimDesc::Obstacle::Kind::Box;
        obstacle.box = readRegion(node.object({"type", "min", "max"}));
    } else {
        const auto fields = node.object({"type", "center", "radius"});
        obstacle.kind = SimDesc::Obstacle::Kind::Sphere;
        obstacle.sphere.center = fields.member("center").vec3(kCoordinateRange);
        obstacle.sphere.radius = fields.member("radius").number(kLengthRange);
    }
    return obstacle;
}

SimDesc::Source readSimSource(const JsonReader& node) {
    SimDesc::Source source;
    if (node.member("type").oneOf({"hot_plate", "jet"}) == "hot_plate") {
        const auto fields = node.object({"type", "min", "max", "temperature"});
        source.kind = SimDesc::Source::Kind::HotPlate;
        source.region = readRegion(fields);
        source.temperature = fields.member("temperature").number(kPositive);
    } else {
        const auto fields = node.object({"type", "min", "max", "velocity", "concentration", "dye"});
        source.kind = SimDesc::Source::Kind::Jet;
        source.region = readRegion(fields);
        source.velocity = fields.member("velocity").vec3();
        if (auto c = fields.optional("concentration")) source.concentration = c->number(NumberRange::closed(0.0, 1.0));
        if (auto dye = fields.optional("dye")) source.dye = dye->number(kNonNegative);
    }
    return source;
}

void readSimBoundaries(const JsonReader& node, SimDesc& sim) {
    const char* const faces[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    const auto fields = node.object({"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"});
    for (int face = 0; face < 6; ++face) {
        if (auto kind = fields.optional(faces[face])) {
            sim.boundaries[face] =
                kind->oneOf({"closed", "open"}) == "open" ? SimDesc::Boundary::Open : SimDesc::Boundary::Closed;
        }
    }
}

void readSimOptics(const JsonReader& node, SimDesc& sim) {
    const auto fields = node.object({"refractivity", "reference_temperature", "reference_pressure", "index_a",
                                     "index_b", "mixing", "dye_extinction", "dye_scattering"});
    if (auto v = fields.optional("refractivity")) sim.refractivity = v->number(kPositive);
    if (auto v = fields.optional("reference_temperature")) sim.referenceTemperature = v->number(kPositive);
    if (auto v = fields.optional("reference_pressure")) sim.referencePressure = v->number(kPositive);
    if (auto v = fields.optional("index_a")) sim.indexA = v->number(kRefractiveIndex);
    if (auto v = fields.optional("index_b")) sim.indexB = v->number(kRefractiveIndex);
    if (auto v = fields.optional("mixing")) {
        sim.mixing = v->oneOf({"linear", "lorentz_lorenz"}) == "linear" ? SimDesc::Mixing::Linear
                                                                        : SimDesc::Mixing::LorentzLorenz;
    }
    Material dye;  // dye coefficients obey the same rule as a material's: σs <= κ per channel
    if (auto v = fields.optional("dye_extinction")) dye.extinction = v->rgb(kAttenuationRange);
    if (auto v = fields.optional("dye_scattering")) {
        dye.scattering = v->rgb(kAttenuationRange);
        for (int channel = 0; channel < 3; ++channel) {
            if (dye.scattering[channel] <= dye.extinction[channel]) continue;
            v->fail("dye_scattering <= dye_extinction " + formatVector(dye.extinction) + " in every channel",
                    formatVector(dye.scattering));
        }
    }
    sim.dyeExtinction = dye.extinction;
    sim.dyeScattering = dye.scattering;
}

// The `sim` section; fluid-dependent defaults (docs/scene-format.md) apply to
// keys left out.
SimDesc readSim(const JsonReader& node) {
    SimDesc sim;
    const auto fields = node.object({"fluid", "device", "resolution", "bounds", "frame_time", "substeps", "max_substeps", "cfl",
                                     "gravity",
                                     "thermal_expansion", "concentration_expansion", "viscosity",
                                     "thermal_diffusivity", "concentration_diffusivity", "dye_diffusivity",
                                     "pressure_tolerance", "vorticity_confinement", "boundaries", "obstacles", "sources",
                                     "ambient_temperature", "ambient_pressure", "optics"});
    if (auto fluid = fields.optional("fluid"); fluid && fluid->oneOf({"air", "liquid"}) == "liquid") {
        sim.fluid = SimDesc::Fluid::Liquid;  // water at 20 °C, sucrose syrup as liquid B
        sim.thermalExpansion = 2.07e-4;
        sim.concentrationExpansion = 0.289;  // (1286.5 − 998.2) / 998.2 kg/m³, 60 % sucrose against water
        sim.viscosity = 1.0e-6;
        sim.thermalDiffusivity = 1.43e-7;
        sim.concentrationDiffusivity = 5.2e-10;  // sucrose in water
    }
    if (auto device = fields.optional("device")) sim.device = readComputeDevice(*device);
    if (auto resolution = fields.optional("resolution")) {
        sim.resolution = resolution->ivec3(1, static_cast<int>(kMaxGridCells));
        const double cells = static_cast<double>(sim.resolution.x) * sim.resolution.y * sim.resolution.z;
        if (cells > static_cast<double>(kMaxGridCells)) {
            resolution->fail("at most " + std::to_string(kMaxGridCells) + " cells (512^3) in total",
                             formatNumber(cells) + " cells");
        }
    }
    if (auto bounds = fields.optional("bounds")) sim.bounds = readRegion(bounds->object({"min", "max"}));
    if (auto v = fields.optional("frame_time")) sim.frameTime = v->number(kPositive);
    if (auto v = fields.optional("substeps")) sim.substeps = static_cast<int>(v->integer(1, kMaxSubsteps));
    sim.maxSubsteps = std::max(sim.maxSubsteps, sim.substeps);
    if (auto v = fields.optional("max_substeps")) {
        sim.maxSubsteps = static_cast<int>(v->integer(1, kMaxSubstepLimit));
        if (sim.maxSubsteps < sim.substeps)
            v->fail("at least sim.substeps (" + std::to_string(sim.substeps) + ")", std::to_string(sim.maxSubsteps));
    }
    if (auto v = fields.optional("cfl")) sim.cfl = v->number(kPositive);
    if (auto v = fields.optional("gravity")) sim.gravity = v->vec3();
    if (auto v = fields.optional("ambient_temperature")) sim.ambientTemperature = v->number(kPositive);
    if (auto v = fields.optional("ambient_pressure")) sim.ambientPressure = v->number(kPositive);
    if (sim.fluid == SimDesc::Fluid::Air) sim.thermalExpansion = 1.0 / sim.ambientTemperature;  // ideal gas
    if (auto v = fields.optional("thermal_expansion")) sim.thermalExpansion = v->number(kNonNegative);
    if (auto v = fields.optional("concentration_expansion")) sim.concentrationExpansion = v->number(kNonNegative);
    if (auto v = fields.optional("viscosity")) sim.viscosity = v->number(kNonNegative);
    if (auto v = fields.optional("thermal_diffusivity")) sim.thermalDiffusivity = v->number(kNonNegative);
    if (auto v = fields.optional("concentration_diffusivity")) sim.concentrationDiffusivity = v->number(kNonNegative);
    if (auto v = fields.optional("dye_diffusivity")) sim.dyeDiffusivity = v->number(kNonNegative);
    if (auto v = fields.optional("pressure_tolerance")) sim.pressureTolerance = v->number(NumberRange::open(0.0, 1.0));
    if (auto v = fields.optional("vorticity_confinement")) sim.vorticityConfinement = v->number(kNonNegative);
    if (auto boundaries = fields.optional("boundaries")) readSimBoundaries(*boundaries, sim);
    sim.obstacles = readList<SimDesc::Obstacle>(fields, "obstacles", readSimObstacle);
    sim.sources = readList<SimDesc::Source>(fields, "sources", readSimSource);
    if (auto optics = fields.optional("optics")) readSimOptics(*optics, sim);
    return sim;
}

// 1-based line and column of a parse error at byte offset `byte` (1-based, as
// nlohmann reports it: the last character read).
std::string lineAndColumn(const std::string& text, std::size_t byte) {
    const std::size_t errorIndex = std::min(byte == 0 ? 0 : byte - 1, text.size());
    std::size_t line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < errorIndex; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(errorIndex - lineStart + 1);
}

// The part of text after the first marker, or all of text if there is none.
std::string textAfter(const std::string& text, const std::string& marker) {
    const std::size_t at = text.find(marker);
    return at == std::string::npos ? text : text.substr(at + marker.size());
}

std::string readTextFile(const std::string& path) {
    std::error_code ignored;
    if (!std::filesystem::exists(path, ignored)) throw InputError(path, "a scene file", "no such file");
    if (!std::filesystem::is_regular_file(path, ignored)) throw InputError(path, "a scene file", "not a regular file");
    return io::readFileBytes(path, "a readable scene file");
}

nlohmann::json parseJsonText(const std::string& text, const std::string& sourceName) {
    try {
        return nlohmann::json::parse(text, DuplicateKeyCheck(sourceName));
    } catch (const nlohmann::json::parse_error& error) {
        // Drops "[json.exception.parse_error.101] parse error at line L, column C: ".
        const std::string reason = textAfter(error.what(), ": ");
        throw InputError(sourceName + ": " + lineAndColumn(text, error.byte), "valid JSON", reason);
    } catch (const nlohmann::json::exception& error) {  // a number too large for a double, say
        const std::optional<std::size_t> byte = jsonErrorByte(text);
        throw InputError(byte ? sourceName + ": " + lineAndColumn(text, *byte) : sourceName, "valid JSON",
                         textAfter(error.what(), "] "));
    }
}

}  // namespace

Scene parseScene(const nlohmann::json& root, const std::string& sourceName) {
    const auto fields = JsonReader(root, sourceName)
                            .object({"description", "grid", "medium", "objects", "paint", "lights", "receivers",
                                     "camera", "render", "tracer", "sim", "frame_time", "volume", "export", "diagnostic"});
    Scene scene;
    scene.sourcePath = sourceName;
    if (auto description = fields.optional("description")) description->string();  // checked, not kept
    if (auto grid = fields.optional("grid")) scene.grid = readGrid(*grid);
    if (auto medium = fields.optional("medium")) readMedium(*medium, scene);
    const std::string sceneFolder = std::filesystem::path(sourceName).parent_path().string();
    scene.objects = readList<ObjectDesc>(fields, "objects",
                                         [&](const JsonReader& node) { return readObject(node, sceneFolder); });
    const auto sharp = std::count_if(scene.objects.begin(), scene.objects.end(),
                                     [](const ObjectDesc& object) { return object.isSharp(); });
    if (sharp > layout::kMaxSharpObjects)
        fields.member("objects").fail("at most " + std::to_string(layout::kMaxSharpObjects) +
                                          " sharp objects (set \"surface\": \"smooth\" on the others)",
                                      std::to_string(sharp));
    scene.paint = readList<PaintStroke>(fields, "paint", readPaintStroke);
    scene.lights = readList<LightDesc>(fields, "lights", readLight);
    if (auto tracer = fields.optional("tracer")) scene.tracer = readTracer(*tracer);
    scene.receivers = readList<ReceiverDesc>(
        fields, "receivers", [&](const JsonReader& node) { return readReceiver(node, scene.tracer.estimator); });
    if (scene.receivers.size() > static_cast<std::size_t>(layout::kMaxReceivers))
        fields.member("receivers").fail("at most " + std::to_string(layout::kMaxReceivers) + " receivers",
                                        std::to_string(scene.receivers.size()));
    if (auto camera = fields.optional("camera")) scene.camera = readCamera(*camera);
    if (auto render = fields.optional("render")) scene.render = readRender(*render, sceneFolder);
    if (auto sim = fields.optional("sim")) scene.sim = readSim(*sim);
    if (scene.sim && scene.airProfile)
        fields.member("medium").member("air_temperature_profile")
            .fail("no air_temperature_profile in a scene whose medium comes from the sim section", "both");
    if (auto frameTime = fields.optional("frame_time")) {
        if (scene.sim) frameTime->fail("no frame_time beside a sim section (sim.frame_time sets it there)", "both");
        scene.frameTime = frameTime->number(kPositive);
    }
    if (scene.sim) scene.frameTime = scene.sim->frameTime;
    if (auto volume = fields.optional("volume")) {
        if (scene.sim) volume->fail("either a sim section or a volume, not both", "both");
        scene.volume = readVolume(*volume, sceneFolder);
        if (scene.volume->emissionLights && scene.tracer.estimator == TracerDesc::Estimator::Wavefront)
            volume->member("emission_lights")
                .fail("false with tracer.estimator \"wavefront\" (a glowing volume is no wavefront source; "
                      "\"photons\" traces it)", "true");
    }
    if (scene.grid.fitVolume) fitGridToVolume(fields.member("grid").member("fit"), scene);
    const bool volumeLights = scene.volume && scene.volume->emissionLights;
    if (scene.lights.empty() && !volumeLights)
        fields.member("lights").fail("an array of at least one light (or a volume with emission_lights)");
    if (auto diagnostic = fields.optional("diagnostic")) scene.diagnostic = readDiagnostic(*diagnostic, sceneFolder);
    checkDiagnostic(fields, scene);
    checkCameraProjection(fields, scene);
    checkRenderMethod(fields, scene);  // after everything image space might drop
    if (auto exports = fields.optional("export")) readExport(*exports, scene);  // last: it checks the fields exist
    return scene;
}

nlohmann::json loadSceneDocument(const std::string& path, const std::vector<std::string>& overrides) {
    nlohmann::json root = parseJsonText(readTextFile(path), path);
    for (const std::string& assignment : overrides) applyOverride(root, assignment);
    return root;
}

Scene parseSceneText(const std::string& text, const std::string& sourceName) {
    return parseScene(parseJsonText(text, sourceName), sourceName);
}

Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
    return parseScene(loadSceneDocument(path, overrides), path);
}

}  // namespace eikon
