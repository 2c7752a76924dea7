// rotinterp.Clip: a clip read from a file or built from arrays, and its data as arrays.
#include "common.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/io/files/euler.h"
#include "rotinterp/io/write.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::python {
namespace {

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
               std::optional<double> frame_time, double metres, bool scalar_first, const std::string& name) {
  const std::size_t nj = names.size();
  const Doubles times = times_array(times_in, "times");
  const auto f = static_cast<std::size_t>(times.shape(0));
  const Integers parents = integer_array(parents_in, "parents");
  bool in_scalar_first = scalar_first;  // a scipy Rotation comes scalar-last
  const Doubles offsets = real_array(offsets_in, "offsets");
  const double unit = metres_per_unit_arg(py::float_(metres), "metres_per_unit");
  Doubles rotations = unit_quats(rotations_in, in_scalar_first, "rotations");
  // (F·J, 4), frame-major, as a flat scipy Rotation of every frame's joints holds them.
  if (rotations.ndim() == 2 && static_cast<std::size_t>(rotations.shape(0)) == f * nj && nj > 0)
    rotations = Doubles::ensure(rotations.reshape({static_cast<py::ssize_t>(f), static_cast<py::ssize_t>(nj),
                                                   py::ssize_t{4}}));
  if (parents.ndim() != 1 || static_cast<std::size_t>(parents.shape(0)) != nj)
    value_error("parents must be a 1-D array with one entry per name (" + std::to_string(nj) + ")");
  // Kept in int's range for Skeleton::validate, which refuses the rest (a parent after its joint).
  for (std::size_t j = 0; j < nj; ++j)
    if (parents.at(j) < -1 || parents.at(j) >= static_cast<long long>(nj))
      value_error("parents[" + std::to_string(j) + "] = " + std::to_string(parents.at(j)) +
                  " is neither -1 (a root) nor the index of a joint (0 to " + std::to_string(nj - 1) + ")");
  if (offsets.ndim() != 2 || static_cast<std::size_t>(offsets.shape(0)) != nj || offsets.shape(1) != 3)
    value_error("offsets must have shape (J, 3) = (" + std::to_string(nj) + ", 3)");
  if (rotations.ndim() != 3 || static_cast<std::size_t>(rotations.shape(0)) != f ||
      static_cast<std::size_t>(rotations.shape(1)) != nj || rotations.shape(2) != 4)
    value_error("rotations must have shape (F, J, 4) = (" + std::to_string(f) + ", " + std::to_string(nj) + ", 4), got " +
                shape_text(rotations));
  require_finite(offsets, "offsets");
  Clip c;
  c.name = name;
  c.source_format = "python";
  c.unit = {unit, UnitOrigin::given, "given: Clip(metres_per_unit=)"};
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
    c.rotations[j] = track_of(times.data(), rotations.data(), f, nj, j, in_scalar_first);
    c.rotations[j].make_sign_continuous();
  }
  if (!translations.is_none()) {
    for (const auto& item : translations.cast<py::dict>()) {
      const std::string joint = item.first.cast<std::string>();
      const int j = c.skeleton.find(joint);
      if (j < 0) value_error("translations: no joint '" + joint + "'");
      const Doubles p = real_array(item.second, "translations");
      if (p.ndim() != 2 || static_cast<std::size_t>(p.shape(0)) != f || p.shape(1) != 3)
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
  // Every frame-based call (positions, to_euler, evaluate, resample) makes each joint's
  // frames: refused here, before any of them allocates.
  if (c.frame_time > 0.0)
    require_key_count((c.end_time() - c.start_time()) / c.frame_time + 1.0, nj,
                      "frame_time=" + py::str(py::float_(c.frame_time)).cast<std::string>() + " s over " +
                          py::str(py::float_(c.end_time() - c.start_time())).cast<std::string>() + " s of keys");
  return c;
}


// ---- clips as data: world positions, Euler angles ---------------------------------------

// Frame indices into the clip's frame grid (clip/frames.h): all of them for None,
// else a number or a 1-D array of indices in [0, F), negative ones counting from the
// end as numpy's do.
std::vector<std::size_t> frame_indices(const py::object& frames, std::size_t count) {
  std::vector<std::size_t> out;
  if (frames.is_none()) {
    for (std::size_t k = 0; k < count; ++k) out.push_back(k);
    return out;
  }
  const Integers a = integer_array(frames, "frames");
  if (a.ndim() > 1) value_error("frames must be None, a frame index or a 1-D array of frame indices");
  const auto n = static_cast<long long>(count);
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    const long long k = a.data()[i];
    if (k < -n || k >= n)
      value_error("frame " + std::to_string(k) + " outside the clip's " + std::to_string(count) + " frames");
    out.push_back(static_cast<std::size_t>(k < 0 ? k + n : k));
  }
  return out;
}

