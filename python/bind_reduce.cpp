// rotinterp.reduce: the fewest keys per joint within an error budget, as `rotinterp
// reduce` chooses them (reduce/reduce.h), with the budgets in the command's forms and
// the kept keys and the report as data.
#include "common.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/clip/units.h"
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

py::array_t<long long> index_array(const std::vector<std::size_t>& v) {
  py::array_t<long long> a(static_cast<py::ssize_t>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<long long>(v[i]);
  return a;
}

// A budget in the forms `rotinterp reduce --tolerance` takes (reduce.h
// add_budget_items): one string "0.5deg,1mm", or a list of items.
BudgetText parse_budget(const py::object& items, const std::string& what) {
  BudgetText b;
  std::string list;
  if (py::isinstance<py::str>(items)) {
    list = items.cast<std::string>();
  } else {
    for (const auto& item : items) list += (list.empty() ? "" : ",") + py::str(item).cast<std::string>();
  }
  if (Status s = add_budget_items(what, list, b); !s) value_error(s.error());
  return b;
}

// The command's budgets and defaults: tolerance (default 1 mm), shell_distance (a
// length, or a number of metres; default 10 cm), tolerance_for {joint: budget}.
// metres_per_unit: the clip's unit (clip.unit) unless given.
py::dict reduce(const Clip& clip, const std::string& method, const py::object& tolerance,
                const py::object& shell_distance, const py::object& tolerance_for, const std::string& translation,
                const std::optional<double>& unit_in, const py::object& loop) {
  const std::string method_name = method_of(method).name;
  BudgetText budget = tolerance.is_none() ? BudgetText{} : parse_budget(tolerance, "tolerance");
  const double shell_m = shell_distance.is_none() ? kDefaultReduceShellDistanceCm / 100.0
                                                 : checked(parse_length(py::str(shell_distance).cast<std::string>()));
  if (budget.deg == 0.0 && budget.mm == 0.0) budget.mm = kDefaultReduceToleranceMm;
  const double deg = budget.deg, mm = budget.mm;
  const double unit = unit_in ? metres_per_unit_arg(py::float_(*unit_in), "metres_per_unit") : metres_per_unit(clip);
  const auto units = [unit](double millimetres) { return millimetres / 1000.0 / unit; };
  ReduceOptions opt;
  opt.method = method_name;
  opt.translation = checked(parse_translation_interp(translation));
  opt.budget.rotation_deg = deg;
  opt.budget.shell = units(mm);
  opt.budget.translation = units(mm > 0.0 ? mm : kDefaultReduceToleranceMm);
  opt.shell_distance = shell_m / unit;
  if (!tolerance_for.is_none()) {
    for (const auto& item : tolerance_for.cast<py::dict>()) {
      const std::string joint = py::str(item.first).cast<std::string>();
      if (clip.skeleton.find(joint) < 0) value_error("tolerance_for: clip '" + clip.name + "' has no joint '" + joint + "'");
      const BudgetText b = parse_budget(py::reinterpret_borrow<py::object>(item.second), "tolerance_for['" + joint + "']");
      if (b.mm > 0.0 && mm == 0.0) value_error("tolerance_for['" + joint + "']: a length budget needs a length tolerance");
      opt.budget_for.emplace_back(joint, ReduceBudget{b.deg, units(b.mm), units(b.mm)});
    }
  }
  // loop: None/False off; True or "auto" detects the form; "closed" or "open" forces it (reduce --loop).
  if (py::isinstance<py::bool_>(loop)) {
    opt.loop = loop.cast<bool>();
  } else if (!loop.is_none()) {
    opt.loop = true;
    opt.loop_form = checked(parse_loop_form(loop.cast<std::string>()));
  }
  Result<ReduceResult> r = make_error("");
  {
    py::gil_scoped_release release;
    r = reduce_clip(clip, opt);
  }
  ReduceResult result = checked(std::move(r));
  // The report, in the units and the arithmetic of the command's keys file (error ·
  // metres per unit · 1000): degrees and millimetres, equal to the last bit.
  const auto to_mm = [unit](double clip_units) { return clip_units * unit * 1000.0; };
  py::list joints;
  double worst_deg = 0.0, worst_mm = 0.0;
  for (std::size_t j = 0; j < result.joints.size(); ++j) {
    const ReducedJoint& rj = result.joints[j];
    py::dict d;
    d["name"] = clip.skeleton.joints[j].name;
    d["rotation_frames"] = index_array(rj.rotation_frames);
    d["translation_frames"] = clip.translations[j] ? py::object(index_array(rj.translation_frames)) : py::none();
    d["max_rotation_error_deg"] = rj.max_rotation_error * 180.0 / kPi;
    d["looped"] = rj.looped;
    d["max_shell_error_mm"] = opt.budget.shell > 0.0 ? py::object(py::float_(to_mm(rj.max_shell_error))) : py::none();
    d["max_translation_error_mm"] =
        clip.translations[j] ? py::object(py::float_(to_mm(rj.max_translation_error))) : py::none();
    worst_deg = std::max(worst_deg, rj.max_rotation_error * 180.0 / kPi);
    worst_mm = std::max(worst_mm, to_mm(rj.max_shell_error));
    joints.append(d);
  }
  py::dict out;
  out["method"] = opt.method;
  out["frames"] = result.grid.size();
  out["source_keys"] = result.source_keys;
  out["kept_keys"] = result.kept_keys;
  out["metres_per_unit"] = unit;
  out["max_rotation_error_deg"] = worst_deg;
  out["max_shell_error_mm"] = opt.budget.shell > 0.0 ? py::object(py::float_(worst_mm)) : py::none();
  out["joints"] = joints;
  out["loop"] = result.cycle ? py::object(py::str(loop_form_name(result.cycle->form))) : py::none();
  out["clip"] = std::move(result.reduced);
  return out;
}

}  // namespace

void bind_reduce(py::module_& m) {
  m.def("reduce", &reduce, py::arg("clip"), py::arg("method") = "slerp", py::arg("tolerance") = py::none(),
        py::arg("shell_distance") = py::none(), py::arg("tolerance_for") = py::none(), py::arg("translation") = "cubic",
        py::arg("metres_per_unit") = py::none(), py::arg("loop") = py::none());
}

}  // namespace rotinterp::python
