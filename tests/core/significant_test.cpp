// Numbers for people (core/format.hpp): significant digits, no raw doubles,
// no printf exponents, units and percentages, tick labels.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "foveate/core/format.hpp"

using namespace foveate;

TEST(FormatSignificant, TheIssuesRawNumbers) {
  // Not a raw double (0.00683761) nor printf's exponent (2.67701e-05).
  EXPECT_EQ(format_significant(0.00683761), "0.00684");
  EXPECT_EQ(format_significant(2.67701e-05), "2.68×10⁻⁵");
  EXPECT_EQ(format_significant(-2.67701e-05, 2), "-2.7×10⁻⁵");
}

TEST(FormatSignificant, DigitsKeptAndCarried) {
  EXPECT_EQ(format_significant(1.0), "1.00");
  EXPECT_EQ(format_significant(13.3333), "13.3");
  EXPECT_EQ(format_significant(0.5), "0.500");
  EXPECT_EQ(format_significant(9.996), "10.0");  // the carry drops a decimal
  EXPECT_EQ(format_significant(0.09996), "0.100");
  EXPECT_EQ(format_significant(999.6), "1000");
  EXPECT_EQ(format_significant(2073600.0), "2073600");  // whole, never 2.07e+06
  EXPECT_EQ(format_significant(988.4), "988");
  EXPECT_EQ(format_significant(0.0275, 2), "0.028");
  EXPECT_EQ(format_significant(0.001), "0.00100");
  EXPECT_EQ(format_significant(0.000999999), "1.00×10⁻³");
  EXPECT_EQ(format_significant(1.234e-12, 2), "1.2×10⁻¹²");
  EXPECT_EQ(format_significant(-0.0004, 1), "-4×10⁻⁴");
  EXPECT_EQ(format_significant(3.14159, 0), "3");  // at least one digit
}

TEST(FormatSignificant, SpecialValues) {
  EXPECT_EQ(format_significant(0.0), "0");
  EXPECT_EQ(format_significant(-0.0), "0");
  EXPECT_EQ(format_significant(std::nan("")), "–");
  EXPECT_EQ(format_significant(std::numeric_limits<double>::infinity()), "∞");
  EXPECT_EQ(format_significant(-std::numeric_limits<double>::infinity()), "−∞");
}

TEST(FormatQuantity, UnitsAndPercentages) {
  EXPECT_EQ(format_quantity(2.0512, "ms"), "2.05 ms");
  EXPECT_EQ(format_quantity(std::nan(""), "ms"), "–");
  EXPECT_EQ(format_quantity(4.0, ""), "4.00");
  EXPECT_EQ(format_percent(0.4531), "45.3 %");
  EXPECT_EQ(format_percent(1.0), "100 %");
  EXPECT_EQ(format_percent(0.0), "0 %");
  // A layer that shades a few pixels is not "0.0 %".
  EXPECT_EQ(format_percent(0.00012, 2), "0.012 %");
}

TEST(FormatTick, DecimalsFromTheStep) {
  EXPECT_EQ(format_tick(0.1, 0.05), "0.10");
  EXPECT_EQ(format_tick(10.0, 5.0), "10");
  EXPECT_EQ(format_tick(0.5, 0.25), "0.50");
  EXPECT_EQ(format_tick(0.94, 0.02), "0.94");
  EXPECT_EQ(format_tick(1.2, 0.2), "1.2");
  EXPECT_EQ(format_tick(-1e-17, 0.2), "0");  // rounding noise at zero
  EXPECT_EQ(format_tick(2000000.0, 500000.0), "2000000");
  EXPECT_EQ(format_tick(2e-5, 1e-5), "2×10⁻⁵");
  EXPECT_EQ(format_tick(0.0, 1e-5), "0");
}

TEST(FormatPowerOfTen, WrittenOutNearOnePowersBeyond) {
  EXPECT_EQ(format_power_of_ten(0), "1");
  EXPECT_EQ(format_power_of_ten(3), "1000");
  EXPECT_EQ(format_power_of_ten(-2), "0.01");
  EXPECT_EQ(format_power_of_ten(9), "10⁹");
  EXPECT_EQ(format_power_of_ten(12), "10¹²");
  EXPECT_EQ(format_power_of_ten(-5), "10⁻⁵");
}
