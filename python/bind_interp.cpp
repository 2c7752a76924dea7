// Interpolation on arrays: interpolate, make_interpolator (Interpolator), methods, and
// the metrics angle and swing_twist.
#include "common.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/key_arrays.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::python {
namespace {

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

// quats (K, 4) or (K, J, 4) against times (K,): the joint count, 1 for a single track
// (`single`), and 0 for J = 0: an empty (N, 0, 4) result.
std::size_t joints_of(const py::array& q, std::size_t k, bool& single) {
  if (q.ndim() >= 1 && q.shape(0) == 0 && k == 0)
    value_error("times and quats are empty (quats of shape " + shape_text(q) + "): a track needs at least one key");
  single = q.ndim() == 2 && q.shape(1) == 4;
  const bool many = q.ndim() == 3 && q.shape(2) == 4;
  if (!single && !many) value_error("quats must have shape (K, 4) or (K, J, 4), got " + shape_text(q));
  if (static_cast<std::size_t>(q.shape(0)) != k)
    value_error("quats has " + std::to_string(q.shape(0)) + " keys but times has " + std::to_string(k));
  return single ? 1 : static_cast<std::size_t>(q.shape(1));
}

py::array interpolate(const py::handle& times_in, const py::handle& quats_in, const py::handle& new_times_in,
                      const std::string& method, bool scalar_first, const std::string& extrapolate) {
  const Doubles times = times_array(times_in, "times");
  const Extrapolate ends = extrapolate_of(extrapolate);
  const double first = times.size() ? times.data()[0] : 0.0, last = times.size() ? times.data()[times.size() - 1] : 0.0;
  const Doubles new_times = sample_times(new_times_in, "new_times", ends, first, last);
  bool in_scalar_first = scalar_first;  // a scipy Rotation comes scalar-last
  // C-contiguous float32 keys (glTF, PyTorch) are read as they are, like float64: no
  // converted copy. Anything else comes through quat_array.
  using Floats = py::array_t<float, py::array::c_style>;
  const bool floats = !py::hasattr(quats_in, "as_quat") && Floats::check_(quats_in);
  py::array quats;
  if (floats) {
    quats = py::reinterpret_borrow<py::array>(quats_in);
    require_quat_shape(quats, "quats");
    require_key_count(static_cast<double>(quats.size() / 4), 1, "quats");
  } else {
    quats = quat_array(quats_in, in_scalar_first, "quats");
  }
  const auto k = static_cast<std::size_t>(times.shape(0));
  std::size_t joints = 0;
  bool single = false;
  try {
    joints = joints_of(quats, k, single);
    require_continuable(ends, method_of(method));
  } catch (const py::value_error&) {
    refuse_bad_quats(Doubles::ensure(quats), "quats");  // a bad quaternion is named first, whatever else is wrong
    throw;
  }
  const auto n = static_cast<std::size_t>(new_times.size());
  require_key_count(static_cast<double>(n), joints, "new_times");
  std::vector<py::ssize_t> shape;  // a number gives one sample's shape: (4,) or (J, 4)
  if (new_times.ndim() == 1) shape.push_back(static_cast<py::ssize_t>(n));
  if (!single) shape.push_back(static_cast<py::ssize_t>(joints));
  shape.push_back(4);
  py::array_t<double> out(shape);
  const KeyArraysCurve curve{method_of(method).name, ends == Extrapolate::at_end_velocity, scalar_first};
  Status s = Ok{};
  {
    py::gil_scoped_release release;
    s = floats ? interpolate_key_arrays(
                     KeyArrays<float>{times.data(), static_cast<const float*>(quats.data()), k, joints, in_scalar_first},
                     new_times.data(), n, curve, out.mutable_data())
               : interpolate_key_arrays(
                     KeyArrays<double>{times.data(), static_cast<const double*>(quats.data()), k, joints, in_scalar_first},
                     new_times.data(), n, curve, out.mutable_data());
  }
  // A bad quaternion anywhere is named (by numpy's index) before a joint's error, as
  // when all keys were made unit before any joint was built.
  if (!s) {
    refuse_bad_quats(Doubles::ensure(quats), "quats");
    value_error(s.error());
  }
  return out;
}

// One track's interpolator, callable on times.
class PyInterpolator {
 public:
  PyInterpolator(const py::handle& times_in, const py::handle& quats_in, const std::string& method, bool scalar_first,
                 const std::string& extrapolate)
      : method_(method_of(method).name), scalar_first_(scalar_first), extrapolate_(extrapolate_of(extrapolate)) {
    require_continuable(extrapolate_, *find_method(method_));
    const Doubles times = times_array(times_in, "times");
    bool in_scalar_first = scalar_first;  // a scipy Rotation comes scalar-last
    const Doubles quats = unit_quats(quats_in, in_scalar_first, "quats");
    const auto k = static_cast<std::size_t>(times.shape(0));
    bool single = false;
    joints_of(quats, k, single);
    if (!single) value_error("make_interpolator takes one track: quats of shape (K, 4)");
    track_ = track_of(times.data(), quats.data(), k, 1, 0, in_scalar_first);
    curve_ = checked(make_interpolator(method_, track_));
    if (extrapolate_ == Extrapolate::at_end_velocity)
      curve_ = continue_at_end_velocity(std::move(curve_), track_.times.front(), track_.times.back());
  }

