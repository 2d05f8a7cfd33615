// Numbers in help text, written from the constants they describe.

#include "help_numbers.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using hullcover::app::number_text;

TEST(HelpNumbers, ShortestTextThatReadsBackWithoutExponentPadding) {
  EXPECT_EQ(number_text(1e-5), "1e-5");
  EXPECT_EQ(number_text(0.02), "0.02");
  EXPECT_EQ(number_text(4.0), "4");
  EXPECT_EQ(number_text(2.5e20), "2.5e20");
  EXPECT_EQ(number_text(-0.125), "-0.125");
  for (const double v : {1e-5, 0.1, 1.0 / 3.0, 123456.789, 6.02e23})
    EXPECT_EQ(std::stod(number_text(v)), v) << number_text(v);
}

} // namespace