// World positions (F, J, 3) in metres at the clip's frames: its motion at each frame
// (dense_clip, as eval and render take it) through forward_kinematics, times the
// clip's metres per unit.
py::array clip_positions(const Clip& c, const py::object& frames_in) {
  DenseClip d;
  {
    py::gil_scoped_release release;
    d = dense_clip(c);
  }
  const std::vector<std::size_t> frames = frame_indices(frames_in, d.grid.size());
  const std::size_t nj = c.skeleton.joints.size();
  py::array_t<double> out({frames.size(), nj, std::size_t{3}});
  double* o = out.mutable_data();
  const double scale = metres_per_unit(c);
  {
    py::gil_scoped_release release;
    std::vector<Quat> rotation(nj);
    std::vector<Vec3> translation(nj);
    WorldPose pose;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      for (std::size_t j = 0; j < nj; ++j) {
        rotation[j] = d.rotation[j][frames[i]];
        translation[j] = d.translation[j][frames[i]];
      }
      forward_kinematics(c.skeleton, rotation, translation, pose);
      for (std::size_t j = 0; j < nj; ++j)
        for (int x = 0; x < 3; ++x) o[3 * (i * nj + j) + static_cast<std::size_t>(x)] = scale * pose.position[j][x];
    }
  }
  return out;
}

// Eval's own world positions (clip units, (F, J, 3)) of the clip's reference: what
// the tests hold positions() against.
py::array eval_world_positions(const Clip& c) {
  ClipEvalOptions o;
  o.methods = {"slerp"};
  const ClipReference r = checked(prepare_reference(c, c.name, o));
  const std::size_t nf = r.world.size(), nj = r.skeleton.joints.size();
  py::array_t<double> out({nf, nj, std::size_t{3}});
  for (std::size_t k = 0; k < nf; ++k)
    for (std::size_t j = 0; j < nj; ++j)
      for (py::ssize_t x = 0; x < 3; ++x) out.mutable_at(k, j, x) = r.world[k].position[j][x];
  return out;
}

// Joint j's Euler order in its file: its BVH rotation channels in file order
// ("ZXY"), else what the BVH writer uses for joints without a layout.
std::string file_euler_order(const Clip& c, std::size_t j) {
  std::string order;
  for (Channel ch : bvh_channels(c, j)) {
    if (ch == Channel::Xrotation) order += 'X';
    if (ch == Channel::Yrotation) order += 'Y';
    if (ch == Channel::Zrotation) order += 'Z';
  }
  return order.size() == 3 ? order : WriteOptions{}.bvh_order;
}

// The principal Euler solution of q: each angle in (−π, π], the middle one in
// [−π/2, π/2] (Tait–Bryan) or [0, π] (proper Euler), as BVH writers give them.
Vec3 principal_euler(const Quat& q, const EulerAxes& axes) {
  Vec3 a = euler_nearest(q, axes, Vec3::Zero());
  const auto wrap = [](double x) { return x - kTwoPi * std::ceil((x - kPi) / kTwoPi); };
  const bool proper = axes[0] == axes[2];
  const double middle = wrap(a[1]);
  if (proper ? middle < 0.0 : std::abs(middle) > 0.5 * kPi)  // the other solution of the pair
    a = Vec3(a[0] + kPi, proper ? -a[1] : kPi - a[1], a[2] + kPi);
  return Vec3(wrap(a[0]), wrap(a[1]), wrap(a[2]));
}

