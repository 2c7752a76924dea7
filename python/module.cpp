// rotinterp._rotinterp: the library on numpy arrays (python/rotinterp/__init__.py
// re-exports it; __init__.pyi documents the signatures).
//
// Quaternions cross the boundary as float64 arrays whose last axis is 4, in one
// of two layouts chosen per call: scalar-last (x, y, z, w) — scipy's default and
// Eigen's storage — or scalar-first (w, x, y, z) with scalar_first=True. Long
// calls release the GIL; errors raise ValueError (bad input) or OSError (files)
// with the library's one-line message.
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace rotinterp {
namespace {

// Arrays as they come: float64, C-contiguous (converted only when they are not).
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

[[noreturn]] void value_error(const std::string& message) { throw py::value_error(message); }

template <class T>
T checked(Result<T> r) {
  if (!r) value_error(r.error());
  return std::move(*r);
}

Quat quat_at(const double* p, bool scalar_first) {
  return scalar_first ? Quat(p[0], p[1], p[2], p[3]) : Quat(p[3], p[0], p[1], p[2]);
}
void put_quat(const Quat& q, double* p, bool scalar_first) {
  if (scalar_first) {
    p[0] = q.w(), p[1] = q.x(), p[2] = q.y(), p[3] = q.z();
  } else {
    p[0] = q.x(), p[1] = q.y(), p[2] = q.z(), p[3] = q.w();
  }
}

std::vector<py::ssize_t> shape_of(const py::array& a) { return {a.shape(), a.shape() + a.ndim()}; }

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

void require_finite(const Doubles& a, const char* what) {
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(p[i])) value_error(std::string(what) + " has a non-finite value at flat index " + std::to_string(i));
}

// A 1-D array of times.
Doubles times_array(const py::handle& h, const char* what) {
  Doubles t = Doubles::ensure(h);
  if (!t || t.ndim() != 1) value_error(std::string(what) + " must be a 1-D array of seconds");
  require_finite(t, what);
  return t;
}

// The rotation track of joint j from times (K,) and quaternions (K, J, 4) as flat data.
RotationTrack track_of(const double* times, const double* quats, std::size_t k, std::size_t joints, std::size_t j,
                       bool scalar_first) {
  RotationTrack track;
  track.times.assign(times, times + k);
  track.keys.resize(k);
  for (std::size_t i = 0; i < k; ++i) track.keys[i] = quat_at(quats + 4 * (i * joints + j), scalar_first);
  return track;
}

// ---- methods ----------------------------------------------------------------------

py::list method_list() {
  py::list out;
  for (const MethodInfo& m : methods()) {
    py::dict d;
    d["name"] = m.name;
    d["description"] = m.description;
    d["continuity"] = m.continuity;
    d["coordinate_invariant"] = m.coordinate_invariant;
    d["exact_on_constant_velocity"] = m.exact_on_constant_velocity;
    d["preserves_holds"] = m.preserves_holds;
    out.append(d);
  }
  return out;
}

// ---- interpolate ------------------------------------------------------------------

// quats (K, 4) or (K, J, 4) against times (K,): the joint count (0 for a single track).
std::size_t joints_of(const Doubles& q, std::size_t k) {
  const bool single = q.ndim() == 2 && q.shape(1) == 4;
  const bool many = q.ndim() == 3 && q.shape(2) == 4;
  if (!single && !many) value_error("quats must have shape (K, 4) or (K, J, 4), got " + shape_text(q));
  if (static_cast<std::size_t>(q.shape(0)) != k)
    value_error("quats has " + std::to_string(q.shape(0)) + " keys but times has " + std::to_string(k));
  return single ? 0 : static_cast<std::size_t>(q.shape(1));
}

py::array interpolate(const py::handle& times_in, const py::handle& quats_in, const py::handle& new_times_in,
                      const std::string& method, bool scalar_first) {
  const Doubles times = times_array(times_in, "times");
  const Doubles new_times = times_array(new_times_in, "new_times");
  const Doubles quats = Doubles::ensure(quats_in);
  if (!quats) value_error("quats must be an array of float quaternions");
  const auto k = static_cast<std::size_t>(times.shape(0));
  const std::size_t joints = joints_of(quats, k);
  require_finite(quats, "quats");
  if (!find_method(method)) value_error(unknown_method_message(method));
  const auto n = static_cast<std::size_t>(new_times.shape(0));
  const std::size_t jn = joints == 0 ? 1 : joints;
  std::vector<py::ssize_t> shape = {static_cast<py::ssize_t>(n)};
  if (joints) shape.push_back(static_cast<py::ssize_t>(joints));
  shape.push_back(4);
  py::array_t<double> out(shape);
  double* o = out.mutable_data();
  const double *t = times.data(), *q = quats.data(), *nt = new_times.data();
  std::string error;
  {
    py::gil_scoped_release release;
    // One joint at a time, each curve freed before the next is built: the heap
    // memory is reused (31 c2 curves alive at once cost 11 000 page faults a call,
    // more than the evaluation itself).
    std::vector<Quat> samples(n);
    for (std::size_t j = 0; j < jn; ++j) {
      auto curve = make_interpolator(method, track_of(t, q, k, jn, j, scalar_first));
      if (!curve) {
        error = (joints ? "joint " + std::to_string(j) + ": " : std::string()) + curve.error();
        break;
      }
      (*curve)->evaluate(nt, n, samples.data());
      for (std::size_t i = 0; i < n; ++i) put_quat(samples[i], o + 4 * (i * jn + j), scalar_first);
    }
  }
  if (!error.empty()) value_error(error);
  return out;
}

// One track's interpolator, callable on times.
class PyInterpolator {
 public:
  PyInterpolator(const py::handle& times_in, const py::handle& quats_in, std::string method, bool scalar_first)
      : method_(std::move(method)), scalar_first_(scalar_first) {
    const Doubles times = times_array(times_in, "times");
    const Doubles quats = Doubles::ensure(quats_in);
    if (!quats) value_error("quats must be an array of float quaternions");
    const auto k = static_cast<std::size_t>(times.shape(0));
    if (joints_of(quats, k) != 0) value_error("make_interpolator takes one track: quats of shape (K, 4)");
    require_finite(quats, "quats");
    track_ = track_of(times.data(), quats.data(), k, 1, 0, scalar_first);
    curve_ = checked(make_interpolator(method_, track_));
  }

  // Orientation(s) at t: (4,) for a number, (N, 4) for an array.
  py::object call(const py::handle& t) const {
    return apply(t, 4, [this](const double* x, std::size_t n, double* o) {
      std::vector<Quat> q(n);
      curve_->evaluate(x, n, q.data());
      for (std::size_t i = 0; i < n; ++i) put_quat(q[i], o + 4 * i, scalar_first_);
    });
  }
  // Fixed-frame angular velocity (rad/s): (3,) or (N, 3).
  py::object angular_velocity(const py::handle& t) const {
    return apply(t, 3, [this](const double* x, std::size_t n, double* o) {
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 w = curve_->angular_velocity(x[i]);
        o[3 * i] = w.x(), o[3 * i + 1] = w.y(), o[3 * i + 2] = w.z();
      }
    });
  }
  const std::string& method() const { return method_; }
  py::array times() const { return py::array_t<double>(track_.times.size(), track_.times.data()); }

 private:
  template <class Fill>
  py::object apply(const py::handle& t, py::ssize_t width, Fill fill) const {
    const bool scalar = py::isinstance<py::float_>(t) || py::isinstance<py::int_>(t);
    const Doubles x = Doubles::ensure(t);
    if (!x || x.ndim() > 1) value_error("t must be a number or a 1-D array of seconds");
    const auto n = static_cast<std::size_t>(x.size());
    py::array_t<double> out(scalar ? std::vector<py::ssize_t>{width}
                                   : std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), width});
    double* o = out.mutable_data();
    const double* xs = x.data();
    {
      py::gil_scoped_release release;
      fill(xs, n, o);
    }
    return std::move(out);
  }

  std::string method_;
  bool scalar_first_;
  RotationTrack track_;
  std::unique_ptr<Interpolator> curve_;
};

