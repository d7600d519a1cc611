#include <gtest/gtest.h>

#include <memory>
#include <type_traits>
#include <vector>

#include "ari_social_sim/core/const_pointer_view.hpp"

namespace ari_social_sim::core {
namespace {

struct Item {
  int value;
};

static_assert(
    std::is_same_v<decltype(*std::declval<ConstPointerView<Item>>().begin()), const Item*>);
static_assert(std::is_same_v<decltype(std::declval<ConstPointerView<Item>>()[0]), const Item*>);

TEST(ConstPointerView, ShowsTheOwnersItemsInOrderAsTheyChange) {
  std::vector<std::unique_ptr<Item>> items;
  const ConstPointerView<Item> view(items);
  EXPECT_TRUE(view.empty());
  items.push_back(std::make_unique<Item>(Item{3}));
  items.push_back(std::make_unique<Item>(Item{5}));
  ASSERT_EQ(view.size(), 2u);
  EXPECT_EQ(view[1]->value, 5);
  std::vector<int> values;
  for (const Item* item : view) {
    values.push_back(item->value);
  }
  EXPECT_EQ(values, (std::vector<int>{3, 5}));
  items[0]->value = 4;  // the owner changes it; the view sees the change
  EXPECT_EQ(view[0]->value, 4);
}

}  // namespace
}  // namespace ari_social_sim::core
