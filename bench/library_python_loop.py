"""A Python loop feeding eikon a 64³ temperature field every step
(docs/library.md): frames per second of set_fields + render alone (the
field moves by np.roll, a few ms), the resident memory over the steps, and
the bytes of the caller's field copied per frame (the report's
caller_fields.host_bytes_copied).

    PYTHONPATH=build/release/python python3 bench/library_python_loop.py [steps]
"""

import os
import sys
import time

import numpy as np

import eikon

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "examples", "python"))
from heated_plume import SCENE, Plume  # noqa: E402  the example's scene and solver


def rss_mib():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def main():
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    renderer = eikon.Renderer(SCENE)
    plume = Plume(64)
    for _ in range(60):  # a developed plume
        plume.step()
    field = plume.t
    rss, copied, loop = [], [], 0.0
    for step in range(steps):
        field = np.roll(field, 1, axis=2)  # a new array each step, contiguous float32
        start = time.perf_counter()
        renderer.set_fields(temperature=field)
        renderer.render()
        loop += time.perf_counter() - start
        copied.append(renderer.report()["caller_fields"]["host_bytes_copied"])
        rss.append(rss_mib())
    print(f"{steps} steps of a 64^3 field: {steps / loop:.2f} frames/s (set_fields + render)")
    print(f"RSS: step 10 {rss[min(9, steps - 1)]:.1f} MiB, step {steps} {rss[-1]:.1f} MiB "
          f"({100 * (rss[-1] / rss[min(9, steps - 1)] - 1):+.2f}%)")
    print(f"caller's field bytes copied per frame: max {max(copied)}")


if __name__ == "__main__":
    main()
