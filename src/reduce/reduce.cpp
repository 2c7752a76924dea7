// reduce_clip: the budgets checked and resolved per joint, then the reducer run (reducer.h).
#include "rotinterp/reduce/reduce.h"

#include "reducer.h"

#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace rotinterp {

namespace {

bool valid_budget_value(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

double translation_tolerance(const ReduceBudget& b) {
  return b.shell > 0.0 ? std::min(b.translation, detail::kTranslationShare * b.shell) : b.translation;
}

Result<ReduceResult> reduce_clip(const Clip& clip, const ReduceOptions& o) {
  if (Status s = clip.validate(); !s) return s.failure();
  if (!find_method(o.method)) return make_error(unknown_method_message(o.method));
  const std::size_t n = clip.skeleton.joints.size();
  std::vector<ReduceBudget> budgets(n, o.budget);
  for (const auto& [name, b] : o.budget_for) {
    const int j = clip.skeleton.find(name);
    if (j < 0) return make_error("no joint named '" + name + "' for its budget");
    ReduceBudget& to = budgets[static_cast<std::size_t>(j)];
    if (b.rotation_deg > 0.0) to.rotation_deg = b.rotation_deg;
    if (b.shell > 0.0) to.shell = b.shell;
    if (b.translation > 0.0) to.translation = b.translation;
  }
  for (std::size_t j = 0; j < n; ++j) {
    const ReduceBudget& b = budgets[j];
    const std::string& name = clip.skeleton.joints[j].name;
    if (!valid_budget_value(b.rotation_deg) || !valid_budget_value(b.shell) || !valid_budget_value(b.translation))
      return make_error("joint '" + name + "': a budget is not a finite number ≥ 0");
    if (!(b.rotation_deg > 0.0) && !(b.shell > 0.0)) return make_error("joint '" + name + "' has no rotation or shell budget");
    if (clip.translations[j] && !(b.translation > 0.0))
      return make_error("joint '" + name + "' has a translation track but no translation budget");
    if (b.shell > 0.0 && !(std::isfinite(o.shell_distance) && o.shell_distance > 0.0))
      return make_error("a shell budget needs a shell distance > 0");
  }
  for (ReduceBudget& b : budgets) b.translation = translation_tolerance(b);
  std::optional<LoopCheck> cycle;
  if (o.loop) {
    auto checked = check_loop(clip, o.loop_form);
    if (!checked) return checked.failure();
    if (!o.loop_form && !checked->looks_like_cycle)
      return make_error("--loop: the clip does not look like a cycle: " + loop_check_text(*checked) +
                        " (give --loop closed or --loop open to treat it as one)");
    cycle = std::move(*checked);
  }
  return detail::Reducer(clip, o, std::move(budgets), std::move(cycle)).run();
}

}  // namespace rotinterp
