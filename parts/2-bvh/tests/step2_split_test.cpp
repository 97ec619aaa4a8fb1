// Part 2, step 2 (split): the split choices on their own (the midpoint, the SAH sweep), and the
// build's decisions made with them: a node stays a leaf exactly when splitting it does not pay,
// the size cut separates big primitives from small ones, the tree records its split axes.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parts/2-bvh/bvh_split.h"
#include "parts/2-bvh/tests/bvh_check.h"
#include "parts/2-bvh/tests/bvh_test_inputs.h"

namespace pt {
namespace {

using test::add_triangle;

const Bounds3 kUnit{glm::vec3(0.0f), glm::vec3(1.0f)};

BvhOptions options(BvhSplitMethod split, int max_leaf) {
  BvhOptions o;
  o.split = split;
  o.max_leaf_size = max_leaf;
  return o;
}

/// Three big triangles on top of one another, their centroids a hair apart: any split leaves
/// both children nearly as big as the node, so it costs traversal + about 3 tests, more than the
/// 3 tests of a leaf.
Scene stacked_triangles() {
  Scene s;
  for (int i = 0; i < 3; ++i) {
    const float z = 0.01f * float(i);
    add_triangle(&s, {-1, -1, z}, {1, -1, z}, {0, 1, z});
  }
  return s;
}

/// The SAH splits two clusters far apart between them: a sweep that never finds a plane (a
/// stub's "no split") would pass the tests where a node rightly stays whole, so those tests ask
/// for this first.
void expect_the_sah_splits_two_clusters() {
  SahBin bins[4];
  bins[0].count = 5;
  bins[0].bounds = Bounds3{glm::vec3(0.0f), glm::vec3(0.1f)};
  bins[3].count = 5;
  bins[3].bounds = Bounds3{glm::vec3(0.9f), glm::vec3(1.0f)};
  const SahSplit split = best_sah_split(bins, 4, kUnit.surface_area(), SahCosts{});
  ASSERT_GE(split.plane, 0) << "best_sah_split finds no plane between two clusters at opposite "
                               "corners of the node";
  ASSERT_LE(split.plane, 2);
  // Both children are boxes of area 0.06 with 5 primitives, the node's area is 6.
  EXPECT_NEAR(split.cost, 1.0f + (0.06f * 5 + 0.06f * 5) / 6.0f, 1e-4f);
}

TEST(split, node_whose_split_does_not_pay_stays_a_leaf) {
  ASSERT_NO_FATAL_FAILURE(expect_the_sah_splits_two_clusters());
  const Scene s = stacked_triangles();
  const Bvh sah(s, options(BvhSplitMethod::sah, 4));
  ASSERT_EQ(sah.nodes().size(), 1u) << "the SAH split a node whose split costs more than a leaf";
  EXPECT_EQ(sah.nodes()[0].count, 3u);
  EXPECT_EQ(sah.stats().leaves, 1u);
  EXPECT_EQ(sah.stats().max_leaf_size, 3u);
  // The cap is a hard limit all the same, and the midpoint split, which weighs no costs,
  // splits down to it.
  const Bvh capped(s, options(BvhSplitMethod::sah, 2));
  EXPECT_GT(capped.nodes().size(), 1u);
  EXPECT_LE(capped.stats().max_leaf_size, 2u);
  EXPECT_EQ(Bvh(s, options(BvhSplitMethod::median, 2)).stats().leaves, 2u);
}

TEST(split, node_whose_split_pays_is_split) {
  // Four small triangles at the corners of a big box: each split leaves boxes a tiny fraction of
  // the node's, so the SAH splits down to single primitives although the cap would allow one
  // leaf of four.
  Scene s;
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 p(float(i & 1) * 10.0f, float(i >> 1) * 10.0f, float(i) * 3.0f);
    add_triangle(&s, p, p + glm::vec3(0.1f, 0, 0), p + glm::vec3(0, 0.1f, 0.05f));
  }
  const Bvh sah(s, options(BvhSplitMethod::sah, 4));
  EXPECT_EQ(sah.stats().leaves, 4u);
  EXPECT_EQ(sah.stats().max_leaf_size, 1u);
  EXPECT_EQ(sah.nodes().size(), 7u);
}

/// One big triangle through the middle of a ball of small ones, its box's centre at the ball's:
/// no plane through centroids separates it from them.
Scene floor_under_ball(int small) {
  Scene s;
  add_triangle(&s, {-20, -20, 1.5f}, {20, -20, 1.5f}, {0, 20, 1.5f});
  Rng rng(41);
  for (int i = 0; i < small; ++i) {
    const glm::vec3 p = glm::vec3(0, 0, 1.5f) + square_to_uniform_sphere(rng.next_2d()) *
                                                    (0.3f + rng.next_float());
    add_triangle(&s, p, p + glm::vec3(0.02f, 0, 0), p + glm::vec3(0, 0.02f, 0.01f));
  }
  return s;
}

TEST(split, big_and_small_mixed_sah_cost_below_midpoint) {
  const Scene s = floor_under_ball(5000);
  const Bvh sah(s, options(BvhSplitMethod::sah, 4)), mid(s, options(BvhSplitMethod::median, 4));
  EXPECT_LT(sah.stats().sah_cost, mid.stats().sah_cost);
  // The floor is cut off at the root: one child is the floor alone.
  const BvhNode& root = sah.nodes()[0];
  ASSERT_FALSE(root.is_leaf());
  const BvhNode& a = sah.nodes()[1];
  const BvhNode& b = sah.nodes()[root.offset];
  const bool floor_alone = (a.is_leaf() && a.count == 1 && sah.order()[a.offset] == 0) ||
                           (b.is_leaf() && b.count == 1 && sah.order()[b.offset] == 0);
  EXPECT_TRUE(floor_alone) << "the big triangle was not separated from the small ones at the root";
  // (Whether the tree's answers stay brute force's is the traversal's check, step 3: it runs the
  // walk and the box test, which are not this step's.)
}

TEST(split, nodes_record_their_split_axis) {
  // Two long rows along x, 5 apart in y: the SAH parts the rows (along y), although the
  // centroids spread widest along x, where the midpoint split cuts.
  Scene s;
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 50; ++i) {
      const glm::vec3 p(float(i) * 0.5f, float(c) * 5.0f, 0.0f);
      add_triangle(&s, p, p + glm::vec3(0.1f, 0, 0), p + glm::vec3(0, 0.1f, 0.1f));
    }
  const Bvh sah(s, options(BvhSplitMethod::sah, 4));
  ASSERT_FALSE(sah.nodes()[0].is_leaf());
  EXPECT_EQ(sah.nodes()[0].axis, 1) << "the root splits the two rows apart, along y";
  const Bvh mid(s, options(BvhSplitMethod::median, 4));
  EXPECT_EQ(mid.nodes()[0].axis, 0) << "the midpoint split cuts the longest spread, along x";
}

