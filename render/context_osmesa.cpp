// OSMesa backend. libOSMesa is opened with dlopen so that the renderer (and the
// rotinterp binary) still loads on systems whose Mesa no longer ships it; there
// `--backend egl` works and osmesa reports itself unavailable.
#include "context_backends.h"

#if ROTINTERP_RENDER_HAVE_OSMESA_H
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <mutex>
#include <string>
#include <vector>

namespace rotinterp::render::detail {
namespace {

using CreateContextAttribsFn = OSMesaContext (*)(const int*, OSMesaContext);
using DestroyContextFn = void (*)(OSMesaContext);
using MakeCurrentFn = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using GetProcAddressFn = OSMESAproc (*)(const char*);

struct OSMesaLibrary {
  void* handle = nullptr;
  CreateContextAttribsFn create = nullptr;
  DestroyContextFn destroy = nullptr;
  MakeCurrentFn make_current = nullptr;
  GetProcAddressFn get_proc_address = nullptr;
  std::string error;
};

// Opened once, never closed (Mesa does not support being unloaded cleanly).
const OSMesaLibrary& library() {
  static OSMesaLibrary lib;
  static std::once_flag once;
  std::call_once(once, [] {
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
      lib.handle = ::dlopen(name, RTLD_NOW | RTLD_LOCAL);
      if (lib.handle) break;
    }
    if (!lib.handle) {
      lib.error = "OSMesa is not available (libOSMesa.so.8 not found; Mesa ≥ 25.1 removed it — try --backend egl)";
      return;
    }
    lib.create = reinterpret_cast<CreateContextAttribsFn>(::dlsym(lib.handle, "OSMesaCreateContextAttribs"));
    lib.destroy = reinterpret_cast<DestroyContextFn>(::dlsym(lib.handle, "OSMesaDestroyContext"));
    lib.make_current = reinterpret_cast<MakeCurrentFn>(::dlsym(lib.handle, "OSMesaMakeCurrent"));
    lib.get_proc_address = reinterpret_cast<GetProcAddressFn>(::dlsym(lib.handle, "OSMesaGetProcAddress"));
    if (!lib.create || !lib.destroy || !lib.make_current || !lib.get_proc_address)
      lib.error = "OSMesa library lacks OSMesaCreateContextAttribs (too old for a core-profile context)";
  });
  return lib;
}

// OSMesa needs a colour buffer to make a context current; the renderer draws into
// its own framebuffer objects, so a tiny one is enough.
constexpr int kDummySize = 4;

class OSMesaGLContext final : public GLContext {
 public:
  explicit OSMesaGLContext(OSMesaContext context) : context_(context), buffer_(kDummySize * kDummySize * 4) {}
  ~OSMesaGLContext() override { library().destroy(context_); }
  OSMesaGLContext(const OSMesaGLContext&) = delete;
  OSMesaGLContext& operator=(const OSMesaGLContext&) = delete;

  Backend backend() const override { return Backend::osmesa; }
  void* get_proc_address(const char* name) const override {
    return reinterpret_cast<void*>(library().get_proc_address(name));
  }
  Status make_current() override {
    if (!library().make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, kDummySize, kDummySize))
      return make_error("osmesa: OSMesaMakeCurrent failed");
    return Ok{};
  }

 private:
  OSMesaContext context_;
  std::vector<unsigned char> buffer_;
};

}  // namespace

bool osmesa_library_loadable() { return library().error.empty(); }

Result<std::unique_ptr<GLContext>> create_osmesa_context() {
  const OSMesaLibrary& lib = library();
  if (!lib.error.empty()) return make_error(lib.error);
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = lib.create(attributes, nullptr);
  if (!context) return make_error("osmesa: could not create an OpenGL 3.3 core-profile context");
  auto result = std::make_unique<OSMesaGLContext>(context);
  if (Status s = result->make_current(); !s) return s.failure();
  return std::unique_ptr<GLContext>(std::move(result));
}

}  // namespace rotinterp::render::detail

#else  // built without osmesa.h: the backend exists but is never available

namespace rotinterp::render::detail {
bool osmesa_library_loadable() { return false; }
Result<std::unique_ptr<GLContext>> create_osmesa_context() {
  return make_error("OSMesa support was not built (no osmesa.h at build time) — use --backend egl");
}
}  // namespace rotinterp::render::detail

#endif
