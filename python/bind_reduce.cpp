// rotinterp.reduce: the fewest keys per joint within an error budget, as `rotinterp
// reduce` chooses them (reduce/reduce.h), with the kept keys and the report as data.
#include "common.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/reduce/reduce.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::python {
namespace {

// A budget given in Python: None, or a finite number > 0.
double positive_or_zero(const std::optional<double>& v, const std::string& what) {
  if (!v) return 0.0;
  if (!std::isfinite(*v) || !(*v > 0.0)) value_error(what + " must be a finite number > 0, got " + std::to_string(*v));
  return *v;
}

py::array_t<long long> index_array(const std::vector<std::size_t>& v) {
  py::array_t<long long> a(static_cast<py::ssize_t>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<long long>(v[i]);
  return a;
}

// The same budgets, in the same units, as the command's options: tolerance_deg
// (local rotation, degrees), tolerance_mm (shell and translation, millimetres),
// shell_distance_cm, tolerance_for {joint: {"deg": …, "mm": …}}; neither tolerance:
// 1 mm at 10 cm. metres_per_unit: the clip's unit unless given.
py::dict reduce(const Clip& clip, const std::string& method, const std::optional<double>& tolerance_deg,
                const std::optional<double>& tolerance_mm, const std::optional<double>& shell_distance_cm,
                const py::object& tolerance_for, const std::string& translation,
                const std::optional<double>& unit_in) {
  if (!find_method(method)) value_error("unknown method '" + method + "' (valid: " + method_names() + ")");
  double deg = positive_or_zero(tolerance_deg, "tolerance_deg"), mm = positive_or_zero(tolerance_mm, "tolerance_mm");
  if (shell_distance_cm && !tolerance_mm) value_error("shell_distance_cm needs tolerance_mm");
  const double shell_cm = shell_distance_cm ? positive_or_zero(shell_distance_cm, "shell_distance_cm")
                                            : kDefaultReduceShellDistanceCm;
  if (deg == 0.0 && mm == 0.0) mm = kDefaultReduceToleranceMm;
  const double unit = unit_in ? positive_or_zero(unit_in, "metres_per_unit") : metres_per_unit(clip);
  const auto units = [unit](double millimetres) { return millimetres / 1000.0 / unit; };
  ReduceOptions opt;
  opt.method = method;
  opt.translation = checked(parse_translation_interp(translation));
  opt.budget.rotation_deg = deg;
  opt.budget.shell = units(mm);
  opt.budget.translation = units(mm > 0.0 ? mm : kDefaultReduceToleranceMm);
  opt.shell_distance = units(shell_cm * 10.0);
  if (!tolerance_for.is_none()) {
    for (const auto& item : tolerance_for.cast<py::dict>()) {
      const std::string joint = py::str(item.first).cast<std::string>();
      if (clip.skeleton.find(joint) < 0) value_error("tolerance_for: clip '" + clip.name + "' has no joint '" + joint + "'");
      const auto b = item.second.cast<py::dict>();
      const double jd = positive_or_zero(b.contains("deg") ? b["deg"].cast<std::optional<double>>() : std::nullopt,
                                         "tolerance_for['" + joint + "']['deg']");
      const double jm = positive_or_zero(b.contains("mm") ? b["mm"].cast<std::optional<double>>() : std::nullopt,
                                         "tolerance_for['" + joint + "']['mm']");
      if (jd == 0.0 && jm == 0.0) value_error("tolerance_for['" + joint + "'] needs \"deg\" or \"mm\"");
      if (jm > 0.0 && mm == 0.0) value_error("tolerance_for['" + joint + "']: a mm budget needs tolerance_mm");
      opt.budget_for.emplace_back(joint, ReduceBudget{jd, units(jm), units(jm)});
    }
  }
  Result<ReduceResult> r = make_error("");
  {
    py::gil_scoped_release release;
    r = reduce_clip(clip, opt);
  }
  ReduceResult result = checked(std::move(r));
  // The report, in the units of the command's keys file: degrees and millimetres.
  const double to_mm = unit * 1000.0;
  py::list joints;
  double worst_deg = 0.0, worst_mm = 0.0;
  for (std::size_t j = 0; j < result.joints.size(); ++j) {
    const ReducedJoint& rj = result.joints[j];
    py::dict d;
    d["name"] = clip.skeleton.joints[j].name;
    d["rotation_frames"] = index_array(rj.rotation_frames);
    d["translation_frames"] = clip.translations[j] ? py::object(index_array(rj.translation_frames)) : py::none();
    d["max_rotation_error_deg"] = rj.max_rotation_error * 180.0 / kPi;
    d["max_shell_error_mm"] = opt.budget.shell > 0.0 ? py::object(py::float_(rj.max_shell_error * to_mm)) : py::none();
    d["max_translation_error_mm"] =
        clip.translations[j] ? py::object(py::float_(rj.max_translation_error * to_mm)) : py::none();
    worst_deg = std::max(worst_deg, rj.max_rotation_error * 180.0 / kPi);
    worst_mm = std::max(worst_mm, rj.max_shell_error * to_mm);
    joints.append(d);
  }
  py::dict out;
  out["method"] = method;
  out["frames"] = result.grid.size();
  out["source_keys"] = result.source_keys;
  out["kept_keys"] = result.kept_keys;
  out["metres_per_unit"] = unit;
  out["max_rotation_error_deg"] = worst_deg;
  out["max_shell_error_mm"] = opt.budget.shell > 0.0 ? py::object(py::float_(worst_mm)) : py::none();
  out["joints"] = joints;
  out["clip"] = std::move(result.reduced);
  return out;
}

}  // namespace

void bind_reduce(py::module_& m) {
  m.def("reduce", &reduce, py::arg("clip"), py::arg("method") = "slerp", py::arg("tolerance_deg") = py::none(),
        py::arg("tolerance_mm") = py::none(), py::arg("shell_distance_cm") = py::none(),
        py::arg("tolerance_for") = py::none(), py::arg("translation") = "cubic",
        py::arg("metres_per_unit") = py::none());
}

}  // namespace rotinterp::python
