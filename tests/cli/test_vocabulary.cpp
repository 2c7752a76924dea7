// One vocabulary (STYLE rule 15, issue 28): walks every subcommand's options in the
// CLI::App the tool builds and fails when one idea goes by two names, when an idea
// is a flag in one command and takes a value in another, or when an option that
// takes a value does not state its default in --help.
#include "common.h"
#include "support/run_cli.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace rotinterp::cli {
namespace {

using test::run_cli;

// An idea every command names alike: its names, and names it must not go by (the
// spellings that grew in one command or another, and the obvious alternatives).
struct Idea {
  std::string idea;
  std::set<std::string> names;     // every option of this idea carries all of them
  std::set<std::string> synonyms;  // no option carries any of them
  bool flag;                       // takes no value
};

const std::vector<Idea>& ideas() {
  static const std::vector<Idea> all = {
      {"output", {"-o", "--output"}, {"--out", "--outdir", "--out-dir", "--output-dir", "--dest"}, false},
      {"method", {"-m", "--method", "--methods"}, {"--interp", "--interpolator", "--interpolators"}, false},
      {"fps", {"--fps"}, {"--rate", "--hz", "--frame-rate", "--framerate"}, false},
      {"keep-every", {"--keep-every"}, {"--keep", "--every", "--step", "--stride", "--decimate"}, false},
      {"range", {"--range"}, {"--time-range", "--cut", "--interval"}, false},
      {"anim", {"--anim"}, {"--animation", "--take", "--takes"}, false},
      {"jobs", {"-j", "--jobs"}, {"--threads", "--workers", "--parallel"}, false},
      {"quiet", {"-q", "--quiet"}, {"--silent", "--no-progress"}, true},
      {"json", {"--json"}, {"--as-json"}, true},
  };
  return all;
}

bool is_flag(const CLI::Option& o) { return o.get_expected_max() == 0; }

std::set<std::string> names_of(const CLI::Option& o) {
  std::set<std::string> names;
  for (const std::string& s : o.get_snames()) names.insert("-" + s);
  for (const std::string& l : o.get_lnames()) names.insert("--" + l);
  return names;
}

std::string joined(const std::set<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

// One line per problem, "render: …".
std::vector<std::string> vocabulary_problems(CLI::App& app) {
  std::vector<std::string> problems;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    const std::string cmd = sub->get_name();
    std::map<std::string, int> options_of_idea;
    for (const CLI::Option* o : sub->get_options()) {
      const std::set<std::string> names = names_of(*o);
      for (const Idea& idea : ideas()) {
        bool ours = false;
        for (const std::string& n : names) ours = ours || idea.names.count(n) || idea.synonyms.count(n);
        if (!ours) continue;
        ++options_of_idea[idea.idea];
        for (const std::string& n : idea.names)
          if (!names.count(n)) problems.push_back(cmd + ": " + joined(names) + " lacks " + n + " (" + idea.idea + ")");
        for (const std::string& n : names)
          if (idea.synonyms.count(n))
            problems.push_back(cmd + ": " + n + " is another name for " + joined(idea.names));
        if (is_flag(*o) != idea.flag)
          problems.push_back(cmd + ": " + joined(names) + (idea.flag ? " takes a value" : " is a flag") +
                             "; elsewhere it is " + (idea.flag ? "a flag" : "an option with a value"));
      }
    }
    for (const auto& [idea, count] : options_of_idea)
      if (count > 1) problems.push_back(cmd + ": " + std::to_string(count) + " options mean " + idea);
  }
  return problems;
}

// Options that take a value and are neither required nor positional: --help states
// their default, by CLI11's [default] or in words ("default …").
std::vector<std::string> unstated_defaults(CLI::App& app) {
  std::vector<std::string> problems;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    for (const CLI::Option* o : sub->get_options()) {
      if (is_flag(*o) || o->get_required() || !o->nonpositional()) continue;
      std::string help = o->get_description();
      for (char& c : help) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (o->get_default_str().empty() && help.find("default") == std::string::npos)
        problems.push_back(sub->get_name() + ": " + joined(names_of(*o)) + " does not state its default");
    }
  }
  return problems;
}

std::string lines(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& l : v) s += l + "\n";
  return s;
}

TEST(Vocabulary, EveryIdeaHasOneNameAndOneKindInEveryCommand) {
  CLI::App app;
  int exit_code = 0;
  add_commands(app, exit_code);
  EXPECT_GE(app.get_subcommands([](CLI::App*) { return true; }).size(), 6u);
  const auto problems = vocabulary_problems(app);
  EXPECT_TRUE(problems.empty()) << lines(problems);
}

