"""eikon.View, the live viewer fed from Python (apps/library/View.cpp), in a
window under Xvfb: each frame a loop hands it is what the window shows —
at the frame's size pixel for pixel, scaled to fit in a larger window. Run
by ctest (Python.View) under xvfb-run."""

import unittest

import numpy as np

import eikon
from test_loop_memory import SCENE, warm_bubble


class View(unittest.TestCase):
    def test_a_loop_shows_each_frame_in_the_window(self):
        renderer = eikon.Renderer(SCENE)
        view = eikon.View("eikon test", 0, 0)
        shown = []
        for step in range(3):
            renderer.set_fields(temperature=warm_bubble(40 * step))
            renderer.render()
            self.assertTrue(view.show(renderer))
            window = view.window_image()
            self.assertEqual(window.shape, (24, 24, 3))
            self.assertTrue(np.array_equal(window, renderer.image()), f"step {step}: the frame, pixel for pixel")
            shown.append(window)
        self.assertTrue(view.is_open)
        self.assertFalse(np.array_equal(shown[0], shown[-1]), "the bubble has risen: the window shows new frames")

    def test_a_larger_window_shows_the_frame_scaled_to_fit(self):
        renderer = eikon.Renderer(SCENE)
        renderer.set_fields(temperature=warm_bubble(0))
        renderer.render()
        view = eikon.View("eikon test", 96, 48)
        self.assertTrue(view.show(renderer))
        window = view.window_image().astype(int)
        self.assertEqual(window.shape, (48, 96, 3))
        # The 24 × 24 frame at twice its size, centred: columns 24 … 71; dark margins.
        frame = renderer.image().astype(int)
        scaled = window[:, 24:72]
        self.assertLess(np.abs(scaled[1::2, 1::2] - frame).max(), 40, "the frame, magnified (linear filter)")
        self.assertLess(window[:, :20].max(), 30)
        self.assertLess(window[:, 76:].max(), 30)

    def test_before_a_frame_show_is_refused(self):
        with self.assertRaises(eikon.Error):
            eikon.View().show(eikon.Renderer(SCENE))


if __name__ == "__main__":
    unittest.main()
