// eikon as a library: a renderer that a program's own solver feeds with
// its fields frame after frame, and that hands back the frame's image,
// receiver maps, fluence and report. This header is the whole public
// interface (installed with the library and its CMake package,
// `find_package(eikon)`, target `eikon::eikon`); nothing else of eikon's
// is installed or stable. docs/library.md shows its use and its costs.
//
// The scene (docs/scene-format.md) sets the grid, lights, camera,
// receivers and the medium; the caller's fields replace what a `volume`
// file would give, mapped by the same optics (the scene's `volume` keys,
// or their defaults where it has no `volume` section): a field handed in
// renders as the same field read from an OpenVDB file, bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eikon {

// Every refusal of the library: a scene, a field or a call it cannot take.
// what() names the file or field, and what was expected and found. After
// one, the renderer is as it was before the call and stays usable.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The scene's render grid: cells per axis (x, y, z) over a world box in m,
// cell-centred samples.
struct Grid {
    std::array<int, 3> cells{};
    std::array<double, 3> boundsMin{};
    std::array<double, 3> boundsMax{};
};

// One dense field of a frame, read where it lies (no copy; RGB fields given
// grey are the one exception, docs/library.md). Cell (i, j, k), channel c
// is values[((k·ny + j)·nx + i)·channels + c]: x fastest, as a C-ordered
// NumPy array of shape (nz, ny, nx) or (nz, ny, nx, 3).
//   name          unit     channels  meaning
//   delta_index   1        1         n − n_ref (replaces the medium's index)
//   index         1        1         n (not with delta_index)
//   temperature   K, °C    1         in `unit` (below): δn by Gladstone–Dale
//   density       1        1         κ, σs by volume.density_extinction, _scattering
//   flame         1        1         as the volume's flame grid
//   extinction    1/m      1 or 3    κ added to the medium's
//   scattering    1/m      1 or 3    σs added to the medium's (≤ κ)
//   anisotropy    1        1         Henyey–Greenstein g
//   emission      W/(m³·sr) 1 or 3   ε
// boundsMin and boundsMax place the field; they must be the scene's grid's.
// `unit` declares what a temperature holds, as a volume file's
// `volume.fields.temperature_unit` does (docs/scene-format.md): "kelvin"
// (T), "celsius" (T − 273.15 K) or "kelvin_above_ambient" (T −
// volume.ambient_temperature, scaled by volume.temperature_scale); left
// empty, as the scene's `volume` reads its temperature (kelvin above
// ambient by default, where a field whose nonzero values all lie 150 K or
// more above 0 is refused as an absolute temperature). Empty for every
// other field.
// `buffer` is the GPU path: the name of an OpenGL buffer object made in the
// renderer's context (Renderer::makeContextCurrent) whose first
// nz·ny·nx·channels floats are the values, in place of `values` (null
// then). No byte of it crosses to the host (the report's
// host_bytes_copied): the fields of the index — delta_index, index,
// temperature, with the same units and optics as host arrays — are mapped
// to δn by a compute pass on the GPU (the host path's own Gladstone–Dale
// text, so the frames are the same bit for bit), and extinction and
// scattering (3 channels) are copied into their textures on the GPU. Every
// check of a host array is made there too (finite values, T > 0 K, n > 0,
// κ ≥ 0, σs ≤ κ, an undeclared absolute temperature), naming the cell.
// The GPU path takes fields mapped together on one side: the index's all
// in buffers or none; extinction and scattering in buffers only without a
// density or flame, scattering only with extinction and without an
// anisotropy, in a scene whose medium neither absorbs nor scatters and
// whose volume.emission is not blackbody. Density, flame, anisotropy and
// emission, and grey extinction and scattering, are mapped on the host and
// refused as buffers; so is any buffer in a scene with objects or paint
// (composited over the fields on the host). Write the buffers, then name
// them in setFields for each frame: δn is mapped then, κ and σs are read at
// render().
struct Field {
    Field() = default;
    Field(std::string name_, const float* values_, std::array<std::size_t, 3> shape_, int channels_,
          std::array<double, 3> boundsMin_, std::array<double, 3> boundsMax_, std::string unit_ = {},
          unsigned buffer_ = 0)
        : name(std::move(name_)), values(values_), shape(shape_), channels(channels_), boundsMin(boundsMin_),
          boundsMax(boundsMax_), unit(std::move(unit_)), buffer(buffer_) {}

