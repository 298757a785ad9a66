// eikon::View (include/eikon/eikon.h): a window of its own, apart from the
// renderers' headless context, that shows the frames the caller hands it
// through eikon-view's presenter (apps/common/ImagePresenter.h). A thread
// has one current context across EGL and GLX (libglvnd refuses a second):
// the view releases the renderers' EGL context before its window's and its
// window's after, and each renderer makes its own current again before its
// GL work, so the two take turns on the one thread.
#include "eikon/eikon.h"

#include "apps/common/ImagePresenter.h"
#include "gl/GlContext.h"

#include <epoxy/egl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>

namespace eikon {

struct View::Impl {
    std::string title;
    int width = 0, height = 0;
    std::unique_ptr<gl::WindowContext> window;
    std::unique_ptr<view::ImagePresenter> presenter;  // of the window's context
    render::Image8 shown;
    bool closed = false;

    // The window's context current in place of a renderer's, and back to none.
    static void releaseRenderers() {
        if (eglGetCurrentContext() != EGL_NO_CONTEXT)
            eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    void enter() {
        releaseRenderers();
        window->makeCurrent();
    }
    static void leave() { glfwMakeContextCurrent(nullptr); }

    void close() {
        if (window) enter();  // the presenter's GL objects go with their context current
        presenter.reset();
        window.reset();
        leave();
    }
    ~Impl() { close(); }

    // The frame into the window's back buffer, the window's context current.
    void present() {
        enter();
        int framebufferWidth = 0, framebufferHeight = 0;
        window->framebufferSize(framebufferWidth, framebufferHeight);
        presenter->present(shown, framebufferWidth, framebufferHeight);
    }
};

View::View(std::string title, int width, int height) : impl_(std::make_unique<Impl>()) {
    if (width < 0 || height < 0)
        throw Error("eikon::View: expected a window size of 0 (the first frame's) or more pixels, found " +
                    std::to_string(width) + " × " + std::to_string(height));
    impl_->title = std::move(title);
    impl_->width = width;
    impl_->height = height;
}
View::~View() = default;
View::View(View&&) noexcept = default;
View& View::operator=(View&&) noexcept = default;

bool View::show(const Renderer& renderer) {
    Impl& impl = *impl_;
    if (impl.closed) return false;
    const ByteArray image = renderer.image();
    impl.shown.height = static_cast<int>(image.shape[0]);
    impl.shown.width = static_cast<int>(image.shape[1]);
    impl.shown.rgba.assign(image.shape[0] * image.shape[1] * 4, 255);
    for (std::size_t p = 0; p < image.shape[0] * image.shape[1]; ++p)
        for (std::size_t c = 0; c < 3; ++c) impl.shown.rgba[4 * p + c] = image.values[3 * p + c];
    if (!impl.window) {
        Impl::releaseRenderers();
        try {
            impl.window = gl::createWindowContext(impl.width ? impl.width : impl.shown.width,
                                                  impl.height ? impl.height : impl.shown.height, impl.title);
        } catch (const std::runtime_error& error) {
            throw Error(std::string("eikon::View: expected a window, found none: ") + error.what());
        }
        impl.presenter = std::make_unique<view::ImagePresenter>();
    }
    impl.present();
    impl.window->swapBuffers();
    impl.window->pollEvents();
    if (impl.window->shouldClose()) {
        impl.closed = true;
        impl.close();
    }
    Impl::leave();
    return !impl.closed;
}

bool View::isOpen() const { return !impl_->closed; }

ByteArray View::windowImage() const {
    Impl& impl = *impl_;
    if (!impl.window) throw Error("eikon::View::windowImage: expected a window shown (call show()), found none");
    impl.present();  // again, into the back buffer, which is read before any swap
    int width = 0, height = 0;
    impl.window->framebufferSize(width, height);
    const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
    std::vector<std::uint8_t> rgba(w * h * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    ByteArray array{{h, w, 3}, std::vector<std::uint8_t>(w * h * 3)};
    for (std::size_t y = 0; y < h; ++y)  // GL's row 0 is the bottom
        for (std::size_t x = 0; x < w; ++x)
            for (std::size_t c = 0; c < 3; ++c)
                array.values[(y * w + x) * 3 + c] = rgba[((h - 1 - y) * w + x) * 4 + c];
    Impl::leave();
    return array;
}

}  // namespace eikon
