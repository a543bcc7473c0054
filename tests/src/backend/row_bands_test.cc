#include "backend/row_bands.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace msp {
namespace {

// The bands cover every row once, in order, each within the budget.
void ExpectTiling(const std::vector<RowBand>& bands, const std::vector<size_t>& row_bytes,
                  size_t budget) {
  int next = 0;
  for (const RowBand& band : bands) {
    EXPECT_EQ(band.begin, next);
    EXPECT_LT(band.begin, band.end);
    size_t bytes = 0;
    for (int row = band.begin; row < band.end; ++row) bytes += row_bytes[row];
    EXPECT_LE(bytes, budget) << "band " << band.begin << ".." << band.end;
    next = band.end;
  }
  EXPECT_EQ(next, static_cast<int>(row_bytes.size()));
}

TEST(RowBands, AnImageThatFitsIsOneBand) {
  const std::vector<size_t> rows(480, 1000);
  const std::vector<RowBand> bands = PlanRowBands(rows, 480 * 1000);
  ASSERT_EQ(bands.size(), 1u);
  EXPECT_EQ(bands[0].begin, 0);
  EXPECT_EQ(bands[0].end, 480);
}

TEST(RowBands, EqualRowsSplitIntoTheFewestFullBands) {
  const std::vector<size_t> rows(100, 10);
  const std::vector<RowBand> bands = PlanRowBands(rows, 300);  // 30 rows a band
  ASSERT_EQ(bands.size(), 4u);
  EXPECT_EQ(bands[0].end, 30);
  EXPECT_EQ(bands[2].end, 90);
  EXPECT_EQ(bands[3].end, 100);
  ExpectTiling(bands, rows, 300);
}

TEST(RowBands, UnevenRowsTakeAsManyRowsAsFit) {
  // Rows without unreliable pixels cost nothing; a dense stretch splits.
  std::vector<size_t> rows(50, 0);
  for (int row = 20; row < 30; ++row) rows[row] = 100;
  const std::vector<RowBand> bands = PlanRowBands(rows, 250);
  ExpectTiling(bands, rows, 250);
  ASSERT_EQ(bands.size(), 5u);  // 0..21, 22..23, 24..25, 26..27, 28..49
  EXPECT_EQ(bands[0].end, 22);
  EXPECT_EQ(bands[4].begin, 28);
  EXPECT_EQ(bands[4].end, 50);
}

TEST(RowBands, ARowLargerThanTheBudgetStopsWithItsSize) {
  std::vector<size_t> rows(10, 10);
  rows[7] = 5000;
  try {
    PlanRowBands(rows, 4096);
    FAIL() << "a 5000-byte row fits in 4096 bytes";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("row 7 needs 5000 bytes"), std::string::npos) << m;
    EXPECT_NE(m.find("4096 bytes free"), std::string::npos) << m;
  }
}

TEST(RowBands, NoRowsNoBand) { EXPECT_TRUE(PlanRowBands({}, 100).empty()); }

}  // namespace
}  // namespace msp
