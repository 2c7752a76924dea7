// rotinterp methods [--json]: the registered interpolators.
#include "common.h"
#include "rotinterp/interp/interpolator.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <memory>

namespace rotinterp::cli {

void add_methods_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("methods", "List the interpolation methods: continuity and coordinate invariance");
  auto json = std::make_shared<bool>(false);
  add_json_option(*sub, *json);
  sub->callback([json, &exit_code] {
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const MethodInfo& m : methods())
        out.push_back({{"name", m.name},
                       {"description", m.description},
                       {"continuity", "C" + std::to_string(m.continuity)},
                       {"coordinate_invariant", m.coordinate_invariant},
                       {"exact_on_constant_velocity", m.exact_on_constant_velocity},
                       {"preserves_holds", m.preserves_holds}});
      fmt::print("{}\n", out.dump(2));
    } else {
      std::size_t width = 6;  // "method"
      for (const MethodInfo& m : methods()) width = std::max(width, m.name.size());
      fmt::print("{:<{}} {:<10} {:<10} {}\n", "method", width, "continuity", "invariant", "description");
      for (const MethodInfo& m : methods())
        fmt::print("{:<{}} C{:<9} {:<10} {}\n", m.name, width, m.continuity, m.coordinate_invariant ? "yes" : "no",
                   m.description);
    }
    exit_code = kExitOk;
  });
}

}  // namespace rotinterp::cli
