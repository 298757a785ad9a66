"""eikon.View, the live viewer fed from Python (apps/library/View.cpp), in a
window under Xvfb: each frame a loop hands it is what the window shows —
at the frame's size pixel for pixel, scaled to fit in a larger window — and
a mouse drag in it, made by the X server's test extension as a hand would,
orbits the camera: the view renders the fields again from there, and the
frames handed in afterwards are seen from there too; a right drag turns the
light; and closing the window ends the loop (show() returns False). Run by ctest
(Python.View) under xvfb-run."""

import ctypes
import time
import unittest

import numpy as np

import eikon
from test_loop_memory import SCENE, warm_bubble
import test_module


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

    def test_drags_orbit_the_camera_and_turn_the_light_and_frames_handed_in_still_show(self):
        x11, xtst = ctypes.CDLL("libX11.so.6"), ctypes.CDLL("libXtst.so.6")
        x11.XOpenDisplay.restype = ctypes.c_void_p
        x11.XFlush.argtypes = [ctypes.c_void_p]
        xtst.XTestFakeMotionEvent.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_ulong]
        xtst.XTestFakeButtonEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]
        display = x11.XOpenDisplay(None)
        self.assertTrue(display, "an X display (xvfb-run)")

        def pointer(x, y):
            xtst.XTestFakeMotionEvent(display, -1, x, y, 0)
            x11.XFlush(display)

        def button(down):
            xtst.XTestFakeButtonEvent(display, 1, down, 0)
            x11.XFlush(display)

        # A lens of δn over a lit floor, seen obliquely: an orbit moves the floor's edges and the caustic.
        renderer, still = eikon.Renderer(test_module.SCENE), eikon.Renderer(test_module.SCENE)
        for r in (renderer, still):
            r.set_fields(delta_index=0.01 * test_module.bump(0.08))
            r.render()
        # The window at the screen's corner (no window manager places it),
        # wider than the panel on its left: the drag is on the picture.
        view = eikon.View("eikon gestures", 600, 400)
        self.assertTrue(view.show(renderer))
        before = renderer.image()
        self.assertTrue(np.array_equal(before, still.image()))
        pointer(560, 300)
        view.show(renderer)
        button(True)
        view.show(renderer)
        for i in range(1, 6):  # 60 pixels left: the camera turns 18° about its target
            pointer(560 - 12 * i, 300)
            time.sleep(0.02)
            self.assertTrue(view.show(renderer))
        button(False)
        time.sleep(0.3)  # past the preview's rest delay: the full frame
        view.show(renderer)
        moved = renderer.image()
        self.assertEqual(moved.shape, before.shape)
        self.assertGreater(np.abs(moved.astype(int) - before.astype(int)).mean(), 2,
                           "the view rendered the same fields from the orbited camera")
        self.assertEqual(renderer.report()["caller_fields"]["names"], [], "re-rendered by the view: no new fields")

        # A frame handed in after the drag: shown, and seen from the orbited camera.
        for r in (renderer, still):
            r.set_fields(delta_index=0.03 * test_module.bump(0.08))
            r.render()
        self.assertTrue(view.show(renderer))
        self.assertFalse(np.array_equal(renderer.image(), moved), "the new frame is shown")
        self.assertGreater(np.abs(renderer.image().astype(int) - still.image().astype(int)).mean(), 2,
                           "seen from the orbited camera, not the scene's")
        # A right drag turns the (directional) light: the receiver's caustic moves.
        lit = renderer.receiver(0)
        pointer(560, 300)
        view.show(renderer)
        xtst.XTestFakeButtonEvent(display, 3, True, 0)
        x11.XFlush(display)
        view.show(renderer)
        for i in range(1, 4):
            pointer(560 - 15 * i, 300)
            self.assertTrue(view.show(renderer))
        xtst.XTestFakeButtonEvent(display, 3, False, 0)
        x11.XFlush(display)
        view.show(renderer)
        self.assertGreater(np.abs(renderer.receiver(0) - lit).max(), 0.05, "the light turned")
        x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
        x11.XCloseDisplay(display)

    def test_closing_the_window_is_reported_to_the_loop(self):
        """The window manager's close (WM_DELETE_WINDOW, sent here as a window
        manager sends it): show() returns False and is_open turns False."""
        x11 = ctypes.CDLL("libX11.so.6")
        x11.XOpenDisplay.restype = ctypes.c_void_p
        x11.XInternAtom.restype = ctypes.c_ulong
        x11.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
        x11.XDefaultRootWindow.restype = ctypes.c_ulong
        x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
        x11.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                                   ctypes.POINTER(ctypes.c_ulong), ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                                   ctypes.POINTER(ctypes.c_uint)]
        x11.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long, ctypes.c_void_p]
        x11.XFlush.argtypes = [ctypes.c_void_p]

        class ClientMessage(ctypes.Structure):  # XClientMessageEvent, padded to an XEvent
            _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                        ("display", ctypes.c_void_p), ("window", ctypes.c_ulong), ("message_type", ctypes.c_ulong),
                        ("format", ctypes.c_int), ("data", ctypes.c_long * 5), ("pad", ctypes.c_long * 12)]

        display = x11.XOpenDisplay(None)
        renderer = eikon.Renderer(SCENE)
        renderer.set_fields(temperature=warm_bubble(0))
        renderer.render()
        view = eikon.View("eikon close", 64, 64)
        self.assertTrue(view.show(renderer))
        root, parent = ctypes.c_ulong(), ctypes.c_ulong()
        children, count = ctypes.POINTER(ctypes.c_ulong)(), ctypes.c_uint()
        x11.XQueryTree(display, x11.XDefaultRootWindow(display), ctypes.byref(root), ctypes.byref(parent),
                       ctypes.byref(children), ctypes.byref(count))
        self.assertGreater(count.value, 0, "the view's window on the screen")
        protocols = x11.XInternAtom(display, b"WM_PROTOCOLS", 0)
        delete = x11.XInternAtom(display, b"WM_DELETE_WINDOW", 0)
        for w in range(count.value):  # the windows at the top (no window manager reparents them)
            event = ClientMessage(type=33, send_event=1, display=display, window=children[w],
                                  message_type=protocols, format=32)
            event.data[0] = delete
            x11.XSendEvent(display, children[w], 0, 0, ctypes.byref(event))
        x11.XFlush(display)
        time.sleep(0.1)
        self.assertFalse(view.show(renderer), "closed: the loop's condition ends it")
        self.assertFalse(view.is_open)
        self.assertFalse(view.show(renderer))

    def test_before_a_frame_show_is_refused(self):
        with self.assertRaises(eikon.Error):
            eikon.View().show(eikon.Renderer(SCENE))


if __name__ == "__main__":
    unittest.main()
