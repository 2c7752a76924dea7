// Shared by the binding files of rotinterp._rotinterp: array conversion, the
// quaternion layouts, and errors as Python exceptions.
//
// Quaternions cross the boundary as float64 arrays whose last axis is 4, in one
// of two layouts chosen per call: scalar-last (x, y, z, w) — scipy's default and
// Eigen's storage — or scalar-first (w, x, y, z) with scalar_first=True. Long
// calls release the GIL; errors raise ValueError (bad input) or OSError (files)
// with the library's one-line message.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/key_limit.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/continued.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/key_arrays.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstring>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::python {

namespace py = pybind11;

// Arrays as they come: float64, C-contiguous (converted only when they are not).
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

[[noreturn]] inline void value_error(const std::string& message) { throw py::value_error(message); }

template <class T>
T checked(Result<T> r) {
  if (!r) value_error(r.error());
  return std::move(*r);
}

inline std::vector<py::ssize_t> shape_of(const py::array& a) { return {a.shape(), a.shape() + a.ndim()}; }

inline std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

inline void require_finite(const Doubles& a, const char* what) {
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(p[i])) value_error(std::string(what) + " has a non-finite value at flat index " + std::to_string(i));
}

// `h` as an array, not yet converted, if its dtype is one of numpy's `kinds`: real
// numbers ("iuf": integers and floats) by default. Any other dtype (complex, bool, str,
// bytes, datetime64, timedelta64, object) raises TypeError: a cast to float64 would
// take it in silence, dropping an imaginary part or a unit.
inline py::array typed_array(const py::handle& h, const char* what, const char* kinds = "iuf") {
  py::array a = py::array::ensure(h);
  if (!a) value_error(std::string(what) + " must be an array of numbers");
  if (!std::strchr(kinds, a.dtype().kind()))
    throw py::type_error(std::string(what) + " must be " +
                         (std::strcmp(kinds, "iu") == 0 ? "integers" : "real numbers (integers or floats)") +
                         ", got dtype " + py::str(a.dtype()).cast<std::string>());
  return a;
}

// Refuses a call that would make more than kMaxKeys keys (frames × joints) before it
// allocates them: "<what> would give 400000000 frames × 1 joint, more than ... keys".
inline void require_key_count(double frames, std::size_t joints, const std::string& what) {
  if (too_many_keys(frames, joints)) value_error(what + " would give " + too_many_keys_text(frames, joints));
}

// A real array of at most kMaxKeys values per joint, as float64 (converted only when
// it is not C-contiguous float64; the limit is checked before the conversion).
inline Doubles real_array(const py::handle& h, const char* what) {
  const py::array a = typed_array(h, what);
  require_key_count(static_cast<double>(a.size()), 1, what);
  return Doubles::ensure(a);
}

// An integer array as int64 (kinds "iu"; a float such as 0.7 is refused, never
// truncated), refused where a uint64 value passes int64, as a wrap would hide it.
using Integers = py::array_t<long long, py::array::c_style | py::array::forcecast>;
inline Integers integer_array(const py::handle& h, const char* what) {
  const py::array a = typed_array(h, what, "iu");
  require_key_count(static_cast<double>(a.size()), 1, what);
  if (a.dtype().kind() == 'u' && a.size() > 0 && a.attr("max")().cast<unsigned long long>() > (1ULL << 63) - 1)
    value_error(std::string(what) + " has a value past 2**63 - 1: " + py::str(a.attr("max")()).cast<std::string>());
  return Integers::ensure(a);
}

// A whole number given as a Python or numpy integer, from `min` to `max`: a float (2.5)
// or a bool is refused (TypeError), never truncated, and one past int64 is too large.
inline long long whole_number(const py::handle& h, const std::string& what, long long min,
                              long long max = std::numeric_limits<long long>::max()) {
  const std::string text = py::repr(h).cast<std::string>();
  if (py::isinstance<py::bool_>(h) || !PyIndex_Check(h.ptr()))
    throw py::type_error(what + " must be a whole number, got " + text);
  const auto index = py::reinterpret_steal<py::object>(PyNumber_Index(h.ptr()));
  if (!index) throw py::error_already_set();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (overflow || v < min) value_error(what + " must be a whole number >= " + std::to_string(min) + ", got " + text);
  if (v > max) value_error(what + " must be a whole number <= " + std::to_string(max) + ", got " + text);
  return v;
}

