"""A heated plume solved with NumPy, its heat shimmer rendered by eikon
every step and saved as plume_NNN.png.

The solver is a small stand-in for one's own: the temperature excess T (K
above ambient) on the render grid, carried upward by a buoyant velocity
w = buoyancy · T (first-order upwind), spread by explicit diffusion, and
fed by a hot strip whose temperature flickers. eikon maps T to the refractive index
of air by Gladstone–Dale (the scene's volume defaults, docs/library.md).

    PYTHONPATH=build/release/python python3 examples/python/heated_plume.py [steps] [out folder] [--view]

With --view the plume is also shown live in eikon's viewer window (an X
display): drag to orbit the camera while it runs; closing the window ends
the loop.
"""

import os
import struct
import sys
import time
import zlib

import numpy as np

import eikon

N = 64  # cells per axis
SCENE = {
    "grid": {"bounds": {"min": [-0.2, 0.0, -0.2], "max": [0.2, 0.4, 0.2]}, "resolution": [N, N, N]},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
    # A telephoto look along the hot strip, through 40 cm of its plume, at a
    # tiled floor 30 cm below it and some metres behind: a deflection of
    # 1e-3 rad moves the tiles by a few pixels.
    "camera": {"position": [0.0, 0.25, 2.0], "target": [0.0, 0.12, 0.0], "fov_deg": 6},
    "render": {"width": 320, "height": 240,
               "environment": {"type": "sky", "ground_height": -0.3, "checker_size": 0.05,
                               "ground_a": [0.85, 0.85, 0.8], "ground_b": [0.05, 0.05, 0.06]}},
}


class Plume:
    """T on the cells (nz, ny, nx), float32, contiguous: handed to eikon as it lies."""

    def __init__(self, n, seed=1):
        self.h = 0.4 / n
        self.t = np.zeros((n, n, n), np.float32)
        c = (np.arange(n) + 0.5) * self.h - 0.2
        z, x = np.meshgrid(c, c, indexing="ij")
        self.plate = np.abs(x) < 0.015  # a 3 cm hot strip along z on the floor of the grid, a grill's bar
        self.rng = np.random.default_rng(seed)

    def step(self, dt=0.02, buoyancy=0.01, diffusivity=2e-4):
        t = self.t
        w = np.minimum(buoyancy * t, 0.9 * self.h / dt)  # m/s, within the upwind scheme's CFL limit
        t -= (w * dt / self.h) * (t - np.roll(t, 1, axis=1))  # upward: y is axis 1
        lap = -6 * t
        for axis in (0, 1, 2):
            lap += np.roll(t, 1, axis) + np.roll(t, -1, axis)
        t += (diffusivity * dt / self.h**2) * lap
        t[:, 0, :] = np.where(self.plate, 250.0 * (1.0 + 0.3 * self.rng.standard_normal(self.plate.shape)), 0.0)
        t[:, -1, :] = 0.0  # heat leaves at the top
        np.maximum(t, 0.0, out=t)


def write_png(path, rgb):
    """An 8-bit RGB PNG with the standard library alone."""
    height, width, _ = rgb.shape
    rows = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path + ".tmp", "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(rows, 6)) + chunk(b"IEND", b""))
    os.replace(path + ".tmp", path)


def main():
    arguments = [a for a in sys.argv[1:] if a != "--view"]
    steps = int(arguments[0]) if len(arguments) > 0 else 40
    out = arguments[1] if len(arguments) > 1 else "plume_frames"
    os.makedirs(out, exist_ok=True)
    renderer = eikon.Renderer(SCENE)
    view = eikon.View("heated plume", 640, 480) if "--view" in sys.argv else None
    plume = Plume(N)
    start, done = time.perf_counter(), 0
    for step in range(steps):
        for _ in range(5):
            plume.step()
        renderer.set_fields(temperature=plume.t)
        renderer.render()
        write_png(os.path.join(out, f"plume_{step:03d}.png"), renderer.image())
        done += 1
        if view and not view.show(renderer):
            break  # the window was closed
    elapsed = time.perf_counter() - start
    print(f"{done} frames in {elapsed:.2f} s: {done / elapsed:.2f} frames/s (solver, render and PNG)")


if __name__ == "__main__":
    main()
