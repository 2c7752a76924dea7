// gl_api: loading the OpenGL 3.3 entry points the renderer uses.
#include "gl_api.h"

#include <string>

namespace rotinterp::render::detail {

Status GLApi::load(const GLContext& context) {
#define ROTINTERP_GL_LOAD(type, name)                                                          \
  name = reinterpret_cast<type>(context.get_proc_address("gl" #name));                         \
  if (!name)                                                                                   \
    return make_error(std::string(backend_name(context.backend())) + ": OpenGL entry point gl" #name \
                      " is missing");
  ROTINTERP_GL_FUNCTIONS(ROTINTERP_GL_LOAD)
#undef ROTINTERP_GL_LOAD
  return Ok{};
}

}  // namespace rotinterp::render::detail
