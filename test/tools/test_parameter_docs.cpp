// docs/parameters.md is what parameter_docs generates from the config structs today.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "parameters_page/parameters_page.hpp"

namespace ari_social_sim::tools {
namespace {

std::string committed_page() {
  std::ifstream in(std::string(ARI_SOURCE_DIR) + "/docs/parameters.md", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first line where `a` and `b` differ (1-based) and both versions of it.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream in_a(a), in_b(b);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(in_a, line_a));
    const bool more_b = static_cast<bool>(std::getline(in_b, line_b));
    if (!more_a && !more_b) {
      return "none";
    }
    if (!more_a || !more_b || line_a != line_b) {
      return "line " + std::to_string(line) + ":\n  committed: " + (more_a ? line_a : "(end)") +
             "\n  generated: " + (more_b ? line_b : "(end)");
    }
  }
}

TEST(ParameterDocs, CommittedPageIsUpToDate) {
  const std::string committed = committed_page();
  const std::string generated = parameters_page();
  EXPECT_TRUE(committed == generated)
      << "docs/parameters.md is out of date; regenerate it from the source tree with\n"
      << "  rosrun ari_social_sim parameter_docs > docs/parameters.md\n"
      << "First difference at " << first_difference(committed, generated);
}

TEST(ParameterDocs, ListsEveryNodeAndTheirParameters) {
  const std::string page = parameters_page();
  for (const char* expected :
       {"### world_node", "### hri_perception_node", "### group_detection_node",
        "### social_mpc_node", "### dialogue_node", "### scenario_node", "### ari_physics_node",
        "| `~step` | number | `0.05` | (0, 1] | sim seconds per step |",
        "| `~mpc/solver` | string | `lbfgs` | lbfgs, slsqp or mppi |",
        "| `~mode` | string | required | world, rl_env or user_bot |",
        "| `body_errors.miss_rate` | number | `0.02` | [0, 1] |",
        "- `persons.forget_after`: at least location_decay (10)"}) {
    EXPECT_NE(page.find(expected), std::string::npos) << expected;
  }
}

}  // namespace
}  // namespace ari_social_sim::tools
