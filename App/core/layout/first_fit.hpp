// SPDX-License-Identifier: LGPL-2.1-or-later
// libnest2d's first-fit selection (selections/firstfit.hpp, 5.0: each part, largest first,
// goes on the first sheet whose placer takes it) that asks a sheet's placer only where the
// part may have room. The placer's try is the costly part of nesting (no-fit polygons
// against everything on the sheet, merged, then an optimiser), and first fit asks every
// sheet for every part: Ball.brep's 56 patches took 596 tries on 20 sheets, 1.4 s. Which
// sheet a part goes on, and where, is libnest2d's, as long as `Config` says false only
// where the placer would say no. Internal to nesting.cpp.
#pragma once

#include <libnest2d/libnest2d.hpp>

#include <algorithm>
#include <functional>
#include <vector>

namespace sliceform {

template <class RawShape>
class FirstFitSkipping : public libnest2d::selections::SelectionBoilerplate<RawShape> {
  using Base = libnest2d::selections::SelectionBoilerplate<RawShape>;
  using Base::packed_bins_;

 public:
  using typename Base::Item;
  using typename Base::ItemGroup;
  // Whether the part may have room on a sheet holding the parts `placed` (never empty).
  using Config = std::function<bool(const ItemGroup& placed, const Item& part)>;

  void configure(const Config& mayFit) { mayFit_ = mayFit; }

  template <class TPlacer, class TIterator,
            class TBin = typename libnest2d::PlacementStrategyLike<TPlacer>::BinType,
            class PConfig = typename libnest2d::PlacementStrategyLike<TPlacer>::Config>
  void packItems(TIterator first, TIterator last, TBin&& bin, PConfig&& pconfig = PConfig()) {
    using Placer = libnest2d::PlacementStrategyLike<TPlacer>;
    ItemGroup store(first, last);
    // As libnest2d: larger first (no part has a priority here), and the parts that fit no
    // empty sheet left out (they keep no sheet).
    std::sort(store.begin(), store.end(), [](Item& a, Item& b) {
      return a.priority() == b.priority() ? a.area() > b.area() : a.priority() > b.priority();
    });
    this->template remove_unpackable_items<Placer>(store, bin, pconfig);
    std::vector<Placer> placers;
    placers.reserve(store.size());
    for (auto it = store.begin(); it != store.end(); ++it) {
      Item& item = *it;
      for (size_t j = 0;; ++j) {
        if (j == placers.size()) {
          placers.emplace_back(bin);
          placers.back().configure(pconfig);
          packed_bins_.emplace_back();
        }
        const ItemGroup& placed = placers[j].getItems();
        if (!placed.empty() && mayFit_ && !mayFit_(placed, item)) continue;
        if (placers[j].pack(item, libnest2d::rem(it, store))) {
          item.binId(static_cast<int>(j));
          packed_bins_[j] = placers[j].getItems();
          break;
        }
      }
    }
  }

 private:
  Config mayFit_;
};

}  // namespace sliceform
