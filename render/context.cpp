// context: choosing an offscreen OpenGL context backend (EGL or OSMesa).
#include "rotinterp/render/context.h"

#include "context_backends.h"

#include <mutex>

namespace rotinterp::render {

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::osmesa: return "osmesa";
    case Backend::egl: return "egl";
  }
  return "?";
}

Result<Backend> parse_backend(std::string_view name) {
  if (name == "osmesa") return Backend::osmesa;
  if (name == "egl") return Backend::egl;
  return make_error("unknown backend '" + std::string(name) + "' (choose osmesa or egl)");
}

Result<std::unique_ptr<GLContext>> create_context(Backend backend) {
  switch (backend) {
    case Backend::osmesa: return detail::create_osmesa_context();
    case Backend::egl: return detail::create_egl_context();
  }
  return make_error("unknown backend");
}

bool backend_available(Backend backend) {
  static std::once_flag once[2];
  static bool available[2] = {false, false};
  const int i = backend == Backend::osmesa ? 0 : 1;
  std::call_once(once[i], [&] {
    available[i] = backend == Backend::osmesa ? detail::osmesa_library_loadable() : create_context(backend).ok();
  });
  return available[i];
}

Backend default_backend() { return backend_available(Backend::osmesa) ? Backend::osmesa : Backend::egl; }

}  // namespace rotinterp::render
