// EGL surfaceless backend: no window system, no pbuffer — a configless context
// made current with EGL_NO_SURFACE; all drawing goes to framebuffer objects.
#include "context_backends.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace rotinterp::render::detail {
namespace {

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("egl: ") + what + " (EGL error " + code + ")";
}

class EGLGLContext final : public GLContext {
 public:
  EGLGLContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
  ~EGLGLContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // The display is left initialized: EGL displays are shared per process, and
    // terminating one would break other live contexts on it.
  }
  EGLGLContext(const EGLGLContext&) = delete;
  EGLGLContext& operator=(const EGLGLContext&) = delete;

  Backend backend() const override { return Backend::egl; }
  void* get_proc_address(const char* name) const override {
    return reinterpret_cast<void*>(eglGetProcAddress(name));
  }
  Status make_current() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      return make_error(egl_error("eglMakeCurrent failed"));
    return Ok{};
  }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

}  // namespace

Result<std::unique_ptr<GLContext>> create_egl_context() {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless"))
    return make_error("egl: the surfaceless platform (EGL_MESA_platform_surfaceless) is not available");
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) return make_error("egl: eglGetPlatformDisplayEXT is missing");
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) return make_error(egl_error("no surfaceless display"));
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return make_error(egl_error("eglInitialize failed"));
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context"))
    return make_error("egl: the display lacks EGL_KHR_surfaceless_context");
  if (!has_extension(extensions, "EGL_KHR_no_config_context") &&
      !has_extension(extensions, "EGL_MESA_configless_context"))
    return make_error("egl: the display lacks configless contexts (EGL_KHR_no_config_context)");
  if (!eglBindAPI(EGL_OPENGL_API)) return make_error(egl_error("desktop OpenGL is not supported"));
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) return make_error(egl_error("could not create an OpenGL 3.3 core-profile context"));
  auto result = std::make_unique<EGLGLContext>(display, context);
  if (Status s = result->make_current(); !s) return s.failure();
  return std::unique_ptr<GLContext>(std::move(result));
}

}  // namespace rotinterp::render::detail
