// `import eikon`: the library (include/eikon/eikon.h) for Python, with
// NumPy arrays in and out (pybind11). A field is read where NumPy holds it:
// it must be C-contiguous float32 (np.ascontiguousarray(a, np.float32)
// makes it so), and no copy of it is made; an array handed back owns the
// vector eikon filled, without a copy either. Refusals raise eikon.Error
// with eikon's words. docs/library.md shows the calls.
#include "eikon/eikon.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace py = pybind11;

namespace {

// An array that owns `values`, with `shape` (C order).
template <typename T>
py::array_t<T> toNumpy(std::vector<T>&& values, const std::vector<std::size_t>& shape) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule release(owned, [](void* vector) { delete static_cast<std::vector<T>*>(vector); });
    return py::array_t<T>(shape, owned->data(), release);
}

[[noreturn]] void refuse(const std::string& name, const std::string& expected, const std::string& found) {
    throw eikon::Error("eikon.Renderer.set_fields: field \"" + name + "\": expected " + expected + ", found " + found);
}

std::string shapeText(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d ? ", " : "") + std::to_string(array.shape(d));
    return text + (array.ndim() == 1 ? ",)" : ")");
}

// eikon.GLBuffer(name, channels=1): an OpenGL buffer object made in the
// renderer's context, handed for a field in place of an array (the GPU
// path, eikon::Field::buffer), with 1 or 3 (RGB) floats per cell.
struct GlBuffer {
    unsigned name = 0;
    int channels = 1;
};

// A NumPy array as an eikon::Field over `grid`'s box, read in place, or a
// GL buffer's name with the grid's shape.
eikon::Field fieldOf(const std::string& name, const py::handle& object, const eikon::Grid& grid) {
    if (py::isinstance<GlBuffer>(object)) {
        const std::array<std::size_t, 3> shape{static_cast<std::size_t>(grid.cells[2]),
                                               static_cast<std::size_t>(grid.cells[1]),
                                               static_cast<std::size_t>(grid.cells[0])};
        const GlBuffer buffer = object.cast<GlBuffer>();
        return {name, nullptr, shape, buffer.channels, grid.boundsMin, grid.boundsMax, {}, buffer.name};
    }
    if (!py::isinstance<py::array>(object)) refuse(name, "a NumPy array", std::string(py::str(py::type::of(object))));
    const auto array = py::reinterpret_borrow<py::array>(object);
    if (!array.dtype().is(py::dtype::of<float>()))
        refuse(name, "dtype float32 (np.ascontiguousarray(a, np.float32))", std::string(py::str(array.dtype())));
    if (!(array.flags() & py::array::c_style))
        refuse(name, "a C-contiguous array (np.ascontiguousarray(a, np.float32))", "a strided view");
    if (array.ndim() != 3 && array.ndim() != 4)
        refuse(name, "shape (nz, ny, nx) or (nz, ny, nx, 3)", shapeText(array));
    eikon::Field field;
    field.name = name;
    field.values = static_cast<const float*>(array.data());
    for (int d = 0; d < 3; ++d) field.shape[static_cast<std::size_t>(d)] = static_cast<std::size_t>(array.shape(d));
    field.channels = array.ndim() == 4 ? static_cast<int>(array.shape(3)) : 1;
    field.boundsMin = grid.boundsMin;
    field.boundsMax = grid.boundsMax;
    return field;
}

py::object report(const eikon::Renderer& renderer) {
    return py::module_::import("json").attr("loads")(renderer.report());
}

eikon::Renderer makeRenderer(const py::object& scene, const std::string& folder) {
    if (py::isinstance<py::dict>(scene)) {
        const std::string text = py::str(py::module_::import("json").attr("dumps")(scene));
        return eikon::Renderer::fromJson(text, folder);
    }
    if (py::isinstance<py::str>(scene) || py::hasattr(scene, "__fspath__"))
        return eikon::Renderer::fromFile(std::string(py::str(py::module_::import("os").attr("fspath")(scene))));
    throw eikon::Error("eikon.Renderer: expected a scene file's path or a dict of the scene, found " +
                       std::string(py::str(py::type::of(scene))));
}

// set_fields(name=array, …, bounds=((x, y, z), (x, y, z)),
// temperature_unit="kelvin"): `bounds`, in m, is where the arrays lie (the
// scene's grid box when left out); `temperature_unit` what the temperature
// holds (eikon::Field::unit: "kelvin", "celsius", "kelvin_above_ambient").
void setFields(eikon::Renderer& renderer, const py::kwargs& arrays) {
    eikon::Grid grid = renderer.grid();
    if (arrays.contains("bounds")) {
        const auto box = arrays["bounds"].cast<std::pair<std::array<double, 3>, std::array<double, 3>>>();
        grid.boundsMin = box.first;
        grid.boundsMax = box.second;
    }
    std::string unit;
    if (arrays.contains("temperature_unit")) {
        if (!py::isinstance<py::str>(arrays["temperature_unit"]))
            refuse("temperature", "temperature_unit a str (\"kelvin\", \"celsius\" or \"kelvin_above_ambient\")",
                   std::string(py::str(py::type::of(arrays["temperature_unit"]))));
        if (!arrays.contains("temperature"))
            refuse("temperature", "a temperature array beside temperature_unit", "none");
        unit = arrays["temperature_unit"].cast<std::string>();
    }
    std::vector<eikon::Field> fields;
    for (const auto& [key, array] : arrays) {
        const std::string name = py::str(key);
        if (name == "bounds" || name == "temperature_unit") continue;
        fields.push_back(fieldOf(name, array, grid));
        if (name == "temperature") fields.back().unit = unit;
    }
    renderer.setFields(fields);
}

}  // namespace