    std::string name;
    const float* values = nullptr;
    std::array<std::size_t, 3> shape{};  // (nz, ny, nx)
    int channels = 1;
    std::array<double, 3> boundsMin{};
    std::array<double, 3> boundsMax{};
    std::string unit;
    unsigned buffer = 0;
};

// An array handed back: C order, x (or the image column) fastest, with its unit.
struct FloatArray {
    std::vector<std::size_t> shape;
    std::vector<float> values;
    std::string unit;
    unsigned buffer = 0;
};
struct ByteArray {
    std::vector<std::size_t> shape;
    std::vector<std::uint8_t> values;
};

// Renderers in one process share one OpenGL context: use them from one
// thread only.
class Renderer {
public:
    // The scene from a file, or from JSON text whose relative paths start at
    // `folder`. Error for a scene eikon refuses (as `eikon run` would, with
    // the file and key path), for a scene with a `sim` section (its solver
    // makes its own fields), and when no OpenGL 4.5 context can be made.
    static Renderer fromFile(const std::string& path);
    static Renderer fromJson(const std::string& json, const std::string& folder = ".");
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    Grid grid() const;

    // Makes the renderer's OpenGL 4.5 context current on the calling thread,
    // so that the caller's GL calls (glCreateBuffers, a compute shader of its
    // solver, CUDA–OpenGL interop) go to the context whose buffers a field
    // may name (Field::buffer).
    void makeContextCurrent() const;

    // The fields of the next frame, each named once; fields not named are
    // those the scene gives without them (the medium's, or the scene's
    // volume file's until the first call). Error naming the field for an
    // unknown name, a wrong shape or channel count, a grid that is not the
    // scene's, a value that is not finite or out of range (n ≤ 0, κ < 0,
    // σs > κ, |g| ≥ 1, ε < 0, T ≤ 0 K), an unknown unit or one on a field
    // other than temperature: nothing is changed.
    void setFields(const std::vector<Field>& fields);
    // Renders the current fields: the stages whose inputs changed run.
    void render();

    // Of the last rendered frame (Error before the first):
    // the image as the PNG of `eikon run`, (height, width, 3) sRGB 8-bit, row 0 at the top;
    ByteArray image() const;
    // its linear radiance, (height, width, 3) in W/(m²·sr);
    FloatArray radiance() const;
    // receiver r's irradiance map, (texels, texels, 3) in W/m², rows along
    // the receiver's v axis (receiverCount() of them, in scene order);
    std::size_t receiverCount() const;
    FloatArray receiver(std::size_t r) const;
    // the fluence φ, (nz, ny, nx, 3) in W/m² (Error where the scene keeps none:
    // it keeps one where its medium scatters or export.vtk asks for it);
    FloatArray fluence() const;
    // the frame's report, a JSON object as a line of `eikon run`'s
    // report.jsonl (units in its keys: _ms, _w, _bytes).
    std::string report() const;

private:
    friend class View;  // re-renders the current fields as the user moves the camera
    struct Impl;
    explicit Renderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// The live viewer fed by the caller's loop: a window (GLFW, on an X
// display) with eikon-view's camera gestures, panel and preview policy. It
// shows the renderer's last frame, scaled to fit and centred; a left drag
// orbits the camera, a middle drag pans, the wheel zooms, a right drag
// moves the first light, and the view then renders the renderer's current
// fields again itself — one ray per k×k
// pixels while the camera moves (k kept to a 40 ms view pass), the full
// frame once it has rested a quarter second — so the camera moves even
// while no new fields come. The panel shows the frame's stage timings and
// error figures and sets the exposure, the photon count and the tracer's
// settings ("apply settings"). The camera and the rest stay the renderer's
// for the frames the caller renders next. Used from the renderers' thread.
class View {
public:
    // `width` × `height` pixels, 0: the first frame's size. The window opens
    // at the first show().
    explicit View(std::string title = "eikon", int width = 0, int height = 0);
    ~View();
    View(View&&) noexcept;
    View& operator=(View&&) noexcept;

    // Handles the window's events (the gestures and the panel), renders the
    // renderer's fields again where the camera moved or the preview refines,
    // and shows its last frame (Error before its first, or where no window
    // can be opened: no display). false, showing nothing, once the user has
    // closed the window. A loop calls it each step, after render(), and may
    // call it meanwhile to keep the window live:
    //   while (view.show(renderer)) { solver.step(); renderer.setFields(...); renderer.render(); }
    bool show(Renderer& renderer);
    bool isOpen() const;
    // The frame as the window shows it, under the panel, (height, width, 3)
    // sRGB 8-bit, row 0 at the top (Error before the first show()).
    ByteArray windowImage() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace eikon
