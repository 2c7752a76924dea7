// The one CSV dialect: fields read back as written whatever they hold, and rows
// built against their table's schema.
#include "rotinterp/io/files/csv.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

TEST(Csv, FieldsReadBackAsWrittenWhateverCharactersTheyHold) {
  std::mt19937 rng(29);
  const std::string alphabet = "ab ,\"\r\n;'x";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1), length(0, 6), count(1, 5);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::string> fields(count(rng));
    for (std::string& f : fields)
      for (std::size_t n = length(rng); n > 0; --n) f += alphabet[pick(rng)];
    CsvSchema schema(std::vector<std::string>(fields.size(), "c"));
    CsvRow row(schema);
    for (const std::string& f : fields) row << f;
    const std::string line = row.line();
    ASSERT_EQ(line.back(), '\n');
    auto back = split_csv_line(line);
    ASSERT_TRUE(back) << back.error();
    EXPECT_EQ(*back, fields) << line;
  }
}

TEST(Csv, PlainFieldsAreWrittenUnquotedAndOthersQuotedWithQuotesDoubled) {
  EXPECT_EQ(csv_field("LeftUpLeg"), "LeftUpLeg");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_FALSE(split_csv_line("\"open,field"));
}

TEST(Csv, HeaderQuotesColumnNamesAndSchemasJoinInOrder) {
  const CsvSchema a = {"sample", "time_s"};
  const CsvSchema joints(std::vector<std::string>{"Left,Hand", "Hips"});
  const CsvSchema both = a + joints;
  EXPECT_EQ(both.size(), 4u);
  EXPECT_EQ(both.header(), "sample,time_s,\"Left,Hand\",Hips\n");
  CsvRow row(both);
  row << "0" << "0.5";
  row.skip(2);
  EXPECT_EQ(row.line(), "0,0.5,,\n");
}

}  // namespace
}  // namespace rotinterp
