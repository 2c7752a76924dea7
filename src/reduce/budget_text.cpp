// add_budget_items: reduce's budget as users write it (one rule for the CLI and Python).
#include "rotinterp/clip/units.h"
#include "rotinterp/reduce/reduce.h"

namespace rotinterp {

Status add_budget_items(const std::string& what, const std::string& list, BudgetText& b) {
  bool any = false;
  for (std::size_t from = 0; from <= list.size();) {
    const std::size_t comma = std::min(list.find(',', from), list.size());
    const std::string part = list.substr(from, comma - from);
    from = comma + 1;
    if (part.empty()) continue;
    any = true;
    const bool angle = part.size() > 3 && (part.compare(part.size() - 3, 3, "deg") == 0 ||
                                           part.compare(part.size() - 3, 3, "rad") == 0);
    if (angle) {
      auto v = parse_angle_deg(part);
      if (!v) return v.failure(what + ": ");
      b.deg = *v;
      continue;
    }
    if (part.find_first_not_of("0123456789.+-eE") == std::string::npos)
      return make_error(what + " '" + part + "' needs a unit: an angle (0.5deg) or a length (1mm)");
    auto v = parse_length(part);
    if (!v) return make_error(what + ": " + v.error() + "; or an angle (0.5deg)");
    b.mm = *v * 1000.0;
  }
  if (!any) return make_error(what + " '" + list + "' gives no budget (e.g. 0.5deg,1mm)");
  return Ok{};
}

}  // namespace rotinterp
