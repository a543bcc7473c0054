#include "io/patch_match_config.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using Kind = PatchMatchConfigEntry::Kind;
using test::InputErrorMessage;

std::vector<PatchMatchConfigEntry> Parse(const std::string& text) {
  return ParsePatchMatchConfigText(text, "cfg");
}

TEST(PatchMatchConfig, ImageUndistorterOutput) {
  const auto entries = Parse("a.jpg\n__auto__, 20\nsub/b.jpg\n__auto__, 20\n");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].ref_name, "a.jpg");
  EXPECT_EQ(entries[0].kind, Kind::kAuto);
  EXPECT_EQ(entries[0].num_auto, 20);
  EXPECT_EQ(entries[1].ref_name, "sub/b.jpg");
}

TEST(PatchMatchConfig, CommentsEmptyLinesAndWhitespace) {
  const auto entries = Parse(
      "# header comment\n"
      "\n"
      "   a.jpg  \r\n"
      "  # comment between the two lines of a pair\n"
      "\t__auto__ ,\t5 \n"
      "\n");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].ref_name, "a.jpg");
  EXPECT_EQ(entries[0].kind, Kind::kAuto);
  EXPECT_EQ(entries[0].num_auto, 5);
}

TEST(PatchMatchConfig, AutoWithSemicolon) {
  const auto entries = Parse("a.jpg\n__auto__;3\n");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].kind, Kind::kAuto);
  EXPECT_EQ(entries[0].num_auto, 3);
}

TEST(PatchMatchConfig, All) {
  const auto entries = Parse("a.jpg\n  __all__ \n");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].kind, Kind::kAll);
  EXPECT_TRUE(entries[0].src_names.empty());
}

TEST(PatchMatchConfig, ExplicitListWithBothSeparators) {
  const auto entries = Parse("a.jpg\nb.jpg, sub/c.jpg;d.jpg ;; , e.jpg,\n");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].kind, Kind::kList);
  EXPECT_EQ(entries[0].src_names,
            (std::vector<std::string>{"b.jpg", "sub/c.jpg", "d.jpg", "e.jpg"}));
}

TEST(PatchMatchConfig, SpecialTokensOnlyWithTheirExactShape) {
  // `__all__` with more items, or `__auto__` without exactly one number, are
  // plain lists in COLMAP (and then fail as unknown image names).
  auto entries = Parse("a.jpg\n__all__, b.jpg\nb.jpg\n__auto__\n");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].kind, Kind::kList);
  EXPECT_EQ(entries[0].src_names, (std::vector<std::string>{"__all__", "b.jpg"}));
  EXPECT_EQ(entries[1].kind, Kind::kList);
  EXPECT_EQ(entries[1].src_names, (std::vector<std::string>{"__auto__"}));
}

TEST(PatchMatchConfig, InvalidAutoCount) {
  EXPECT_NE(InputErrorMessage([] {
              Parse("a.jpg\n__auto__, many\n");
            }).find("cfg:2: invalid number of source images `many` after __auto__"),
            std::string::npos);
  EXPECT_NE(InputErrorMessage([] {
              Parse("a.jpg\n__auto__, -1\n");
            }).find("invalid number of source images `-1`"),
            std::string::npos);
}

TEST(PatchMatchConfig, OddNumberOfLines) {
  const std::string message = InputErrorMessage([] { Parse("a.jpg\n__all__\n# c\n\nb.jpg\n"); });
  EXPECT_NE(message.find("cfg:5: reference image `b.jpg` has no source line"), std::string::npos)
      << message;
}

TEST(PatchMatchConfig, EmptyFileHasNoProblems) {
  EXPECT_TRUE(Parse("").empty());
  EXPECT_TRUE(Parse("# nothing\n\n").empty());
}

TEST(PatchMatchConfig, MissingFile) {
  test::TempDir dir;
  EXPECT_NE(InputErrorMessage([&] {
              ParsePatchMatchConfig(dir / "patch-match.cfg");
            }).find("patch-match.cfg does not exist"),
            std::string::npos);
  test::WriteRaw(dir / "p.cfg", "x.png\n__all__\n");
  EXPECT_EQ(ParsePatchMatchConfig(dir / "p.cfg").size(), 1u);
}

}  // namespace
}  // namespace msp
