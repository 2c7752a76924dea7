// rotinterp methods [--json]: the registered interpolators, and `source`, the file's own curves.
#include "common.h"
#include "options.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/source_motion.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <memory>

namespace rotinterp::cli {

namespace {

// `source` is no interpolator of keys (interp/interpolator.h): it replays the motion
// a file stores (io/source_motion.h), so the properties of a curve through keys do not apply.
std::string source_description() {
  return std::string("the file's own motion: FBX curves as the DCC evaluates them, glTF animation samplers as the "
                     "glTF spec does, BVH frames; runs in ") + kSourceRunsIn;
}
// Where the interpolators run: every command that takes -m.
constexpr const char* kMethodsRunIn = "resample, eval, reduce, render";

}  // namespace

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
                       {"preserves_holds", m.preserves_holds},
                       {"replays_file_curves", false},
                       {"runs_in", kMethodsRunIn}});
      out.push_back({{"name", kSourceMethodName},
                     {"description", source_description()},
                     {"continuity", "as keyed"},
                     {"coordinate_invariant", nullptr},
                     {"exact_on_constant_velocity", nullptr},
                     {"preserves_holds", nullptr},
                     {"replays_file_curves", true},
                     {"runs_in", kSourceRunsIn}});
      fmt::print("{}\n", json_text(out, 2));
    } else {
      std::size_t width = 6;  // "method"
      for (const MethodInfo& m : methods()) width = std::max(width, m.name.size());
      fmt::print("{:<{}} {:<10} {:<10} {}\n", "method", width, "continuity", "invariant", "description");
      for (const MethodInfo& m : methods())
        fmt::print("{:<{}} C{:<9} {:<10} {}\n", m.name, width, m.continuity, m.coordinate_invariant ? "yes" : "no",
                   m.description);
      fmt::print("{:<{}} {:<10} {:<10} {}\n", kSourceMethodName, width, "as keyed", "-", source_description());
      fmt::print("\nEvery method but source runs in {} (-m).\n", kMethodsRunIn);
    }
    exit_code = kExitOk;
  });
}

}  // namespace rotinterp::cli
