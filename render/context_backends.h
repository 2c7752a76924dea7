// The two context factories behind create_context() (private to render/).
#pragma once

#include "rotinterp/render/context.h"

namespace rotinterp::render::detail {

Result<std::unique_ptr<GLContext>> create_osmesa_context();
Result<std::unique_ptr<GLContext>> create_egl_context();
// Whether libOSMesa can be dlopen'ed and has OSMesaCreateContextAttribs.
bool osmesa_library_loadable();

}  // namespace rotinterp::render::detail
