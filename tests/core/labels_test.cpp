// SPDX-License-Identifier: LGPL-2.1-or-later
// Partner labels where slots crowd: every slot gets its partner's id, smaller, turned along
// the slot or further along its hinge line, but always on paper, clear of the cuts and of
// the other labels, and nearer its own slot than any other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "layout/labels.hpp"

namespace sliceform {
namespace {

Region2d boxOf(const Label& l) {
  const double w = labelWidth(l.text, l.height) / 2, h = l.height / 2;
  const double hx = l.vertical ? h : w, hy = l.vertical ? w : h;
  return Region2d::fromLoops({{{l.at.x - hx, l.at.y - hy},
                               {l.at.x + hx, l.at.y - hy},
                               {l.at.x + hx, l.at.y + hy},
                               {l.at.x - hx, l.at.y + hy}}});
}

// A strip of paper 60 mm wide with `count` slots `pitch` apart cut 10 mm down from its top
// edge, and `below` mm of paper under them, as a patch with many close hinges has; one
// spot per slot.
struct Comb {
  Region2d paper;
  std::vector<LabelSpot> spots;
};

Comb comb(int count, double pitch, double below) {
  const double width = 0.5, x0 = 30 - (count - 1) * pitch / 2, bottom = 10 - below;
  Region2d::Loop outline{{0, bottom}, {60, bottom}, {60, 20}};
  for (int i = count; i-- > 0;) {
    const double x = x0 + i * pitch;
    outline.insert(outline.end(),
                   {{x + width / 2, 20}, {x + width / 2, 10}, {x - width / 2, 10}, {x - width / 2, 20}});
  }
  outline.push_back({0, 20});
  Comb c{Region2d::fromLoops({outline}), {}};
  for (int i = 0; i < count; ++i)
    c.spots.push_back({"V" + std::to_string(10 + i), x0 + i * pitch, {bottom, 20}, 15, width, {10, 20}});
  return c;
}

void expectEveryLabelFitsItsSlot(const Comb& c, const std::vector<Label>& labels, const Label& name) {
  ASSERT_EQ(labels.size(), c.spots.size());
  const Region2d clear = c.paper.offset(-0.59);  // the 0.6 mm margin, less rounding
  for (size_t i = 0; i < labels.size(); ++i) {
    const Label& l = labels[i];
    EXPECT_EQ(l.text, c.spots[i].text);
    EXPECT_GE(l.height, kMinLabelHeight - 1e-9) << l.text;
    EXPECT_TRUE(boxOf(l).subtract(clear).empty()) << l.text << " at " << l.at.x << ", " << l.at.y;
    EXPECT_TRUE(boxOf(l).intersect(boxOf(name)).empty()) << l.text;
    for (size_t j = 0; j < i; ++j)
      EXPECT_TRUE(boxOf(l).offset(0.59).intersect(boxOf(labels[j])).empty())
          << l.text << " on " << labels[j].text;
    // No other slot is nearer than its own: whoever assembles reads it as this slot's.
    for (const LabelSpot& other : c.spots) {
      if (other.text == l.text) continue;
      EXPECT_LT(std::abs(l.at.x - c.spots[i].x), std::abs(l.at.x - other.x)) << l.text;
    }
  }
}

// Slots 1.2 mm apart leave 0.7 mm of paper between them: no label of any size fits beside
// a slot, so each goes on its hinge line beyond the slot's root, turned to read along it.
TEST(PartnerLabels, EverySlotLabelledWhereSlotsCrowd) {
  const Comb c = comb(24, 1.2, 10);
  const Label name = placeName(c.paper, "U5");
  int missing = 0;
  const std::vector<Label> labels = placePartners(c.paper, c.spots, {name}, 3.5, missing);
  EXPECT_EQ(missing, 0);
  expectEveryLabelFitsItsSlot(c, labels, name);
}

// A whole patch labelled: its id and every partner, the id clear of them all.
TEST(PartnerLabels, PatchIdAndEveryPartner) {
  const Comb c = comb(24, 1.2, 10);
  const PatchLabels labels = labelPatch(labelPaper(c.paper), "U5", c.spots);
  EXPECT_EQ(labels.missing, 0);
  ASSERT_GT(labels.name.height, 0);
  expectEveryLabelFitsItsSlot(c, labels.partners, labels.name);
}

// Slots 3 mm apart leave 2.5 mm between them, and 1.8 mm of paper under them: too narrow
// for "V12" lying across at any legible size, wide enough for it turned along the slot.
TEST(PartnerLabels, TurnedAlongTheSlotWhereItIsNarrow) {
  const Comb c = comb(16, 3, 1.8);
  const Label name = placeName(c.paper, "U5");
  int missing = 0;
  const std::vector<Label> labels = placePartners(c.paper, c.spots, {name}, 3.5, missing);
  EXPECT_EQ(missing, 0);
  expectEveryLabelFitsItsSlot(c, labels, name);
  // The first and last slots have the strip's ends beside them.
  for (size_t i = 1; i + 1 < labels.size(); ++i) EXPECT_TRUE(labels[i].vertical) << labels[i].text;
}

// Where there is room, labels stay as they were: beside the slot, across it, full size.
TEST(PartnerLabels, BesideTheSlotWhereThereIsRoom) {
  const Comb c = comb(4, 12, 10);
  int missing = 0;
  const std::vector<Label> labels = placePartners(c.paper, c.spots, {}, 3.5, missing);
  EXPECT_EQ(missing, 0);
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_FALSE(labels[i].vertical) << labels[i].text;
    EXPECT_NEAR(labels[i].height, 3.5, 1e-9) << labels[i].text;
    EXPECT_GT(labels[i].at.y, 10) << labels[i].text;  // beside the slot, not below it
  }
}

}  // namespace
}  // namespace sliceform
