// A solver of one's own feeding eikon: a warm bubble rising through still
// air (an advected Gaussian, standing in for the user's solver), its
// temperature handed to the renderer every step and its heat shimmer
// written as plume_N.ppm over a checkerboard floor. Built against the
// installed package (CMakeLists.txt beside it).
#include <eikon/eikon.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char* const kScene = R"({
  "grid": {"bounds": {"min": [-0.2, 0.0, -0.2], "max": [0.2, 0.4, 0.2]}, "resolution": [24, 24, 24]},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
  "camera": {"position": [0.0, 0.2, 1.6], "target": [0.0, 0.15, 0.0], "fov_deg": 20},
  "render": {"width": 64, "height": 48, "environment": {"type": "sky", "ground_height": -0.1, "checker_size": 0.02,
             "ground_a": [0.9, 0.9, 0.9], "ground_b": [0.1, 0.1, 0.1]}}
})";

void writePpm(const std::string& path, const eikon::ByteArray& image) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << image.shape[1] << " " << image.shape[0] << "\n255\n";
    out.write(reinterpret_cast<const char*>(image.values.data()), static_cast<std::streamsize>(image.values.size()));
    if (!out) throw std::runtime_error("could not write " + path);
}

}  // namespace

int main(int argc, char** argv) {
    const int steps = argc > 1 ? std::stoi(argv[1]) : 3;
    try {
        eikon::Renderer renderer = eikon::Renderer::fromJson(kScene);
        const eikon::Grid grid = renderer.grid();
        const int nx = grid.cells[0], ny = grid.cells[1], nz = grid.cells[2];
        std::vector<float> temperature(static_cast<std::size_t>(nx) * ny * nz);  // K above ambient
        for (int step = 0; step < steps; ++step) {
            const double centreY = 0.1 + 0.05 * step;  // m: the bubble rises 5 cm a step
            for (int k = 0; k < nz; ++k)
                for (int j = 0; j < ny; ++j)
                    for (int i = 0; i < nx; ++i) {
                        const double h = 0.4 / nx;
                        const double x = -0.2 + (i + 0.5) * h, y = (j + 0.5) * h, z = -0.2 + (k + 0.5) * h;
                        const double r2 = x * x + (y - centreY) * (y - centreY) + z * z;
                        temperature[(static_cast<std::size_t>(k) * ny + j) * nx + i] =
                            static_cast<float>(60.0 * std::exp(-r2 / (0.06 * 0.06)));
                    }
            renderer.setFields({{"temperature",
                                 temperature.data(),
                                 {static_cast<std::size_t>(nz), static_cast<std::size_t>(ny), static_cast<std::size_t>(nx)},
                                 1,
                                 grid.boundsMin,
                                 grid.boundsMax}});
            renderer.render();
            writePpm("plume_" + std::to_string(step) + ".ppm", renderer.image());
            std::cout << "step " << step << ": " << renderer.report().substr(0, 60) << "...\n";
        }
    } catch (const eikon::Error& error) {
        std::cerr << "heated_plume: " << error.what() << "\n";
        return 2;
    }
    return 0;
}