// Metres per unit given as a number (or a string, as --unit takes it: "cm"), through
// --unit's parser: a positive finite number, else its message after "<what>: ".
inline double metres_per_unit_arg(const py::handle& h, const char* what) {
  const Result<double> m = parse_unit(py::str(h).cast<std::string>());
  if (!m) value_error(std::string(what) + ": " + m.error());
  return *m;
}

// A 1-D array of times.
inline Doubles times_array(const py::handle& h, const char* what) {
  Doubles t = real_array(h, what);
  if (t.ndim() != 1) value_error(std::string(what) + " must be a 1-D array of seconds");
  require_finite(t, what);
  return t;
}

// Times a curve is asked at, by every entry point (interpolate, an Interpolator's call and
// derivatives): a number (ndim 0) or a 1-D array, finite (a NaN raises, never a quiet
// answer), and, with extrapolate "raise", within [first, last]. Beyond the end keys the
// curve holds them ("clamp") or turns on at its end velocity ("continue",
// interp/continued.h), for the methods that have one.
enum class Extrapolate { clamp, raise, at_end_velocity };
inline Extrapolate extrapolate_of(const std::string& name) {
  if (name == "clamp") return Extrapolate::clamp;
  if (name == "raise") return Extrapolate::raise;
  if (name == "continue") return Extrapolate::at_end_velocity;
  value_error("extrapolate must be \"clamp\", \"raise\" or \"continue\", got \"" + name + "\"");
}
// Refuses "continue" for a method without a velocity at its end keys.
inline void require_continuable(Extrapolate ends, const MethodInfo& method) {
  if (ends == Extrapolate::at_end_velocity && !can_continue(method))
    value_error("extrapolate=\"continue\" needs a curve with a velocity at its end keys, and " + method.name +
                "'s is only its last chord's: use one of " + continued_method_names() +
                ", or extrapolate=\"clamp\" or \"raise\"");
}
inline Doubles sample_times(const py::handle& h, const char* what, Extrapolate extrapolate, double first,
                            double last) {
  Doubles t = real_array(h, what);
  if (t.ndim() > 1) value_error(std::string(what) + " must be a number or a 1-D array of seconds");
  require_finite(t, what);
  if (extrapolate == Extrapolate::raise)
    for (py::ssize_t i = 0; i < t.size(); ++i)
      if (t.data()[i] < first || t.data()[i] > last)
        value_error(std::string(what) + " = " + py::str(py::float_(t.data()[i])).cast<std::string>() +
                    " is outside the key range [" + py::str(py::float_(first)).cast<std::string>() + ", " +
                    py::str(py::float_(last)).cast<std::string>() + "] (extrapolate=\"raise\")");
  return t;
}

// The method called `name`, or ValueError: the library's message, and for scipy's class
// names the method that is their curve ("RotationSpline" is c2, "Slerp" slerp).
// `context` starts the message ("methods: " where a list was given).
inline const MethodInfo& method_of(const std::string& name, const std::string& context = "") {
  if (const MethodInfo* m = find_method(name)) return *m;
  std::string lower;
  for (char c : name) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (lower == "rotationspline")
    value_error(context + "unknown method '" + name + "': scipy's RotationSpline is method=\"c2\" here (the same curve)");
  value_error(context + unknown_method_message(name));
}

// numpy's text for the index of the i-th quaternion of an array of shape (..., 4):
// "quats[3, 1]".
inline std::string quat_index_text(const char* what, const py::array& a, py::ssize_t i) {
  std::string index;
  for (py::ssize_t d = a.ndim() - 2; d >= 0; --d) {
    index = std::to_string(i % a.shape(d)) + (index.empty() ? "" : ", ") + index;
    i /= a.shape(d);
  }
  return std::string(what) + "[" + index + "]";
}

