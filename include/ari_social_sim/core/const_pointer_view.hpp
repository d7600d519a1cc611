#pragma once

#include <cstddef>
#include <iterator>
#include <memory>
#include <vector>

namespace ari_social_sim::core {

/// A read-only look at objects an owner keeps as std::vector<std::unique_ptr<T>>: its items are
/// `const T*`. Handing out the vector itself, even as const, would hand out `T*` (unique_ptr's
/// operator-> is const), and with it the means to change the objects around the owner's rules.
template <class T>
class ConstPointerView {
 public:
  using Items = std::vector<std::unique_ptr<T>>;

  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = const T*;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = const T*;

    explicit Iterator(typename Items::const_iterator at) : at_(at) {}
    const T* operator*() const { return at_->get(); }
    Iterator& operator++() {
      ++at_;
      return *this;
    }
    bool operator==(const Iterator& other) const { return at_ == other.at_; }
    bool operator!=(const Iterator& other) const { return at_ != other.at_; }

   private:
    typename Items::const_iterator at_;
  };

  explicit ConstPointerView(const Items& items) : items_(&items) {}

  Iterator begin() const { return Iterator(items_->begin()); }
  Iterator end() const { return Iterator(items_->end()); }
  size_t size() const { return items_->size(); }
  bool empty() const { return items_->empty(); }
  const T* operator[](size_t i) const { return (*items_)[i].get(); }

 private:
  const Items* items_;
};

}  // namespace ari_social_sim::core