TEST(split, midpoint_cuts_the_widest_spread_in_half) {
  const MidpointSplit s = midpoint_split(Bounds3{glm::vec3(0, -4, 1), glm::vec3(1, 2, 2)});
  EXPECT_EQ(s.axis, 1);
  EXPECT_FLOAT_EQ(s.position, -1.0f);
  EXPECT_EQ(midpoint_split(Bounds3{glm::vec3(0), glm::vec3(1, 1, 3)}).axis, 2);
}

/// The SAH cost of every plane evaluated directly, plane by plane.
SahSplit naive_sah(const SahBin* bins, int n, float area, const SahCosts& c) {
  SahSplit best;
  for (int p = 0; p < n - 1; ++p) {
    Bounds3 l, r;
    uint32_t nl = 0, nr = 0;
    for (int i = 0; i <= p; ++i) l.grow(bins[i].bounds), nl += bins[i].count;
    for (int i = p + 1; i < n; ++i) r.grow(bins[i].bounds), nr += bins[i].count;
    if (nl == 0 || nr == 0) continue;
    const float cost = c.traversal + c.intersection * (l.surface_area() * nl + r.surface_area() * nr) / area;
    if (cost < best.cost) best = {p, cost};
  }
  return best;
}

TEST(split, sah_sweep_agrees_with_plane_by_plane_cost) {
  Rng rng(17);
  const SahCosts costs{1.0f, 2.0f};
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 2 + int(rng.next_u32() % 15);
    SahBin bins[kMaxSahBins];
    Bounds3 all;
    for (int i = 0; i < n; ++i) {
      if (rng.next_float() < 0.3f) continue;  // empty bins
      bins[i].count = 1 + rng.next_u32() % 20;
      const glm::vec3 lo(float(i) + rng.next_float(), rng.next_float(), rng.next_float());
      bins[i].bounds = Bounds3{lo, lo + glm::vec3(rng.next_float(), rng.next_float(), rng.next_float())};
      all.grow(bins[i].bounds);
    }
    if (all.empty()) continue;
    const float area = all.surface_area();
    const SahSplit got = best_sah_split(bins, n, area, costs), want = naive_sah(bins, n, area, costs);
    ASSERT_EQ(got.plane, want.plane) << "trial " << trial;
    if (want.plane >= 0) {
      ASSERT_NEAR(got.cost, want.cost, 1e-4f * want.cost) << "trial " << trial;
    }
  }
}

TEST(split, sah_has_no_split_when_one_bin_holds_everything) {
  ASSERT_NO_FATAL_FAILURE(expect_the_sah_splits_two_clusters());
  SahBin bins[4];
  bins[2].count = 7;
  bins[2].bounds = kUnit;
  EXPECT_EQ(best_sah_split(bins, 4, kUnit.surface_area(), SahCosts{}).plane, -1);
}

}  // namespace
}  // namespace pt
