// rotinterp.Clip: a clip read from a file or built from arrays, and its data as arrays.
#include "common.h"
#include "rotinterp/clip/frames.h"

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
  c.unit_scale = unit_scale;
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


}  // namespace

void bind_clip(py::module_& m) {
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
      .def_readonly("unit_scale", &Clip::unit_scale)
      .def_readonly("source_format", &Clip::source_format)
      .def_property_readonly("frame_count", &Clip::frame_count)
      .def("__repr__", [](const Clip& c) {
        const std::optional<Rate> r = clip_rate(c);
        return "<rotinterp.Clip '" + c.name + "': " + std::to_string(c.skeleton.joints.size()) + " joints, " +
               std::to_string(c.frame_count()) + " frames" + (r ? ", " + r->to_string() + " Hz" : "") + ">";
      });
}

}  // namespace rotinterp::python