// ---- clips ------------------------------------------------------------------------

// Whether every rotation track is keyed at the same times (BVH, resampled clips).
bool on_one_grid(const Clip& c) {
  for (const RotationTrack& r : c.rotations)
    if (r.times != c.rotations.front().times) return false;
  for (const auto& tr : c.translations)
    if (tr && tr->times != c.rotations.front().times) return false;
  return !c.rotations.empty();
}
void require_one_grid(const Clip& c) {
  if (!on_one_grid(c))
    value_error("clip '" + c.name +
                "': its joints are keyed at different times (a sparse FBX); rotinterp.resample(clip) puts every joint "
                "on the frame grid, clip.track(j) gives one joint's own keys");
}

py::array clip_times(const Clip& c) {
  require_one_grid(c);
  const auto& t = c.rotations.front().times;
  return py::array_t<double>(t.size(), t.data());
}

py::array clip_rotations(const Clip& c, bool scalar_first) {
  require_one_grid(c);
  const std::size_t f = c.rotations.front().times.size(), nj = c.rotations.size();
  py::array_t<double> out({f, nj, std::size_t{4}});
  double* o = out.mutable_data();
  for (std::size_t j = 0; j < nj; ++j)
    for (std::size_t k = 0; k < f; ++k) put_quat(c.rotations[j].keys[k], o + 4 * (k * nj + j), scalar_first);
  return out;
}

