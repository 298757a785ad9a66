#include "verify/accuracy/RingMap.h"

#include "verify/reference/CircleDeposit.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace eikon::accuracy {

std::vector<double> ringMap(const reference::IndexField& field, const reference::ReferenceOptions& options,
                            const RingMapSetup& setup) {
    const reference::ReferenceTracer tracer(field, options);
    const std::size_t texels = static_cast<std::size_t>(setup.texels) * static_cast<std::size_t>(setup.texels);
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::vector<double>> partial(threads, std::vector<double>(texels, 0.0));
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < threads; ++w)
        workers.emplace_back([&, w] {
            reference::CircleDeposit circles(setup.texels, setup.size, partial[w]);
            for (int k = static_cast<int>(w); k < setup.rings; k += static_cast<int>(threads)) {
                const RingRay ray = setup.ray(k);
                const reference::ReferenceResult result =
                    tracer.trace(tracer.start(ray.start, ray.direction), 10.0, setup.plane);
                if (result.eventHit) circles.add(setup.radius(result.state.x), ray.power);
            }
        });
    for (auto& worker : workers) worker.join();
    std::vector<double> map(texels, 0.0);
    const double texelArea = (setup.size / setup.texels) * (setup.size / setup.texels);
    for (const auto& part : partial)
        for (std::size_t t = 0; t < texels; ++t) map[t] += part[t] / texelArea;
    return map;
}

}  // namespace eikon::accuracy
