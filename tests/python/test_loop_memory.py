"""A solver's loop through the Python module (docs/library.md): 100 steps of
a 64³ temperature field, a new contiguous float32 array each step, render
without the process's resident memory growing (flat within 5 % from step 10
to step 100) and without eikon copying the field (the report's
caller_fields.host_bytes_copied is 0 every step); the same loop keeping a
copy of each field, as a leaking copy would, grows past the 5 %. The view
is small so that the loop, not llvmpipe, is what runs. Run by ctest
(Python.LoopMemory), in a process of its own."""

import os
import unittest

import numpy as np

import eikon

N = 64
SCENE = {
    "grid": {"bounds": {"min": [-0.2, 0.0, -0.2], "max": [0.2, 0.4, 0.2]}, "resolution": [N, N, N]},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
    "camera": {"position": [0.0, 0.25, 2.0], "target": [0.0, 0.12, 0.0], "fov_deg": 6},
    "render": {"width": 24, "height": 24,
               "environment": {"type": "sky", "ground_height": -0.3, "checker_size": 0.05}},
}


def resident_mib():
    """The process's resident set (the kernel's count of its pages in memory)."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def warm_bubble(step):
    """T above ambient (K) of a bubble rising 2 mm a step, (nz, ny, nx) float32."""
    c = (np.arange(N, dtype=np.float32) + 0.5) * (0.4 / N)
    z, y, x = np.meshgrid(c - 0.2, c, c - 0.2, indexing="ij")
    centre = 0.1 + 0.002 * step
    return (60 * np.exp(-(x * x + (y - centre) ** 2 + z * z) / 0.0036)).astype(np.float32)


def loop(renderer, steps, keep=None):
    """Feeds `steps` fields; returns the resident memory after each step and
    the caller's bytes eikon copied. `keep`: a list that keeps a copy of each
    field, the leak a per-step copy would be."""
    resident, copied, frames = [], [], set()
    for step in range(steps):
        t = warm_bubble(step)  # a new array each step, as a solver's
        assert t.flags["C_CONTIGUOUS"] and t.dtype == np.float32
        renderer.set_fields(temperature=t)
        renderer.render()
        if keep is not None:
            keep.append(t.copy())
        copied.append(renderer.report()["caller_fields"]["host_bytes_copied"])
        frames.add(renderer.radiance().tobytes())
        resident.append(resident_mib())
    return resident, copied, len(frames)


class LoopMemory(unittest.TestCase):
    def test_a_hundred_steps_keep_memory_flat_and_copy_nothing(self):
        renderer = eikon.Renderer(SCENE)
        resident, copied, frames = loop(renderer, 100)
        growth = resident[-1] / resident[9] - 1
        print(f"\nresident memory: step 10 {resident[9]:.1f} MiB, step 100 {resident[-1]:.1f} MiB "
              f"({100 * growth:+.2f} %); caller's bytes copied per step: max {max(copied)}")
        self.assertEqual(max(copied), 0, "a contiguous float32 field is read where it lies")
        self.assertLess(abs(growth), 0.05, "resident memory flat within 5 %")
        self.assertGreater(frames, 1, "the rising bubble changes the frame: the loop renders")

        # The measure sees a leak of a per-step copy's size (1 MiB a step),
        # after the loop above (so that its freed memory hides nothing from it).
        kept = []
        leaking, _, _ = loop(renderer, 100, kept)
        leak = leaking[-1] / leaking[9] - 1
        print(f"the same loop keeping a copy of each field: {100 * leak:+.2f} %")
        self.assertGreater(leak, 0.05)


if __name__ == "__main__":
    unittest.main()