py::dict clip_translations(const Clip& c) {
  py::dict out;
  for (std::size_t j = 0; j < c.translations.size(); ++j) {
    if (!c.translations[j]) continue;
    const auto& keys = c.translations[j]->keys;
    py::array_t<double> a({keys.size(), std::size_t{3}});
    double* o = a.mutable_data();
    for (std::size_t k = 0; k < keys.size(); ++k) o[3 * k] = keys[k].x(), o[3 * k + 1] = keys[k].y(), o[3 * k + 2] = keys[k].z();
    out[py::str(c.skeleton.joints[j].name)] = a;
  }
  return out;
}

py::tuple clip_track(const Clip& c, const py::handle& joint, bool scalar_first) {
  int j = -1;
  if (py::isinstance<py::str>(joint)) {
    j = c.skeleton.find(joint.cast<std::string>());
    if (j < 0) value_error("no joint '" + joint.cast<std::string>() + "' in clip '" + c.name + "'");
  } else {
    j = joint.cast<int>();
    if (j < 0 || j >= static_cast<int>(c.rotations.size()))
      value_error("joint index " + std::to_string(j) + " outside 0.." + std::to_string(c.rotations.size() - 1));
  }
  const RotationTrack& r = c.rotations[static_cast<std::size_t>(j)];
  py::array_t<double> q({r.keys.size(), std::size_t{4}});
  for (std::size_t k = 0; k < r.keys.size(); ++k) put_quat(r.keys[k], q.mutable_data() + 4 * k, scalar_first);
  return py::make_tuple(py::array_t<double>(r.times.size(), r.times.data()), q);
}

py::object rate_hz(const Clip& c) {
  const std::optional<Rate> r = rotinterp::clip_rate(c);
  if (!r) return py::none();
  return py::float_(r->hz());
}
py::object rate_text(const Clip& c) {
  const std::optional<Rate> r = rotinterp::clip_rate(c);
  if (!r) return py::none();
  return py::str(r->to_string());
}

