#include "io/scene/PaintParser.h"

#include <string>

namespace eikon {

namespace {

PaintStroke::Brush readBrush(const JsonReader& node) {
    return node.oneOf({"soft", "smoke"}) == std::string("soft") ? PaintStroke::Brush::Soft : PaintStroke::Brush::Smoke;
}

PaintStroke::Where readWhere(const JsonReader& node) {
    const std::string where = node.oneOf({"everywhere", "inside_objects", "outside_objects"});
    if (where == "inside_objects") return PaintStroke::Where::InsideObjects;
    if (where == "outside_objects") return PaintStroke::Where::OutsideObjects;
    return PaintStroke::Where::Everywhere;
}

}  // namespace

PaintStroke readPaintStroke(const JsonReader& node) {
    const auto fields =
        node.object({"brush", "where", "path", "radius", "index", "extinction", "scattering", "seed"});
    PaintStroke stroke;
    if (auto brush = fields.optional("brush")) stroke.brush = readBrush(*brush);
    if (auto where = fields.optional("where")) stroke.where = readWhere(*where);
    const JsonReader path = fields.member("path");
    for (const JsonReader& point : path.array()) stroke.path.push_back(point.vec3(kCoordinateRange));
    if (stroke.path.empty()) path.fail("an array of at least one point [x, y, z]", "an empty array");
    stroke.radius = fields.member("radius").number(kLengthRange);
    if (auto index = fields.optional("index")) stroke.index = index->number();
    if (auto extinction = fields.optional("extinction")) stroke.extinction = extinction->rgb(kAttenuationRange);
    if (auto scattering = fields.optional("scattering")) {
        stroke.scattering = scattering->rgb(kAttenuationRange);
        for (int channel = 0; channel < 3; ++channel)
            if (stroke.scattering[channel] > stroke.extinction[channel])
                scattering->fail("scattering <= the stroke's extinction in every channel",
                                 std::to_string(stroke.scattering[channel]) + " > " +
                                     std::to_string(stroke.extinction[channel]) + " in channel " +
                                     std::to_string(channel));
    }
    if (auto seed = fields.optional("seed")) stroke.seed = static_cast<unsigned>(seed->integer(0, 4294967295LL));
    if (stroke.index == 0.0 && stroke.extinction == Rgb(0.0))
        node.fail("a stroke that paints something: a non-zero index or extinction", "neither");
    return stroke;
}

}  // namespace eikon