  // Orientation(s) at t: (4,) for a number, (N, 4) for an array.
  py::object call(const py::handle& t) const {
    return apply(t, 4, [this](const double* x, std::size_t n, double* o) {
      std::vector<Quat> q(n);
      curve_->evaluate(x, n, q.data());
      for (std::size_t i = 0; i < n; ++i) put_quat(q[i], o + 4 * i, scalar_first_);
    });
  }
  // Angular velocity (rad/s) and acceleration (rad/s²), (3,) or (N, 3), in the fixed
  // frame or the body frame (scipy's RotationSpline(t, 1) and (t, 2)): the body
  // vector is q(t)⁻¹·(fixed vector) for both, as the frame's turning adds ω × ω = 0
  // to the acceleration.
  py::object angular_velocity(const py::handle& t, const std::string& frame) const {
    return derivative(t, frame, &Interpolator::angular_velocity);
  }
  py::object angular_acceleration(const py::handle& t, const std::string& frame) const {
    return derivative(t, frame, &Interpolator::angular_acceleration);
  }
  const std::string& method() const { return method_; }
  py::array times() const { return py::array_t<double>(track_.times.size(), track_.times.data()); }

 private:
  py::object derivative(const py::handle& t, const std::string& frame, Vec3 (Interpolator::*of)(double) const) const {
    if (frame != "fixed" && frame != "body") value_error("frame must be \"fixed\" or \"body\", got \"" + frame + "\"");
    const bool body = frame == "body";
    return apply(t, 3, [this, body, of](const double* x, std::size_t n, double* o) {
      for (std::size_t i = 0; i < n; ++i) {
        Vec3 v = (curve_.get()->*of)(x[i]);
        if (body) v = curve_->evaluate(x[i]).conjugate() * v;
        o[3 * i] = v.x(), o[3 * i + 1] = v.y(), o[3 * i + 2] = v.z();
      }
    });
  }