// A clip from arrays (see the stub for the argument rules).
Clip make_clip(const std::vector<std::string>& names, const py::handle& parents_in, const py::handle& offsets_in,
               const py::handle& times_in, const py::handle& rotations_in, const py::object& translations,
               std::optional<double> frame_time, double unit_scale, bool scalar_first, const std::string& name) {
  const std::size_t nj = names.size();
  const Doubles times = times_array(times_in, "times");
  const auto f = static_cast<std::size_t>(times.shape(0));
  const auto parents = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(parents_in);
  const Doubles offsets = Doubles::ensure(offsets_in), rotations = Doubles::ensure(rotations_in);
  if (!parents || parents.ndim() != 1 || static_cast<std::size_t>(parents.shape(0)) != nj)
    value_error("parents must be a 1-D array with one entry per name (" + std::to_string(nj) + ")");
  if (!offsets || offsets.ndim() != 2 || static_cast<std::size_t>(offsets.shape(0)) != nj || offsets.shape(1) != 3)
    value_error("offsets must have shape (J, 3) = (" + std::to_string(nj) + ", 3)");
  if (!rotations || rotations.ndim() != 3 || static_cast<std::size_t>(rotations.shape(0)) != f ||
      static_cast<std::size_t>(rotations.shape(1)) != nj || rotations.shape(2) != 4)
    value_error("rotations must have shape (F, J, 4) = (" + std::to_string(f) + ", " + std::to_string(nj) + ", 4), got " +
                shape_text(rotations));
  require_finite(offsets, "offsets");
  require_finite(rotations, "rotations");
  Clip c;
  c.name = name;
  c.source_format = "python";
  c.unit = {unit_scale, UnitOrigin::given, "given: make_clip(unit_scale=)"};
  for (std::size_t j = 0; j < nj; ++j) {
    Joint joint;
    joint.name = names[j];
    joint.parent = static_cast<int>(parents.at(static_cast<py::ssize_t>(j)));
    joint.offset = Vec3(offsets.at(j, 0), offsets.at(j, 1), offsets.at(j, 2));
    c.skeleton.joints.push_back(std::move(joint));
  }
  c.rotations.resize(nj);
  c.translations.resize(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    c.rotations[j] = track_of(times.data(), rotations.data(), f, nj, j, scalar_first);
    c.rotations[j].make_sign_continuous();  // normalizes too
  }
  if (!translations.is_none()) {
    for (const auto& item : translations.cast<py::dict>()) {
      const std::string joint = item.first.cast<std::string>();
      const int j = c.skeleton.find(joint);
      if (j < 0) value_error("translations: no joint '" + joint + "'");
      const Doubles p = Doubles::ensure(item.second);
      if (!p || p.ndim() != 2 || static_cast<std::size_t>(p.shape(0)) != f || p.shape(1) != 3)
        value_error("translations['" + joint + "'] must have shape (F, 3) = (" + std::to_string(f) + ", 3)");
      require_finite(p, "translations");
      TranslationTrack tr;
      tr.times.assign(times.data(), times.data() + f);
      for (std::size_t k = 0; k < f; ++k) tr.keys.emplace_back(p.at(k, 0), p.at(k, 1), p.at(k, 2));
      c.translations[static_cast<std::size_t>(j)] = std::move(tr);
    }
  }
  // The frame time: given, else the uniform spacing of `times` (within 1e-9 relative).
  if (frame_time) {
    c.frame_time = *frame_time;
  } else if (f >= 2) {
    const double dt = (times.at(f - 1) - times.at(0)) / static_cast<double>(f - 1);
    bool uniform = dt > 0.0;
    for (std::size_t k = 1; k < f && uniform; ++k)
      uniform = std::abs(times.at(k) - times.at(k - 1) - dt) <= 1e-9 * dt;
    if (uniform) c.frame_time = dt;
  }
  if (Status s = c.validate(); !s) value_error("clip '" + name + "': " + s.error());
  return c;
}

// ---- files ------------------------------------------------------------------------

// The reader's error as a Python exception: OSError subclasses for what the file
// system says (its kind), ValueError for a file that is not a clip.
[[noreturn]] void raise_read_error(const Error& e, const fs::path& path) {
  PyObject* type = PyExc_ValueError;
  int err = 0;
  switch (e.kind) {
    case ErrorKind::no_file: type = PyExc_FileNotFoundError, err = ENOENT; break;
    case ErrorKind::directory: type = PyExc_IsADirectoryError, err = EISDIR; break;
    case ErrorKind::cannot_open: type = PyExc_OSError, err = EIO; break;
    default: value_error(e.message);
  }
  PyErr_SetObject(type, py::make_tuple(err, e.message, path.string()).ptr());
  throw py::error_already_set();
}

Clip read_path(const fs::path& path, const py::object& anim) {
  ReadOptions o;
  if (!anim.is_none()) o.animation = py::str(anim).cast<std::string>();
  Result<Clip> c = make_error("");
  {
    py::gil_scoped_release release;
    c = read_clip(path, o);
  }
  if (!c) raise_read_error(c.failure(), path);
  return std::move(*c);
}

