// SPDX-License-Identifier: LGPL-2.1-or-later
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <utility>

namespace sliceform {

// A map that forgets what was not asked for lately, in two generations: the current one and
// the one before. A value found in the older one moves into the current one. age() starts a
// new generation when the current one holds more than `budget` (the values' costs summed,
// e.g. bytes), dropping the older one, so about twice the budget is held at most. It ages only
// when its owner calls age(), so what was put in since the last call is still found.
template <class Key, class T>
class BoundedCache {
 public:
  explicit BoundedCache(size_t budget) : budget_(budget) {}

  // The value for `key`, or null.
  std::shared_ptr<const T> find(const Key& key) {
    const auto it = current_.find(key);
    if (it != current_.end()) return it->second.value;
    const auto old = older_.find(key);
    if (old == older_.end()) return nullptr;
    Entry entry = std::move(old->second);
    older_.erase(old);
    cost_ += entry.cost;
    return current_.emplace(key, std::move(entry)).first->second.value;
  }

  bool contains(const Key& key) const { return current_.count(key) > 0 || older_.count(key) > 0; }
  size_t size() const { return current_.size() + older_.size(); }

  void put(Key key, std::shared_ptr<const T> value, size_t cost) {
    if (contains(key)) return;
    cost_ += cost;
    current_.emplace(std::move(key), Entry{std::move(value), cost});
  }

  void age() {
    if (cost_ <= budget_) return;
    older_ = std::move(current_);
    current_.clear();
    cost_ = 0;
  }

 private:
  struct Entry {
    std::shared_ptr<const T> value;
    size_t cost = 0;
  };
  size_t budget_;
  size_t cost_ = 0;  // of current_
  std::map<Key, Entry> current_, older_;
};

}  // namespace sliceform