  template <class Fill>
  py::object apply(const py::handle& t, py::ssize_t width, Fill fill) const {
    const Doubles x = sample_times(t, "t", extrapolate_, track_.times.front(), track_.times.back());
    const bool scalar = x.ndim() == 0;  // a number of any type, numpy's float32 included
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
  Extrapolate extrapolate_;
  RotationTrack track_;
  std::unique_ptr<Interpolator> curve_;
};


// ---- metrics on arrays ---------------------------------------------------------------------

// (…, 4) arrays of the same shape → the rotation angle between them (radians), (…).
py::array angle_between(const py::handle& a_in, const py::handle& b_in, bool scalar_first) {
  bool a_first = scalar_first, b_first = scalar_first;
  const Doubles a = unit_quats(a_in, a_first, "a"), b = unit_quats(b_in, b_first, "b");
  if (shape_of(a) != shape_of(b))
    value_error("angle: a and b must be quaternion arrays of the same shape (..., 4), got " + shape_text(a) + " and " +
                shape_text(b));
  std::vector<py::ssize_t> shape(a.shape(), a.shape() + a.ndim() - 1);
  py::array_t<double> out(shape);
  const auto n = static_cast<std::size_t>(a.size() / 4);
  const double *pa = a.data(), *pb = b.data();
  double* o = out.mutable_data();
  for (std::size_t i = 0; i < n; ++i)
    o[i] = angular_distance(quat_at(pa + 4 * i, a_first), quat_at(pb + 4 * i, b_first));
  return out;
}

// q = swing · twist about `axis` (3,) in the moving frame, for (…, 4) arrays.
py::tuple swing_twist_split(const py::handle& q_in, const py::handle& axis_in, bool scalar_first) {
  bool q_first = scalar_first;
  const Doubles q = unit_quats(q_in, q_first, "q"), axis = real_array(axis_in, "axis");
  if (axis.ndim() != 1 || axis.shape(0) != 3) value_error("swing_twist: axis must have shape (3,)");
  Vec3 ax(axis.at(0), axis.at(1), axis.at(2));
  if (!ax.allFinite() || ax.cwiseAbs().maxCoeff() == 0.0)  // a twist needs a direction
    value_error("swing_twist: axis must be a finite non-zero vector, got " +
                py::str(py::reinterpret_borrow<py::object>(axis_in)).cast<std::string>());
  ax /= ax.cwiseAbs().maxCoeff();  // no underflow in its norm (an axis of 1e-200)
  py::array_t<double> swing(shape_of(q)), twist(shape_of(q));
  const auto n = static_cast<std::size_t>(q.size() / 4);
  for (std::size_t i = 0; i < n; ++i) {
    const SwingTwist st = swing_twist(quat_at(q.data() + 4 * i, q_first), ax);
    put_quat(st.swing, swing.mutable_data() + 4 * i, scalar_first);
    put_quat(st.twist, twist.mutable_data() + 4 * i, scalar_first);
  }
  return py::make_tuple(swing, twist);
}

}  // namespace

void bind_interp(py::module_& m) {
  py::class_<PyInterpolator>(m, "Interpolator")
      .def("__call__", &PyInterpolator::call, py::arg("t"))
      .def(
          "__call__",  // scipy's RotationSpline(t, order): the derivatives have their own names here
          [](const PyInterpolator&, const py::handle&, const py::handle&) -> py::object {
            throw py::type_error(
                "an Interpolator takes only t: for scipy's RotationSpline(t, 1) and (t, 2) call "
                "f.angular_velocity(t, frame=\"body\") and f.angular_acceleration(t, frame=\"body\")");
          },
          py::arg("t"), py::arg("order"))
      .def("angular_velocity", &PyInterpolator::angular_velocity, py::arg("t"), py::arg("frame") = "fixed")
      .def("angular_acceleration", &PyInterpolator::angular_acceleration, py::arg("t"), py::arg("frame") = "fixed")
      .def_property_readonly("method", &PyInterpolator::method)
      .def_property_readonly("times", &PyInterpolator::times);

  m.def("methods", &method_list);
  m.def(
      "make_interpolator",
      [](const py::handle& times, const py::handle& quats, const std::string& method, bool scalar_first,
         const std::string& extrapolate) { return PyInterpolator(times, quats, method, scalar_first, extrapolate); },
      py::arg("times"), py::arg("quats"), py::arg("method") = std::string(kDefaultResampleMethod),
      py::arg("scalar_first") = false, py::arg("extrapolate") = "clamp");
  m.def("interpolate", &interpolate, py::arg("times"), py::arg("quats"), py::arg("new_times"),
        py::arg("method") = std::string(kDefaultResampleMethod), py::arg("scalar_first") = false,
        py::arg("extrapolate") = "clamp");
  m.def("angle", &angle_between, py::arg("a"), py::arg("b"), py::arg("scalar_first") = false);
  m.def("swing_twist", &swing_twist_split, py::arg("q"), py::arg("axis"), py::arg("scalar_first") = false);
}

}  // namespace rotinterp::python
