#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/core/json_string.hpp"

namespace ari_social_sim::core {
namespace {

TEST(JsonString, QuotesAndEscapesWhatJsonRequires) {
  EXPECT_EQ(json_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\n\"");
  EXPECT_EQ(json_string(std::string(1, '\x01')), "\"\\u0001\"");
  EXPECT_EQ(json_string("\t\r"), "\"\\t\\r\"");
  EXPECT_EQ(json_string(""), "\"\"");
  // UTF-8 passes through byte for byte: JSON text is UTF-8.
  EXPECT_EQ(json_string("caf\xc3\xa9"), "\"caf\xc3\xa9\"");
}

}  // namespace
}  // namespace ari_social_sim::core
