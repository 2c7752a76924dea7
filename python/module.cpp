// rotinterp._rotinterp: the library on numpy arrays (python/rotinterp/__init__.py
// re-exports it; __init__.pyi documents the signatures). One file per API area:
// bind_clip.cpp, bind_interp.cpp, bind_commands.cpp (read, write, resample, evaluate,
// info), bind_reduce.cpp, bind_render.cpp; shared helpers in common.h.
#include "common.h"
#include "rotinterp/clip/resample.h"

PYBIND11_MODULE(_rotinterp, m) {
  using namespace rotinterp;
  m.doc() = "rotinterp: keyframed 3-D orientations on numpy arrays (see the rotinterp package)";
  m.attr("__version__") = ROTINTERP_VERSION;
  m.attr("default_method") = kDefaultResampleMethod;
  // Clip first: the signatures of the others name it.
  python::bind_clip(m);
  python::bind_interp(m);
  python::bind_commands(m);
  python::bind_reduce(m);
  // Without the renderer the package's render() says so (rotinterp/__init__.py).
#if ROTINTERP_HAVE_RENDER
  python::bind_render(m);
#endif
}