TEST(Vocabulary, TheCheckFindsAnIdeaUnderTwoNames) {
  // What issue 28 found: render's --out beside resample's --output, --methods and
  // --method as two options, a --jobs that is a flag.
  CLI::App app;
  std::string s;
  bool b = false;
  CLI::App* render = app.add_subcommand("render");
  render->add_option("-o,--out", s);
  render->add_option("--methods", s);
  render->add_option("--method", s);
  app.add_subcommand("eval")->add_flag("-j,--jobs", b);
  const std::string found = lines(vocabulary_problems(app));
  EXPECT_NE(found.find("render: --out is another name for --output,-o"), std::string::npos) << found;
  EXPECT_NE(found.find("render: --out,-o lacks --output"), std::string::npos) << found;
  EXPECT_NE(found.find("render: 2 options mean method"), std::string::npos) << found;
  EXPECT_NE(found.find("render: --methods lacks -m"), std::string::npos) << found;
  EXPECT_NE(found.find("eval: --jobs,-j is a flag"), std::string::npos) << found;
}

TEST(Vocabulary, EveryOptionWithAValueStatesItsDefaultInHelp) {
  CLI::App app;
  int exit_code = 0;
  add_commands(app, exit_code);
  const auto problems = unstated_defaults(app);
  EXPECT_TRUE(problems.empty()) << lines(problems);
  CLI::App bare;
  std::string s;
  bare.add_subcommand("x")->add_option("--size", s, "Image size");
  EXPECT_EQ(unstated_defaults(bare).size(), 1u) << "the check can fail";
}

// One unit per kind of quantity: every option that takes a length says a bare number
// is metres, and one that takes a speed says m/s, in every command (clip/units.h).
std::vector<std::string> unit_problems(CLI::App& app) {
  static const std::set<std::string> kLengths = {"--shell-distance", "--floor", "--contact-height"};
  std::vector<std::string> problems;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for (const CLI::Option* o : sub->get_options()) {
      const std::string name = o->get_name(false, true);
      const std::string help = o->get_description();
      const bool length = kLengths.count(name) > 0, speed = name == "--contact-speed";
      if (length && help.find("a bare number is metres") == std::string::npos)
        problems.push_back(sub->get_name() + ": " + name + " does not take lengths in metres");
      if (speed && help.find("a bare number is m/s") == std::string::npos)
        problems.push_back(sub->get_name() + ": " + name + " does not take speeds in m/s");
      if (name.find("-mm") != std::string::npos || name.find("-cm") != std::string::npos ||
          name.find("-deg") != std::string::npos || name.find("-scale") != std::string::npos)
        problems.push_back(sub->get_name() + ": " + name + " names a unit; the value takes it (1mm, 0.5deg)");
    }
  return problems;
}

TEST(Vocabulary, EveryQuantityHasOneUnitInEveryCommand) {
  CLI::App app;
  int exit_code = 0;
  add_commands(app, exit_code);
  EXPECT_TRUE(unit_problems(app).empty()) << lines(unit_problems(app));
  CLI::App bad;
  std::string s;
  bad.add_subcommand("reduce")->add_option("--shell-distance", s, "centimetres");
  bad.add_subcommand("eval")->add_option("--tolerance-mm", s, "millimetres");
  EXPECT_EQ(unit_problems(bad).size(), 2u) << "the check can fail";
}

TEST(Vocabulary, UsageErrorsNameTheSubcommandsHelp) {
  const std::string walk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";
  // A parse error (CLI11's) and a bad value found by the command (fail_usage).
  for (const auto& [args, command] : std::vector<std::pair<std::string, std::string>>{
           {"resample " + walk + " -o /tmp/never.bvh --no-such-option", "resample"},
           {"resample " + walk + " -o /tmp/never.bvh --keep-every 0", "resample"},
           {"eval " + walk + " -o /tmp/never --method wobble -q", "eval"},
           {"reduce " + walk + " --method wobble", "reduce"},
           {"info", "info"}}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find("(see 'rotinterp " + command + " --help')"), std::string::npos) << args << "\n" << r.err;
  }
  const auto top = run_cli("frobnicate");
  EXPECT_NE(top.err.find("run 'rotinterp --help'"), std::string::npos) << top.err;
}

TEST(Vocabulary, MethodNamesAreTakenInAnyCaseUnderEveryNameOfTheOption) {
  const std::string walk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";
  const auto dir = std::filesystem::temp_directory_path() / ("rotinterp_vocab_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const std::string option : {"-m", "--method", "--methods"}) {
    const auto r = run_cli("resample " + walk + " -o " + (dir / "x.bvh").string() + " --keep-every 4 -q " + option +
                           " SLERP");
    EXPECT_EQ(r.exit_code, 0) << option << ": " << r.err;
  }
  const auto typo = run_cli("resample " + walk + " -o " + (dir / "x.bvh").string() + " -m sqaud");
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.err.find("did you mean squad?"), std::string::npos) << typo.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::cli
