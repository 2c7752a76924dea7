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
