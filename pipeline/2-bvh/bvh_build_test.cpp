// Not needed for the assignment.
// BVH construction, whatever splits it is given: the tree is well formed (every primitive once,
// boxes nested, leaves within size), bad options are refused, an empty scene has no tree. These
// hold with a stub's splits too (the build falls back to halving), so they are not Part 2's.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "framework/testing/test_paths.h"
#include "parts/2-bvh/bvh.h"
#include "parts/2-bvh/tests/bvh_check.h"
#include "parts/2-bvh/tests/bvh_test_inputs.h"

namespace pt {
namespace {

using test::add_triangle;

TEST(PipelineBvhBuild, EmptySceneHasNoTreeAndNoHits) {
  const Scene scene;
  const Bvh bvh(scene);
  EXPECT_TRUE(bvh.nodes().empty());
  EXPECT_EQ(bvh.stats().nodes, 0u);
  SurfaceHit hit;
  Ray ray;
  EXPECT_FALSE(bvh.intersect(ray, &hit));
  EXPECT_FALSE(bvh.occluded(ray));
}

/// Checks the tree's invariants: every primitive once, boxes nested, leaves within size.
void expect_well_formed(const Scene& scene, const Bvh& bvh, int leaf) {
  const auto& nodes = bvh.nodes();
  std::multiset<uint32_t> seen(bvh.order().begin(), bvh.order().end());
  ASSERT_EQ(seen.size(), scene.primitive_count());
  for (uint32_t p = 0; p < scene.primitive_count(); ++p) ASSERT_EQ(seen.count(p), 1u) << p;
  uint32_t leaves = 0, covered = 0;
  auto inside = [](const Bounds3& in, const Bounds3& out) {
    return glm::all(glm::greaterThanEqual(in.lo, out.lo)) && glm::all(glm::lessThanEqual(in.hi, out.hi));
  };
  for (size_t i = 0; i < nodes.size(); ++i) {
    const BvhNode& n = nodes[i];
    if (n.is_leaf()) {
      ++leaves;
      covered += n.count;
      EXPECT_LE(n.count, uint32_t(leaf));
      for (uint32_t k = n.offset; k < n.offset + n.count; ++k)
        EXPECT_TRUE(inside(scene.primitive_bounds(bvh.order()[k]), n.bounds));
    } else {
      ASSERT_GT(n.offset, i + 1);
      ASSERT_LT(n.offset, nodes.size());
      EXPECT_TRUE(inside(nodes[i + 1].bounds, n.bounds));
      EXPECT_TRUE(inside(nodes[n.offset].bounds, n.bounds));
    }
  }
  EXPECT_EQ(covered, scene.primitive_count());
  EXPECT_EQ(nodes.size(), 2 * size_t(leaves) - 1);
  EXPECT_EQ(bvh.stats().leaves, leaves);
  EXPECT_EQ(bvh.stats().nodes, nodes.size());
}

TEST(PipelineBvhBuild, TreeIsWellFormed) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(pt::test::source_dir()) + "/scenes/cornell_coil.dae", &scene, &why))
    GTEST_SKIP() << why;
  for (int leaf : {1, 4, 8}) {
    BvhOptions sah{BvhSplitMethod::sah, leaf, 16, {}}, mid{BvhSplitMethod::median, leaf, 16, {}};
    expect_well_formed(scene, Bvh(scene, sah), leaf);
    expect_well_formed(scene, Bvh(scene, mid), leaf);
  }
}

TEST(PipelineBvhBuild, BadOptionsAreRefused) {
  Scene s;
  add_triangle(&s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_THROW(Bvh(s, BvhOptions{BvhSplitMethod::sah, 0, 16, {}}), std::invalid_argument);
  EXPECT_THROW(Bvh(s, BvhOptions{BvhSplitMethod::sah, 1000, 16, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace pt
