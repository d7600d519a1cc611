#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ari_social_sim/core/format_text.hpp"

namespace ari_social_sim::core {
namespace {

TEST(FormatText, FormatsNumbersAndStringsAsPrintfDoes) {
  EXPECT_EQ(format_text("%.2f s in state %s", 26.449, "leave"), "26.45 s in state leave");
  EXPECT_EQ(format_text("(%.2f, %.2f)", -0.004, 3.6), "(-0.00, 3.60)");
  EXPECT_EQ(format_text("%016llx", 0xabcULL), "0000000000000abc");
  EXPECT_EQ(format_text("no arguments"), "no arguments");
  EXPECT_EQ(format_text("%s", ""), "");
}

TEST(FormatText, KeepsTextLongerThanAnyFixedBuffer) {
  const std::string long_name(5000, 'x');
  const std::string text = format_text("<%s> %d", long_name.c_str(), 42);
  ASSERT_EQ(text.size(), 5000u + 5u);
  EXPECT_EQ(text.substr(0, 2), "<x");
  EXPECT_EQ(text.substr(text.size() - 4), "> 42");
}

// A rogue transform at 1e300 used to print its 300 digits in navigation's messages.
TEST(FormatText, CoordinatesKeepTwoDecimalsUpToAMillionThenPercentG) {
  EXPECT_EQ(point_text({1.234, -4.5}), "(1.23, -4.50)");
  EXPECT_EQ(point_text({1e300, 2.0}), "(1e+300, 2.00)");
  EXPECT_EQ(coordinate_text(-INFINITY), "-inf");
  EXPECT_EQ(coordinate_text(999999.0), "999999.00");
  EXPECT_EQ(coordinate_text(2e6), "2e+06");
}

}  // namespace
}  // namespace ari_social_sim::core
