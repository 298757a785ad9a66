#include "io/vtk/ExportGeometry.h"

#include "bridge/core/Error.h"
#include "bridge/scene/ReceiverAxes.h"

namespace eikon::io {

PolyData receiverQuads(const std::vector<ReceiverDesc>& receivers,
                       const std::vector<std::vector<float>>& irradiance) {
    EIKON_CHECK_EQ(receivers.size(), irradiance.size());
    PolyData data;
    NamedArray power{"irradiance", 3, {}, {"W/m^2", ArrayRole::Density}}, index{"receiver", 1, {}, {"1"}};
    for (std::size_t r = 0; r < receivers.size(); ++r) {
        const ReceiverDesc& receiver = receivers[r];
        const auto res = static_cast<std::uint32_t>(receiver.resolution);
        EIKON_CHECK_EQ(irradiance[r].size(), std::size_t{3} * res * res);
        const ReceiverAxes axes = receiverAxes(receiver);
        const glm::vec3 origin(receiver.point), u(axes.u), v(axes.v);
        const auto size = static_cast<float>(receiver.size);
        const glm::vec3 corner = origin - 0.5f * size * (u + v);
        const auto first = static_cast<std::uint32_t>(data.points.size());
        for (std::uint32_t j = 0; j <= res; ++j)
            for (std::uint32_t i = 0; i <= res; ++i)
                data.points.push_back(corner + (size * static_cast<float>(i) / static_cast<float>(res)) * u +
                                      (size * static_cast<float>(j) / static_cast<float>(res)) * v);
        for (std::uint32_t j = 0; j < res; ++j)
            for (std::uint32_t i = 0; i < res; ++i) {
                const std::uint32_t p = first + j * (res + 1) + i;
                data.polygons.push_back({p, p + 1, p + res + 2, p + res + 1});
            }
        power.values.insert(power.values.end(), irradiance[r].begin(), irradiance[r].end());
        index.values.insert(index.values.end(), static_cast<std::size_t>(res) * res, static_cast<float>(r));
    }
    data.cellArrays = {std::move(power), std::move(index)};
    return data;
}

PolyData photonPolylines(const std::vector<glm::vec4>& vertices, const std::vector<glm::vec4>& power,
                         int verticesPerPhoton) {
    EIKON_CHECK(verticesPerPhoton > 0 && vertices.size() == power.size() &&
                vertices.size() % static_cast<std::size_t>(verticesPerPhoton) == 0);
    PolyData data;
    NamedArray watts{"power", 3, {}, {"W", ArrayRole::Density}};
    const auto per = static_cast<std::size_t>(verticesPerPhoton);
    for (std::size_t photon = 0; photon < vertices.size() / per; ++photon) {
        std::vector<std::uint32_t> line;
        for (std::size_t k = photon * per; k < (photon + 1) * per && vertices[k].w == 1.0f; ++k) {
            line.push_back(static_cast<std::uint32_t>(data.points.size()));
            data.points.emplace_back(vertices[k]);
            watts.values.insert(watts.values.end(), {power[k].r, power[k].g, power[k].b});
        }
        if (line.size() >= 2) {
            data.lines.push_back(std::move(line));
        } else {  // a lone vertex is no path
            data.points.resize(data.points.size() - line.size());
            watts.values.resize(3 * data.points.size());
        }
    }
    data.pointArrays = {std::move(watts)};
    return data;
}

}  // namespace eikon::io