void write_path(const Clip& clip, const fs::path& path, const std::string& bvh_order) {
  if (!can_write_format(path))
    value_error("output '" + path.string() + "': unknown format (use .bvh, .fbx, .glb, .gltf or .dae)");
  WriteOptions o;
  o.bvh_order = bvh_order;
  Status s = Ok{};
  {
    py::gil_scoped_release release;
    s = write_clip(clip, path, o);
  }
  if (!s) {
    PyErr_SetString(PyExc_OSError, s.error().c_str());
    throw py::error_already_set();
  }
}

// ---- resample ------------------------------------------------------------------------

Rate rate_of(const py::handle& fps) {
  // Fractions print as "30000/1001", numbers and strings as themselves.
  return checked(parse_rate(py::str(fps).cast<std::string>()));
}

Clip resample(const Clip& clip, const py::object& fps, const py::object& keep_every, const std::string& method,
              const std::map<std::string, std::string>& method_for, const std::string& translation,
              const py::object& range) {
  ResampleOptions o;
  if (!fps.is_none()) o.fps = rate_of(fps);
  if (!keep_every.is_none()) {
    const long long n = keep_every.cast<long long>();
    if (n < 1) value_error("keep_every must be a whole number >= 1, got " + std::to_string(n));
    o.keep_every = static_cast<std::size_t>(n);
  }
  o.method = method;
  for (const auto& [joint, m] : method_for) o.method_for.emplace_back(joint, m);
  o.translation = checked(parse_translation_interp(translation));
  if (!range.is_none()) {
    const auto r = range.cast<std::pair<std::optional<double>, std::optional<double>>>();
    TimeRange tr;
    if (r.first) tr.start = *r.first;
    if (r.second) tr.end = *r.second;
    o.range = tr;
  }
  Result<Clip> out = make_error("");
  {
    py::gil_scoped_release release;
    out = resample_clip(clip, o);
  }
  return checked(std::move(out));
}

// ---- evaluate --------------------------------------------------------------------------

