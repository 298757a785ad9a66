"""The Python module (`import eikon`, apps/python/EikonModule.cpp) from the
build folder: NumPy fields in, arrays out, read in place, and each refusal
an eikon.Error with eikon's words, after which the renderer renders its
earlier fields unchanged. Run by ctest (Python.Module) with PYTHONPATH at
the build folder's python/."""

import ctypes
import json
import os
import tempfile
import unittest

import numpy as np

import eikon

SCENE = {
    "grid": {"bounds": {"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}, "resolution": [32, 32, 32]},
    "lights": [{"type": "directional", "direction": [0.1, -1, 0.05], "irradiance": [1, 1, 1]}],
    "receivers": [{"type": "plane", "point": [0.25, -0.05, 0.25], "normal": [0, 1, 0], "albedo": 0.8,
                   "size": 0.6, "resolution": 24}],
    "camera": {"position": [0.25, 0.6, 1.4], "target": [0.25, 0.1, 0.25], "fov_deg": 40},
    "render": {"width": 40, "height": 32, "photons": 20000, "seed": 3},
}


def bump(width):
    """A Gaussian about the grid's centre on the cell centres, (nz, ny, nx) float32."""
    h = 0.5 / 32
    c = (np.arange(32) + 0.5) * h - 0.25
    z, y, x = np.meshgrid(c, c, c, indexing="ij")
    return np.exp(-(x * x + y * y + z * z) / width**2).astype(np.float32)


def fields():
    return {"delta_index": 0.01 * bump(0.08), "temperature": 300 * bump(0.05),
            "extinction": 2 * bump(0.1), "scattering": np.stack([0.5 * bump(0.1)] * 3, axis=-1)}


class Module(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.renderer = eikon.Renderer(SCENE)
        cls.fields = fields()
        cls.renderer.set_fields(**cls.fields)
        cls.renderer.render()
        cls.image = cls.renderer.image()

    def test_arrays_out_have_their_shapes_and_the_frame_is_a_picture(self):
        r = self.renderer
        self.assertEqual(r.grid["shape"], (32, 32, 32))
        self.assertEqual((self.image.shape, self.image.dtype), ((32, 40, 3), np.uint8))
        self.assertGreater(int(self.image.max()) - int(self.image.min()), 50, "not a flat image")
        radiance = r.radiance()
        self.assertEqual((radiance.shape, radiance.dtype), ((32, 40, 3), np.float32))
        self.assertEqual(r.receiver_count, 1)
        irradiance = r.receiver(0)
        self.assertEqual(irradiance.shape, (24, 24, 3))
        self.assertGreater(irradiance[..., 0].min(), 0.1)
        self.assertGreater(irradiance[..., 0].max() / irradiance[..., 0].min(), 1.2, "the bump's caustic")
        self.assertEqual(r.fluence().shape, (32, 32, 32, 3))
        report = r.report()
        self.assertLess(abs(report["photons"]["energy_balance_error"]), 1e-3)

    def test_contiguous_float32_fields_are_not_copied(self):
        # Grey extinction is spread into three channels: the one copy, 12 bytes a cell.
        self.renderer.set_fields(**self.fields)
        self.renderer.render()
        report = self.renderer.report()
        self.assertEqual(report["caller_fields"]["host_bytes_copied"], 12 * 32**3)
        self.assertEqual(sorted(report["caller_fields"]["names"]), sorted(self.fields))
        rgb = dict(self.fields, extinction=np.stack([self.fields["extinction"]] * 3, axis=-1))
        self.renderer.set_fields(**rgb)
        self.renderer.render()
        self.assertEqual(self.renderer.report()["caller_fields"]["host_bytes_copied"], 0)

    def test_a_scene_file_and_its_dict_render_the_same_bytes(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "scene.json")
            with open(path, "w") as f:
                json.dump(SCENE, f)
            from_file = eikon.Renderer(path)
            from_file.set_fields(**self.fields)
            from_file.render()
            self.assertTrue(np.array_equal(from_file.image(), self.image))

    def test_render_image_for_a_notebook(self):
        image = eikon.render_image(SCENE, **self.fields)
        self.assertTrue(np.array_equal(image, self.image))

    def refused(self, words, **arrays):
        with self.assertRaises(eikon.Error) as caught:
            self.renderer.set_fields(**arrays)
        for word in words:
            self.assertIn(word, str(caught.exception))
        self.renderer.render()
        self.assertTrue(np.array_equal(self.renderer.image(), self.image), "the refused fields were not rendered")

    def test_a_wrong_dtype(self):
        self.refused(["\"temperature\"", "float32", "float64"], temperature=self.fields["temperature"].astype(np.float64))

    def test_a_non_contiguous_array(self):
        self.refused(["\"temperature\"", "C-contiguous"], temperature=self.fields["temperature"].transpose(2, 1, 0))

    def test_a_wrong_shape(self):
        self.refused(["\"temperature\"", "(32, 32, 32)", "(16, 32, 32)"],
                     temperature=np.ascontiguousarray(self.fields["temperature"][:16]))

    def test_a_nan(self):
        t = self.fields["temperature"].copy()
        t[5, 4, 3] = np.nan
        self.refused(["\"temperature\"", "NaN", "(3, 4, 5)"], temperature=t)

    def test_a_grid_that_is_not_the_scenes(self):
        with self.assertRaises(eikon.Error) as caught:
            self.renderer.set_fields(temperature=self.fields["temperature"], bounds=((0, 0, 0), (1, 1, 1)))
        self.assertIn("grid box", str(caught.exception))

    def test_a_bad_scene_names_the_key(self):
        scene = json.loads(json.dumps(SCENE))
        scene["render"]["width"] = -4
        with self.assertRaises(eikon.Error) as caught:
            eikon.Renderer(scene)
        self.assertIn("render.width", str(caught.exception))


def write_legacy_vtk(path, name, values):
    """A legacy binary VTK image of cell data `values` (nz, ny, nx) whose
    cells are the scene's render cells: read back value for value."""
    nz, ny, nx = values.shape
    h = 0.5 / 32
    with open(path, "wb") as f:
        f.write((f"# vtk DataFile Version 3.0\nheated core\nBINARY\nDATASET STRUCTURED_POINTS\n"
                 f"DIMENSIONS {nx + 1} {ny + 1} {nz + 1}\nORIGIN 0 0 0\nSPACING {h!r} {h!r} {h!r}\n"
                 f"CELL_DATA {values.size}\nSCALARS {name} float 1\nLOOKUP_TABLE default\n").encode())
        f.write(values.astype(">f4").tobytes())
        f.write(b"\n")


class Temperature(unittest.TestCase):
    """A temperature with its unit declared renders as the same temperature
    in a VTK file declared the same way (volume.fields.temperature_unit)."""

    def test_kelvin_and_celsius_render_as_the_file_declared_so(self):
        hot = 400 * bump(0.06)
        for unit, values in (("kelvin", 293.15 + hot), ("celsius", 20.0 + hot)):
            values = values.astype(np.float32)
            with tempfile.TemporaryDirectory() as folder:
                write_legacy_vtk(os.path.join(folder, "hot.vtk"), "T", values)
                scene = dict(SCENE, volume={"path": "hot.vtk",
                                            "fields": {"temperature": "T", "temperature_unit": unit}})
                from_file = eikon.Renderer(scene, folder)
                from_file.render()
            handed = eikon.Renderer(SCENE)
            handed.set_fields(temperature=values, temperature_unit=unit)
            handed.render()
            self.assertTrue(np.array_equal(handed.image(), from_file.image()), unit)
            self.assertTrue(np.array_equal(handed.radiance(), from_file.radiance()), unit)
            self.assertTrue(np.array_equal(handed.receiver(0), from_file.receiver(0)), unit)
            self.assertEqual(handed.report()["photons"], from_file.report()["photons"], unit)
            self.assertEqual(handed.report()["caller_fields"]["host_bytes_copied"], 0)
            # The same values read above ambient give another frame: the unit matters.
            misread = eikon.Renderer(SCENE)
            misread.set_fields(temperature=values, temperature_unit="kelvin_above_ambient")
            misread.render()
            self.assertFalse(np.array_equal(misread.radiance(), from_file.radiance()), unit)

    def test_an_absolute_temperature_without_a_unit_says_how_to_declare_it(self):
        renderer = eikon.Renderer(SCENE)
        with self.assertRaises(eikon.Error) as caught:
            renderer.set_fields(temperature=(293.15 + 400 * bump(0.06)).astype(np.float32))
        for word in ("\"temperature\"", "above ambient", "temperature_unit=", "\"kelvin\""):
            self.assertIn(word, str(caught.exception))

    def test_a_unit_without_a_temperature_or_not_a_str(self):
        renderer = eikon.Renderer(SCENE)
        with self.assertRaises(eikon.Error) as caught:
            renderer.set_fields(density=bump(0.06), temperature_unit="kelvin")
        self.assertIn("beside temperature_unit", str(caught.exception))
        with self.assertRaises(eikon.Error) as caught:
            renderer.set_fields(temperature=bump(0.06), temperature_unit=273)
        self.assertIn("a str", str(caught.exception))


class GpuPath(unittest.TestCase):
    """Fields handed as OpenGL buffers made in the renderer's context
    (eikon.GLBuffer) render as the same arrays from host memory, bit for bit,
    and cross no byte to the host: δn copied, a temperature mapped to δn on
    the GPU, extinction and scattering (RGB) copied, a density mapped to κ
    and σs on the GPU. The buffers are made through libOpenGL (ctypes), as
    a solver on the GPU would have them."""

    gl = ctypes.CDLL("libOpenGL.so.0")

    def buffer_of(self, renderer, values):
        renderer.make_context_current()
        buffer = ctypes.c_uint(0)
        self.gl.glCreateBuffers(1, ctypes.byref(buffer))
        self.gl.glNamedBufferData(buffer, ctypes.c_ssize_t(values.nbytes), values.ctypes.data_as(ctypes.c_void_p),
                                  0x88E8)  # GL_DYNAMIC_DRAW
        return buffer

    def write(self, renderer, buffer, values):
        renderer.make_context_current()
        self.gl.glNamedBufferSubData(buffer, ctypes.c_ssize_t(0), ctypes.c_ssize_t(values.nbytes),
                                     values.ctypes.data_as(ctypes.c_void_p))

    def expect_same_frames(self, step_fields, channels, make=lambda: eikon.Renderer(SCENE), radiance_tolerance=0,
                           **keywords):
        """Two steps of the fields (a dict per step) from arrays and from
        buffers; the radiance within `radiance_tolerance` of its largest
        value where two renders of the scene from arrays differ."""
        host, device = make(), make()
        buffers = {}
        for step in range(2):  # the second: a solver's next step, written in place
            arrays = step_fields(step)
            for name, values in arrays.items():
                if step == 0:
                    buffers[name] = self.buffer_of(device, values)
                else:
                    self.write(device, buffers[name], values)
            host.set_fields(**arrays, **keywords)
            host.render()
            device.set_fields(**{name: eikon.GLBuffer(buffers[name].value, channels.get(name, 1))
                                 for name in arrays}, **keywords)
            device.render()
            self.assertTrue(np.array_equal(device.image(), host.image()), f"step {step}")
            tolerance = radiance_tolerance * host.radiance().max()
            self.assertLessEqual(np.abs(device.radiance() - host.radiance()).max(), tolerance, f"step {step}")
            self.assertTrue(np.array_equal(device.receiver(0), host.receiver(0)), f"step {step}")
        self.assertEqual(device.report()["host_bytes_copied"], 0)
        self.assertGreater(host.report()["host_bytes_copied"], 0)
        device.make_context_current()
        for buffer in buffers.values():
            self.gl.glDeleteBuffers(1, ctypes.byref(buffer))
        return device

    def test_a_delta_index_buffer_renders_as_the_array(self):
        device = self.expect_same_frames(lambda step: {"delta_index": (0.01 + 0.01 * step) * bump(0.08)}, {})
        self.assertGreater(device.receiver(0)[..., 0].max() / device.receiver(0)[..., 0].min(), 1.2, "a caustic")

    def test_a_temperature_buffer_is_mapped_on_the_gpu_as_the_array(self):
        self.expect_same_frames(lambda step: {"temperature": (300 + (300 + 100 * step) * bump(0.08))},
                                {}, temperature_unit="kelvin")

    def test_extinction_and_scattering_buffers_render_as_the_arrays(self):
        # Two renders of a scattering medium's arrays may differ in a radiance
        # value's last bits (6e-8 of the largest): compared to 1e-6 of it.
        rgb = lambda a: np.ascontiguousarray(np.stack([a, 0.8 * a, 0.6 * a], axis=-1))
        self.expect_same_frames(lambda step: {"extinction": rgb((3 + step) * bump(0.1)),
                                              "scattering": rgb((1 + step) * bump(0.1))},
                                {"extinction": 3, "scattering": 3}, radiance_tolerance=1e-6)

    def test_a_density_buffer_is_mapped_on_the_gpu_as_the_array(self):
        # A smoke whose density absorbs and scatters (volume.density_*); a
        # volume names its file, whose zero temperature the fields replace.
        # Two renders of the smoke's arrays may differ in a radiance value's
        # last bits (6e-8 of the largest): compared to 1e-6 of it.
        with tempfile.TemporaryDirectory() as folder:
            write_legacy_vtk(os.path.join(folder, "smoke.vtk"), "T", np.zeros((32, 32, 32), np.float32))
            scene = dict(SCENE, volume={"path": "smoke.vtk", "density_extinction": [8, 6, 4],
                                        "density_scattering": [4, 3, 2],
                                        "fields": {"temperature": "T", "temperature_unit": "kelvin_above_ambient"}})
            self.expect_same_frames(lambda step: {"density": (1 + step) * bump(0.08) - 0.05}, {},
                                    make=lambda: eikon.Renderer(scene, folder), radiance_tolerance=1e-6)

    def test_a_field_mapped_on_the_host_is_refused_as_a_buffer(self):
        renderer = eikon.Renderer(SCENE)
        buffer = self.buffer_of(renderer, bump(0.08))
        with self.assertRaises(eikon.Error) as caught:
            renderer.set_fields(flame=eikon.GLBuffer(buffer.value))
        self.assertIn("mapped with the scene's medium on the host", str(caught.exception))
        with self.assertRaises(eikon.Error) as caught:
            renderer.set_fields(temperature=eikon.GLBuffer(buffer.value), delta_index=bump(0.08))
        self.assertIn("mapped together", str(caught.exception))
        renderer.make_context_current()
        self.gl.glDeleteBuffers(1, ctypes.byref(buffer))


if __name__ == "__main__":
    unittest.main()
