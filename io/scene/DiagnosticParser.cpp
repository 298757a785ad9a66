#include "io/scene/DiagnosticParser.h"

#include "bridge/core/Error.h"
#include "bridge/core/MemoryLimit.h"
#include "bridge/core/NumberFormat.h"
#include "io/image/ImageIo.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace eikon {

namespace {

// Wavelengths in nm: any light a diagnostic could use, up to a millimetre.
const NumberRange kWavelengthRange = {0.0, 1e6, false, true};
// The dots' share of the background: at most 0.5 keeps a dot's lattice cell
// at least its diameter wide, so that the dots of the 3 × 3 cells around a
// point are all that darken it.
const NumberRange kDotDensityRange = {0.0, 0.5, false, true};

DiagnosticDesc::Cutoff readCutoff(const JsonReader& node) {
    const std::string name = node.oneOf({"knife_edge", "circular", "colour"});
    if (name == "circular") return DiagnosticDesc::Cutoff::Circular;
    return name == "colour" ? DiagnosticDesc::Cutoff::Colour : DiagnosticDesc::Cutoff::KnifeEdge;
}

// BOS's `pattern`: "dots", or an image file read now, so that a bad one
// stops the run before anything is written.
void readPatternImage(const JsonReader& node, const std::string& sceneFolder, DiagnosticDesc& diagnostic) {
    const std::string name = node.string();
    if (name == "dots") return;
    constexpr const char* kExpected =
        "\"dots\" or an existing PNG or JPEG image file (relative paths start at the scene file's folder)";
    const std::filesystem::path path = name;
    diagnostic.patternPath = (path.is_absolute() ? path : std::filesystem::path(sceneFolder) / path).string();
    if (!std::filesystem::is_regular_file(diagnostic.patternPath))
        node.fail(kExpected, "\"" + diagnostic.patternPath + "\", which does not exist");
    const MemoryLimit limit = machineMemoryLimit();  // checked before the image is decoded
    const std::uint64_t decoding = io::floatImageDecodingBytes(diagnostic.patternPath);
    if (limit.bytes && decoding > limit.bytes)
        node.fail("an image whose decoding fits " + limit.source,
                  "\"" + diagnostic.patternPath + "\", " + mebibytes(decoding) + " to decode");
    try {
        diagnostic.patternImage = std::make_shared<const FloatImage>(io::readSrgbImageAsLinear(diagnostic.patternPath));
    } catch (const InputError& error) {
        node.fail(kExpected, "\"" + diagnostic.patternPath + "\", which is not one (" + error.what() + ")");
    }
}

}  // namespace

DiagnosticDesc readDiagnostic(const JsonReader& node, const std::string& sceneFolder) {
    DiagnosticDesc diagnostic;
    const std::string type = node.member("type").oneOf({"interferometry", "schlieren", "shadowgraph", "bos"});
    if (type == "shadowgraph") {
        const auto fields = node.object({"type", "screen_distance"});
        diagnostic.type = DiagnosticDesc::Type::Shadowgraph;
        if (auto distance = fields.optional("screen_distance")) diagnostic.screenDistance = distance->number(kLengthRange);
        return diagnostic;
    }
    if (type == "bos") {
        const auto fields = node.object(
            {"type", "background_distance", "pattern", "pattern_width", "seed", "dot_diameter", "dot_density"});
        diagnostic.type = DiagnosticDesc::Type::Bos;
        if (auto distance = fields.optional("background_distance"))
            diagnostic.backgroundDistance = distance->number(kLengthRange);
        if (auto pattern = fields.optional("pattern")) readPatternImage(*pattern, sceneFolder, diagnostic);
        if (auto width = fields.optional("pattern_width")) {
            if (diagnostic.patternPath.empty())
                width->fail("no pattern_width with the \"dots\" pattern (dot_diameter sizes the dots)");
            diagnostic.patternWidth = width->number(kLengthRange);
        }
        if (auto seed = fields.optional("seed")) diagnostic.seed = static_cast<std::uint32_t>(seed->integer(0, 4294967295LL));
        if (auto diameter = fields.optional("dot_diameter")) diagnostic.dotDiameter = diameter->number(kLengthRange);
        if (auto density = fields.optional("dot_density")) diagnostic.dotDensity = density->number(kDotDensityRange);
        return diagnostic;
    }
    if (type == "interferometry") {
        const auto fields = node.object({"type", "wavelength_nm", "fringe_tilt"});
        diagnostic.type = DiagnosticDesc::Type::Interferometry;
        if (auto wavelength = fields.optional("wavelength_nm")) diagnostic.wavelengthNm = wavelength->number(kWavelengthRange);
        if (auto tilt = fields.optional("fringe_tilt")) diagnostic.fringeTilt = tilt->number();
        return diagnostic;
    }
    const auto fields = node.object({"type", "focal_length", "source_height", "cutoff", "knife_angle_deg"});
    diagnostic.type = DiagnosticDesc::Type::Schlieren;
    if (auto focal = fields.optional("focal_length")) diagnostic.focalLength = focal->number(kLengthRange);
    if (auto source = fields.optional("source_height")) diagnostic.sourceHeight = source->number(kLengthRange);
    if (auto cutoff = fields.optional("cutoff")) diagnostic.cutoff = readCutoff(*cutoff);
    // Read with every cut-off, used by the knife edge: `--set diagnostic.cutoff=…` switches a scene's filter.
    if (auto angle = fields.optional("knife_angle_deg")) diagnostic.knifeAngleDeg = angle->number();
    return diagnostic;
}

void checkDiagnostic(const JsonObjectReader& sceneFields, const Scene& scene) {
    if (!scene.diagnostic) return;
    if (scene.diagnostic->type == DiagnosticDesc::Type::Bos) {
        if (scene.camera.orthographic())
            sceneFields.member("camera").member("projection").fail(
                "\"perspective\" with a bos diagnostic (a camera focused on the background)", "\"orthographic\"");
    } else if (!scene.camera.orthographic()) {
        const std::string why = " with a diagnostic (its light crosses the volume in parallel)";
        if (auto camera = sceneFields.optional("camera"))
            camera->member("projection").fail("\"orthographic\"" + why, "\"perspective\"");
        sceneFields.member("camera").fail("a camera with projection \"orthographic\" and width_m" + why);
    }
    if (scene.render.method == RenderDesc::Method::ImageSpace)
        sceneFields.member("render").member("method").fail("\"eikonal\" with a diagnostic (it traces the graded field)",
                                                           "\"image_space\"");
    // The fringes of a tilted reference beam alone must stay two pixels apart (Nyquist).
    const double tiltLimit = 0.5 * scene.render.width;
    if (std::abs(scene.diagnostic->fringeTilt) > tiltLimit)
        sceneFields.member("diagnostic").member("fringe_tilt").fail(
            "a number in [-" + formatNumber(tiltLimit) + ", " + formatNumber(tiltLimit) +
                "] (render.width / 2: a fringe spans at least two pixels)",
            formatNumber(scene.diagnostic->fringeTilt));
}

}  // namespace eikon