py::dict evaluate(const py::object& inputs, const std::optional<std::vector<std::string>>& method_names_in,
                  const std::vector<int>& keep_every, int subframe, double shell_distance_m) {
  ClipEvalOptions o;
  if (method_names_in) {
    o.methods = *method_names_in;
  } else {
    for (const MethodInfo& m : methods()) o.methods.push_back(m.name);
  }
  for (std::string& m : o.methods) {
    if (!find_method(m)) value_error(unknown_method_message(m));
    m = find_method(m)->name;  // one spelling in the results ("SLERP" is slerp)
  }
  for (int n : keep_every)
    if (n < 1) value_error("keep_every values must be >= 1, got " + std::to_string(n));
  o.keep_every = keep_every;
  o.subframe = subframe;
  o.shell_distance_m = shell_distance_m;
  // One clip, one path, or a list of them; paths keep their text as the clip id (as
  // in errors.csv), clips their name.
  std::vector<py::object> items;
  if (py::isinstance<py::list>(inputs) || py::isinstance<py::tuple>(inputs)) {
    for (const auto& h : inputs) items.push_back(py::reinterpret_borrow<py::object>(h));
  } else {
    items.push_back(inputs);
  }
  std::vector<ErrorRow> rows;
  for (const py::object& item : items) {
    Clip clip;
    std::string id;
    if (py::isinstance<Clip>(item)) {
      clip = item.cast<Clip>();
      id = clip.name;
    } else {
      id = py::str(item).cast<std::string>();
      clip = read_path(id, py::none());
    }
    Result<std::vector<ErrorRow>> r = make_error("");
    {
      py::gil_scoped_release release;
      r = evaluate_clip(clip, id, o);
    }
    std::vector<ErrorRow> part = checked(std::move(r));
    rows.insert(rows.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }
  // Columns, named and ordered as in errors.csv (error_row.h). End Site rows have no
  // rotation or smoothness values, rows of joints that are not feet no foot-contact
  // values: NaN there, as pandas reads the CSV's empty cells.
  const std::size_t n = rows.size();
  py::list clip, method, joint, kind;
  py::array_t<long long> keep(n), frames(n), samples(n);
  const std::vector<ErrorValueColumn>& measured = error_value_columns();
  std::vector<py::array_t<double>> values;
  for (std::size_t c = 0; c < measured.size(); ++c) values.emplace_back(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ErrorRow& r = rows[i];
    clip.append(r.clip);
    method.append(r.method);
    joint.append(r.joint);
    kind.append(r.end_site ? "end_site" : "joint");
    keep.mutable_at(i) = r.keep_every;
    frames.mutable_at(i) = static_cast<long long>(r.frames);
    samples.mutable_at(i) = static_cast<long long>(r.samples);
    for (std::size_t c = 0; c < measured.size(); ++c)
      values[c].mutable_at(i) =
          (r.end_site && measured[c].joint_only) || (!r.foot && measured[c].foot_only) ? std::nan("") : r.*measured[c].field;
  }
  py::module_ np = py::module_::import("numpy");
  std::map<std::string, py::object> by_name = {
      {"clip", np.attr("array")(clip, "str")},     {"method", np.attr("array")(method, "str")},
      {"keep_every", keep},                         {"joint", np.attr("array")(joint, "str")},
      {"frames", frames},                           {"samples", samples},
      {"kind", np.attr("array")(kind, "str")}};
  for (std::size_t c = 0; c < measured.size(); ++c) by_name.emplace(measured[c].name, values[c]);
  py::dict out;
  for (const std::string& name : checked(split_csv_line(error_csv_header()))) out[py::str(name)] = by_name.at(name);
  return out;
}

// ---- metrics on arrays ---------------------------------------------------------------------

// (…, 4) arrays of the same shape → the rotation angle between them (radians), (…).
py::array angle_between(const py::handle& a_in, const py::handle& b_in, bool scalar_first) {
  const Doubles a = Doubles::ensure(a_in), b = Doubles::ensure(b_in);
  if (!a || !b || a.ndim() < 1 || a.shape(a.ndim() - 1) != 4 || shape_of(a) != shape_of(b))
    value_error("angle: a and b must be quaternion arrays of the same shape (..., 4)");
  std::vector<py::ssize_t> shape(a.shape(), a.shape() + a.ndim() - 1);
  py::array_t<double> out(shape);
  const auto n = static_cast<std::size_t>(a.size() / 4);
  const double *pa = a.data(), *pb = b.data();
  double* o = out.mutable_data();
  for (std::size_t i = 0; i < n; ++i)
    o[i] = angular_distance(quat_at(pa + 4 * i, scalar_first), quat_at(pb + 4 * i, scalar_first));
  return out;
}

// q = swing · twist about `axis` (3,) in the moving frame, for (…, 4) arrays.
py::tuple swing_twist_split(const py::handle& q_in, const py::handle& axis_in, bool scalar_first) {
  const Doubles q = Doubles::ensure(q_in), axis = Doubles::ensure(axis_in);
  if (!q || q.ndim() < 1 || q.shape(q.ndim() - 1) != 4) value_error("swing_twist: q must have shape (..., 4)");
  if (!axis || axis.ndim() != 1 || axis.shape(0) != 3) value_error("swing_twist: axis must have shape (3,)");
  const Vec3 ax(axis.at(0), axis.at(1), axis.at(2));
  py::array_t<double> swing(shape_of(q)), twist(shape_of(q));
  const auto n = static_cast<std::size_t>(q.size() / 4);
  for (std::size_t i = 0; i < n; ++i) {
    const SwingTwist st = swing_twist(quat_at(q.data() + 4 * i, scalar_first), ax);
    put_quat(st.swing, swing.mutable_data() + 4 * i, scalar_first);
    put_quat(st.twist, twist.mutable_data() + 4 * i, scalar_first);
  }
  return py::make_tuple(swing, twist);
}

}  // namespace
}  // namespace rotinterp

