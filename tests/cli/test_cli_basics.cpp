// The command line's contract: --help, --version, exit codes for usage errors.
#include "support/run_cli.h"

#include <gtest/gtest.h>

using rotinterp::test::run_cli;

TEST(Cli, VersionPrintsTheProjectVersionAndSucceeds) {
  const auto r = run_cli("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find(std::string("rotinterp ") + ROTINTERP_VERSION), std::string::npos) << r.out;
}

TEST(Cli, HelpListsSubcommandsAndSucceeds) {
  const auto r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("methods"), std::string::npos) << r.out;
}

TEST(Cli, SubcommandHelpSucceeds) {
  const auto r = run_cli("methods --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--json"), std::string::npos) << r.out;
}

TEST(Cli, UnknownOptionIsAUsageErrorWithOneLine) {
  const auto r = run_cli("methods --no-such-option");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("rotinterp: "), std::string::npos) << r.err;
}

TEST(Cli, UnknownSubcommandIsAUsageError) {
  EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
  EXPECT_EQ(run_cli("").exit_code, 2);
}

TEST(Cli, MisspelledSubcommandSuggestsTheNearest) {
  const auto r = run_cli("resampel in.bvh -o out.bvh");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown subcommand 'resampel' (did you mean 'resample'?"), std::string::npos) << r.err;
}

TEST(Cli, MisspelledOptionSuggestsTheSubcommandsNearestOption) {
  const auto r = run_cli("resample in.bvh -o out.bvh --fsp 30");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("did you mean '--fps'?"), std::string::npos) << r.err;
  const auto e = run_cli("eval in.bvh --keep-evry 4");
  EXPECT_NE(e.err.find("did you mean '--keep-every'?"), std::string::npos) << e.err;
}

TEST(Cli, SourceIsRefusedWithWhereItRunsByCommandsThatRebuildFromKeys) {
  for (const char* cmd : {"eval in.fbx -m slerp,source --keep-every 4", "reduce in.fbx -m source"}) {
    const auto r = run_cli(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_EQ(r.err.find("unknown method"), std::string::npos) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("it runs in resample -m source, render -m source, eval --truth source"), std::string::npos)
        << cmd << ": " << r.err;
  }
}

TEST(Cli, MethodsSaysWhereEachMethodRuns) {
  const auto r = run_cli("methods");
  EXPECT_NE(r.out.find("runs in resample -m source, render -m source, eval --truth source"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Every method but source runs in resample, eval, reduce, render"), std::string::npos) << r.out;
}
