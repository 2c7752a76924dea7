// Offscreen OpenGL contexts. The drawing code never knows how its context was
// made: it asks a GLContext for entry points and draws into its own framebuffer
// objects, so a context needs no window and no default framebuffer.
//
// Two backends, chosen at run time:
//  * osmesa — Mesa's OSMesa (libOSMesa.so.8, loaded with dlopen, so a binary built
//    here still runs where Mesa ≥ 25.1 removed it);
//  * egl    — EGL on the surfaceless platform (EGL_MESA_platform_surfaceless) with
//    a configless, surfaceless context (EGL_KHR_surfaceless_context).
// Both ask for an OpenGL ≥ 3.3 core-profile context (llvmpipe gives 4.5 core).
#pragma once

#include "rotinterp/core/result.h"

#include <memory>
#include <string>
#include <string_view>

namespace rotinterp::render {

enum class Backend { osmesa, egl };

// "osmesa" or "egl".
const char* backend_name(Backend backend);
// The backend called `name` ("osmesa" or "egl"); an error naming the choices otherwise.
Result<Backend> parse_backend(std::string_view name);

// An OpenGL ≥ 3.3 core context. Current on the thread that created it; use it
// from that thread only (or call make_current() on another thread first).
class GLContext {
 public:
  virtual ~GLContext() = default;
  virtual Backend backend() const = 0;
  // Address of a GL entry point (core or extension); nullptr if there is none.
  virtual void* get_proc_address(const char* name) const = 0;
  // Makes the context current on the calling thread.
  virtual Status make_current() = 0;
};

// Whether a context of this backend can be created here. Cheap after the first
// call for a backend (the answer is cached).
bool backend_available(Backend backend);
// OSMesa where present, else EGL.
Backend default_backend();
// A new context, current on the calling thread. The error is one line saying
// which backend failed and why (library missing, no core 3.3 context, …).
Result<std::unique_ptr<GLContext>> create_context(Backend backend);

}  // namespace rotinterp::render