PYBIND11_MODULE(_rotinterp, m) {
  using namespace rotinterp;
  m.doc() = "rotinterp: keyframed 3-D orientations on numpy arrays (see the rotinterp package)";
  m.attr("__version__") = ROTINTERP_VERSION;
  m.attr("default_method") = kDefaultResampleMethod;

  py::class_<Clip>(m, "Clip")
      .def(py::init(&make_clip), py::arg("names"), py::arg("parents"), py::arg("offsets"), py::arg("times"),
           py::arg("rotations"), py::arg("translations") = py::none(), py::arg("frame_time") = py::none(),
           py::arg("unit_scale") = 1.0, py::arg("scalar_first") = false, py::arg("name") = "clip")
      .def_readonly("name", &Clip::name)
      .def_property_readonly("names",
                             [](const Clip& c) {
                               std::vector<std::string> n;
                               for (const Joint& j : c.skeleton.joints) n.push_back(j.name);
                               return n;
                             })
      .def_property_readonly("parents",
                             [](const Clip& c) {
                               py::array_t<long long> p(static_cast<py::ssize_t>(c.skeleton.joints.size()));
                               for (std::size_t j = 0; j < c.skeleton.joints.size(); ++j)
                                 p.mutable_at(j) = c.skeleton.joints[j].parent;
                               return p;
                             })
      .def_property_readonly("offsets",
                             [](const Clip& c) {
                               const std::size_t nj = c.skeleton.joints.size();
                               py::array_t<double> o({nj, std::size_t{3}});
                               for (std::size_t j = 0; j < nj; ++j)
                                 for (int i = 0; i < 3; ++i) o.mutable_at(j, i) = c.skeleton.joints[j].offset[i];
                               return o;
                             })
      .def_property_readonly("times", &clip_times)
      .def_property_readonly("rotations", [](const Clip& c) { return clip_rotations(c, false); })
      .def("rotations_as", &clip_rotations, py::arg("scalar_first"))
      .def_property_readonly("translations", &clip_translations)
      .def("track", &clip_track, py::arg("joint"), py::arg("scalar_first") = false)
      .def_readonly("frame_time", &Clip::frame_time)
      .def_property_readonly("rate", &rate_hz)
      .def_property_readonly("rate_text", &rate_text)
      .def_property_readonly("unit_scale", [](const Clip& c) { return c.unit.metres_per_unit; })
      .def_readonly("source_format", &Clip::source_format)
      .def_property_readonly("frame_count", &Clip::frame_count)
      .def("__repr__", [](const Clip& c) {
        const std::optional<Rate> r = clip_rate(c);
        return "<rotinterp.Clip '" + c.name + "': " + std::to_string(c.skeleton.joints.size()) + " joints, " +
               std::to_string(c.frame_count()) + " frames" + (r ? ", " + r->to_string() + " Hz" : "") + ">";
      });

  py::class_<PyInterpolator>(m, "Interpolator")
      .def("__call__", &PyInterpolator::call, py::arg("t"))
      .def("angular_velocity", &PyInterpolator::angular_velocity, py::arg("t"))
      .def_property_readonly("method", &PyInterpolator::method)
      .def_property_readonly("times", &PyInterpolator::times);

  m.def("methods", &method_list);
  m.def(
      "make_interpolator",
      [](const py::handle& times, const py::handle& quats, const std::string& method, bool scalar_first) {
        return PyInterpolator(times, quats, method, scalar_first);
      },
      py::arg("times"), py::arg("quats"), py::arg("method") = std::string(kDefaultResampleMethod),
      py::arg("scalar_first") = false);
  m.def("interpolate", &interpolate, py::arg("times"), py::arg("quats"), py::arg("new_times"),
        py::arg("method") = std::string(kDefaultResampleMethod), py::arg("scalar_first") = false);
  m.def("read_clip", &read_path, py::arg("path"), py::arg("anim") = py::none());
  m.def("write_clip", &write_path, py::arg("clip"), py::arg("path"), py::arg("bvh_order") = "ZXY");
  m.def("resample", &resample, py::arg("clip"), py::arg("fps") = py::none(), py::arg("keep_every") = py::none(),
        py::arg("method") = std::string(kDefaultResampleMethod),
        py::arg("method_for") = std::map<std::string, std::string>{}, py::arg("translation") = "cubic",
        py::arg("range") = py::none());
  m.def("evaluate", &evaluate, py::arg("inputs"), py::arg("methods") = py::none(),
        py::arg("keep_every") = std::vector<int>{2, 4, 8, 16}, py::arg("subframe") = 0,
        py::arg("shell_distance") = kDefaultShellDistanceMetres);
  m.def("angle", &angle_between, py::arg("a"), py::arg("b"), py::arg("scalar_first") = false);
  m.def("swing_twist", &swing_twist_split, py::arg("q"), py::arg("axis"), py::arg("scalar_first") = false);
}