// Quaternions as callers hold them, taken as scipy's Rotation.from_quat takes them:
// any real dtype (float32 from glTF or PyTorch, decimals rounded in a CSV), each
// finite non-zero quaternion normalized; or any object with as_quat() (a scipy
// Rotation), whose scalar-last layout is used whatever scalar_first says. The
// library itself keeps its unit-norm contract (RotationTrack rule 3): this is the
// boundary where rounded data becomes unit (unit_quat, interp/key_arrays.h).

// Refuses an array whose last axis is not 4, naming `what` and its shape.
inline void require_quat_shape(const py::array& raw, const char* what) {
  if (raw.ndim() < 1 || raw.shape(raw.ndim() - 1) != 4)
    value_error(std::string(what) + " must be quaternions: an array of shape (..., 4) or a scipy Rotation, got shape " +
                shape_text(raw));
}

// quat_array: the array as float64 (converted only when it is not C-contiguous
// float64), its last axis 4; scalar_first is set to the layout of its data.
inline Doubles quat_array(const py::handle& h, bool& scalar_first, const char* what) {
  const bool rotation = py::hasattr(h, "as_quat");
  const py::array a = typed_array(rotation ? h.attr("as_quat")() : py::reinterpret_borrow<py::object>(h), what);
  if (rotation) scalar_first = false;
  require_quat_shape(a, what);
  require_key_count(static_cast<double>(a.size() / 4), 1, what);
  const Doubles raw = Doubles::ensure(a);
  return raw;
}

// Raises the error for the first quaternion of `raw` that unit_quat refuses, by its
// index (numpy's order); returns if there is none.
inline void refuse_bad_quats(const Doubles& raw, const char* what) {
  Eigen::Vector4d unused = Eigen::Vector4d::Zero();
  for (py::ssize_t i = 0; i < raw.size() / 4; ++i) {
    const double* p = raw.data() + 4 * i;
    if (unit_quat(p, unused)) continue;
    if (!Eigen::Map<const Eigen::Vector4d>(p).allFinite()) value_error(quat_index_text(what, raw, i) + " is not finite");
    value_error(quat_index_text(what, raw, i) + " is zero: a rotation needs a non-zero quaternion");
  }
}

// quat_array normalized into a float64 copy (for the calls that keep the whole array).
inline Doubles unit_quats(const py::handle& h, bool& scalar_first, const char* what) {
  const Doubles raw = quat_array(h, scalar_first, what);
  Doubles out(shape_of(raw));
  const double* p = raw.data();
  double* o = out.mutable_data();
  Eigen::Vector4d unit = Eigen::Vector4d::Zero();
  for (py::ssize_t i = 0; i < raw.size() / 4; ++i) {
    if (!unit_quat(p + 4 * i, unit)) refuse_bad_quats(raw, what);
    Eigen::Map<Eigen::Vector4d>(o + 4 * i) = unit;
  }
  return out;
}

// The rotation track of joint j from times (K,) and quaternions (K, J, 4) as flat data.
inline RotationTrack track_of(const double* times, const double* quats, std::size_t k, std::size_t joints,
                              std::size_t j, bool scalar_first) {
  RotationTrack track;
  track.times.assign(times, times + k);
  track.keys.resize(k);
  for (std::size_t i = 0; i < k; ++i) track.keys[i] = quat_at(quats + 4 * (i * joints + j), scalar_first);
  return track;
}

// read_clip's reading (bind_commands.cpp): the clip at `path`, its animation `anim`
// (None, a name or an index) and its unit (None: the file's or inferred; "cm", …, or
// metres per unit as a number); raises OSError subclasses or ValueError.
Clip read_path(const std::string& path, const py::object& anim, const py::object& unit = py::none(),
               bool allow_external_files = false);
// read_path's reading of an FBX file, and its own motion (its curves) into `motion`:
// render(methods=["source", ...]).
Clip read_path_with_source_motion(const std::string& path, SourceMotion& motion);
// A clip given as a rotinterp.Clip or read from a path.
Clip clip_or_path(const py::object& input);

// The parts of the module, one per API area (module.cpp calls them in this order).
void bind_clip(py::module_& m);
void bind_interp(py::module_& m);
void bind_commands(py::module_& m);
void bind_reduce(py::module_& m);
void bind_render(py::module_& m);  // bind_render.cpp: only where the renderer is built

}  // namespace rotinterp::python
