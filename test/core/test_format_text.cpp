#include <gtest/gtest.h>

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

}  // namespace
}  // namespace ari_social_sim::core