PYBIND11_MODULE(eikon, m) {
    m.doc() = "eikon: light through graded-index media, rendered from your own solver's fields (docs/library.md)";
    py::register_exception<eikon::Error>(m, "Error", PyExc_ValueError);

    py::class_<GlBuffer>(m, "GLBuffer",
                         "An OpenGL buffer object's name in the renderer's context with `channels` floats a cell, "
                         "handed for delta_index, index, temperature, extinction or scattering (channels=3) in place "
                         "of an array (the GPU path: mapped and copied on the GPU, docs/library.md).")
        .def(py::init([](unsigned name, int channels) { return GlBuffer{name, channels}; }), py::arg("name"),
             py::arg("channels") = 1)
        .def_readonly("name", &GlBuffer::name)
        .def_readonly("channels", &GlBuffer::channels);

    py::class_<eikon::Renderer>(m, "Renderer")
        .def(py::init(&makeRenderer), py::arg("scene"), py::arg("folder") = ".",
             "A renderer of a scene: a file's path, or a dict as the JSON of a scene file (its relative paths "
             "start at `folder`).")
        .def_property_readonly(
            "grid",
            [](const eikon::Renderer& r) {
                const eikon::Grid g = r.grid();
                return py::dict(py::arg("shape") = py::make_tuple(g.cells[2], g.cells[1], g.cells[0]),
                                py::arg("bounds_min") = g.boundsMin, py::arg("bounds_max") = g.boundsMax);
            },
            "The render grid: shape (nz, ny, nx) of a field, and its box in m.")
        .def("make_context_current", &eikon::Renderer::makeContextCurrent,
             "Makes the renderer's OpenGL context current on this thread: buffers made now live in it "
             "(eikon.GLBuffer).")
        .def("set_fields", &setFields,
             "The next frame's fields as keyword arrays (delta_index, index, temperature, density, flame, "
             "extinction, scattering, anisotropy, emission), C-contiguous float32 of shape (nz, ny, nx) or "
             "(nz, ny, nx, 3), read in place (or an eikon.GLBuffer: delta_index, index, temperature, extinction, scattering); bounds=((x, y, z), (x, y, z)) in m where they lie (default: the "
             "scene's grid box); temperature_unit=\"kelvin\", \"celsius\" or \"kelvin_above_ambient\" what the "
             "temperature holds (default: as the scene's volume reads it, kelvin above ambient).")
        .def("render", &eikon::Renderer::render, py::call_guard<py::gil_scoped_release>(),
             "Renders the current fields.")
        .def(
            "image",
            [](const eikon::Renderer& r) {
                eikon::ByteArray a = r.image();
                return toNumpy(std::move(a.values), a.shape);
            },
            "The image as eikon run's PNG: (height, width, 3) uint8 sRGB, row 0 at the top.")
        .def(
            "radiance",
            [](const eikon::Renderer& r) {
                eikon::FloatArray a = r.radiance();
                return toNumpy(std::move(a.values), a.shape);
            },
            "Linear radiance (height, width, 3) float32 in W/(m^2 sr).")
        .def_property_readonly("receiver_count", &eikon::Renderer::receiverCount)
        .def(
            "receiver",
            [](const eikon::Renderer& r, std::size_t index) {
                eikon::FloatArray a = r.receiver(index);
                return toNumpy(std::move(a.values), a.shape);
            },
            py::arg("index") = 0, "Receiver `index`'s irradiance (texels, texels, 3) float32 in W/m^2.")
        .def(
            "fluence",
            [](const eikon::Renderer& r) {
                eikon::FloatArray a = r.fluence();
                return toNumpy(std::move(a.values), a.shape);
            },
            "The fluence (nz, ny, nx, 3) float32 in W/m^2.")
        .def("report", &report, "The last frame's report (a dict, as a line of eikon run's report.jsonl).");

    py::class_<eikon::View>(m, "View")
        .def(py::init<std::string, int, int>(), py::arg("title") = "eikon", py::arg("width") = 0,
             py::arg("height") = 0,
             "The live viewer: a window (an X display) with eikon-view's gestures (left drag: orbit, "
             "middle: pan, wheel: zoom, right: the first light), panel and preview, showing the renderer's frames scaled to fit; "
             "width × height pixels, 0: the first frame's size.")
        .def("show", &eikon::View::show, py::arg("renderer"), py::call_guard<py::gil_scoped_release>(),
             "Handles the window's events, renders the renderer's current fields again where the camera moved "
             "(a preview while it moves, the full frame once it rests) and shows its last frame; False once the "
             "window is closed (a loop's condition: while view.show(r): ...). Call it between steps too, to keep "
             "the window live.")
        .def_property_readonly("is_open", &eikon::View::isOpen)
        .def(
            "window_image",
            [](const eikon::View& v) {
                eikon::ByteArray a = v.windowImage();
                return toNumpy(std::move(a.values), a.shape);
            },
            "The frame as the window shows it, under the panel: (height, width, 3) uint8 sRGB, row 0 at the top.");

    m.def(
        "render_image",
        [](const py::object& scene, const py::kwargs& arrays) {
            eikon::Renderer renderer = makeRenderer(scene, ".");
            if (arrays.size() > 0) setFields(renderer, arrays);
            {
                py::gil_scoped_release released;
                renderer.render();
            }
            eikon::ByteArray a = renderer.image();
            return toNumpy(std::move(a.values), a.shape);
        },
        py::arg("scene"),
        "One image of a scene (a path or a dict) with the given fields, as a (height, width, 3) uint8 array: "
        "for a notebook cell.");
}