// Local rotations at the clip's frames as Euler angles (F, J, 3): in `order` for
// every joint, or each joint's file order for None. Frame 0 takes the principal
// solution (a BVH file's own numbers, up to round-off), every later frame the
// solution nearest the frame before (euler_nearest): the curves have no ±180° wraps.
py::array clip_euler(const Clip& c, const std::optional<std::string>& order, bool degrees) {
  const std::size_t nj = c.skeleton.joints.size();
  std::vector<EulerAxes> axes(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    const std::string text = order ? *order : file_euler_order(c, j);
    const std::optional<EulerAxes> a = parse_euler_order(text);
    if (!a) value_error("Euler order '" + text + "': three axis letters, as \"ZXY\" (the first outermost)");
    axes[j] = *a;
  }
  const DenseClip d = dense_clip(c);
  const std::size_t nf = d.grid.size();
  py::array_t<double> out({nf, nj, std::size_t{3}});
  double* o = out.mutable_data();
  const double scale = degrees ? 180.0 / kPi : 1.0;
  for (std::size_t j = 0; j < nj; ++j) {
    Vec3 previous;
    for (std::size_t k = 0; k < nf; ++k) {
      previous = k == 0 ? principal_euler(d.rotation[j][k], axes[j])
                        : euler_nearest(d.rotation[j][k], axes[j], previous);
      for (int x = 0; x < 3; ++x) o[3 * (k * nj + j) + static_cast<std::size_t>(x)] = scale * previous[x];
    }
  }
  return out;
}

}  // namespace

void bind_clip(py::module_& m) {
  // The clip's unit (clip/units.h): metres per unit and where that figure came from.
  py::class_<ClipUnit>(m, "ClipUnit")
      .def_readonly("metres_per_unit", &ClipUnit::metres_per_unit)
      .def_property_readonly("origin", [](const ClipUnit& u) { return std::string(unit_origin_name(u.origin)); })
      .def_readonly("reason", &ClipUnit::reason)
      .def_property_readonly("name", [](const ClipUnit& u) { return unit_name(u.metres_per_unit); })
      .def("__repr__", [](const ClipUnit& u) { return "<rotinterp.ClipUnit " + describe_unit(u) + ">"; });
  py::class_<Clip>(m, "Clip")
      .def(py::init(&make_clip), py::arg("names"), py::arg("parents"), py::arg("offsets"), py::arg("times"),
           py::arg("rotations"), py::arg("translations") = py::none(), py::arg("frame_time") = py::none(),
           py::arg("metres_per_unit") = 1.0, py::arg("scalar_first") = false, py::arg("name") = "clip")
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
      .def_readonly("unit", &Clip::unit)
      .def_property_readonly("metres_per_unit", [](const Clip& c) { return metres_per_unit(c); })
      .def_property_readonly("joint_names",
                             [](const Clip& c) {
                               std::vector<std::string> n;
                               for (const Joint& j : c.skeleton.joints) n.push_back(j.name);
                               return n;
                             })
      .def("positions", &clip_positions, py::arg("frames") = py::none())
      .def_property_readonly("euler_orders",
                             [](const Clip& c) {
                               std::vector<std::string> orders;
                               for (std::size_t j = 0; j < c.skeleton.joints.size(); ++j)
                                 orders.push_back(file_euler_order(c, j));
                               return orders;
                             })
      .def_property_readonly("local_rotations", [](const Clip& c) { return clip_euler(c, std::nullopt, false); })
      .def("to_euler", &clip_euler, py::arg("order") = py::none(), py::arg("degrees") = false)
      .def_readonly("source_format", &Clip::source_format)
      .def_property_readonly("frame_count", &Clip::frame_count)
      .def("__repr__", [](const Clip& c) {
        const std::optional<Rate> r = clip_rate(c);
        return "<rotinterp.Clip '" + c.name + "': " + std::to_string(c.skeleton.joints.size()) + " joints, " +
               std::to_string(c.frame_count()) + " frames" + (r ? ", " + r->to_string() + " Hz" : "") + ">";
      });
  m.def("_eval_world_positions", &eval_world_positions, py::arg("clip"));
}

}  // namespace rotinterp::python
