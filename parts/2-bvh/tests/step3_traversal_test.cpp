// Part 2: the BVH on inputs that break naive builds and traversals — no primitives, one, all
// centroids equal, boxes of zero thickness, duplicates — gives brute force's answers; and the
// tree it builds is well formed.
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "parts/2-bvh/tests/bvh_check.h"
#include "parts/2-bvh/tests/bvh_test_inputs.h"

namespace pt {
namespace {

using test::add_triangle;

/// Checks `scene` against brute force with both split methods and two leaf sizes.
void expect_brute_force_answers(const Scene& scene, std::vector<Ray> extra = {}) {
  std::vector<Ray> rays = test::random_rays(scene, 100000, 99);
  rays.insert(rays.end(), extra.begin(), extra.end());
  for (BvhSplitMethod split : {BvhSplitMethod::sah, BvhSplitMethod::median})
    for (int leaf : {1, 4}) {
      SCOPED_TRACE(std::string(split == BvhSplitMethod::sah ? "sah" : "median") + " leaf " +
                   std::to_string(leaf));
      BvhOptions o;
      o.split = split;
      o.max_leaf_size = leaf;
      const Bvh bvh(scene, o);
      const test::Comparison r = test::compare_with_brute_force(scene, bvh, rays);
      EXPECT_EQ(r.nearest_differ, 0u) << r.examples;
      EXPECT_EQ(r.occluded_differ, 0u) << r.examples;
      EXPECT_EQ(r.anyhit_vs_nearest, 0u) << r.examples;
      EXPECT_GT(r.hits, 0u);
    }
}

TEST(Part2BvhDegenerate, EmptySceneHasNoTreeAndNoHits) {
  const Scene scene;
  const Bvh bvh(scene);
  EXPECT_TRUE(bvh.nodes().empty());
  EXPECT_EQ(bvh.stats().nodes, 0u);
  SurfaceHit hit;
  Ray ray;
  EXPECT_FALSE(bvh.intersect(ray, &hit));
  EXPECT_FALSE(bvh.occluded(ray));
}

TEST(Part2BvhDegenerate, OnePrimitiveIsOneLeaf) {
  Scene tri;
  add_triangle(&tri, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  EXPECT_EQ(Bvh(tri).nodes().size(), 1u);
  expect_brute_force_answers(tri);
  Scene sphere;
  sphere.spheres.push_back(Sphere{glm::vec3(1, 2, 3), 0.5f, 0});
  EXPECT_EQ(Bvh(sphere).nodes().size(), 1u);
  expect_brute_force_answers(sphere);
}

TEST(Part2BvhDegenerate, AllCentroidsEqual) {
  // Triangles and spheres whose boxes are all centred on the origin: no plane separates them.
  const Scene s = test::centroids_all_equal();
  const Bvh bvh(s, BvhOptions{BvhSplitMethod::sah, 4, 16, {}});
  EXPECT_LE(bvh.stats().max_leaf_size, 4u);
  EXPECT_LT(bvh.stats().depth, uint32_t(Bvh::kMaxDepth));
  expect_brute_force_answers(s);
}

TEST(Part2BvhDegenerate, FlatBoxesAndRaysInTheirPlane) {
  // Every box has zero thickness; rays inside the plane make the slab test divide 0 by 0.
  expect_brute_force_answers(test::flat_grid(), test::rays_at_flat_grid(11));
}

TEST(Part2BvhDegenerate, DuplicatesTieToTheLowestIndex) {
  const Scene s = test::duplicate_triangles(50);
  const Bvh bvh(s, BvhOptions{BvhSplitMethod::sah, 1, 16, {}});
  SurfaceHit hit;
  Ray ray;
  ray.o = glm::vec3(0, 0, 1);
  ASSERT_TRUE(bvh.intersect(ray, &hit));
  EXPECT_EQ(hit.primitive, 0u);
  expect_brute_force_answers(s);
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

TEST(Part2BvhBuild, TreeIsWellFormed) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(PT_SOURCE_DIR) + "/scenes/cornell_coil.dae", &scene, &why))
    GTEST_SKIP() << why;
  for (int leaf : {1, 4, 8}) {
    BvhOptions sah{BvhSplitMethod::sah, leaf, 16, {}}, mid{BvhSplitMethod::median, leaf, 16, {}};
    expect_well_formed(scene, Bvh(scene, sah), leaf);
    expect_well_formed(scene, Bvh(scene, mid), leaf);
  }
}

TEST(Part2BvhDegenerate, ClusteredGeometry) {
  // Small triangles in a few tight clusters among big random triangles: boxes that overlap a lot.
  Scene s;
  Rng rng(23);
  for (int w = 0; w < 12; ++w)
    add_triangle(&s, 10.0f * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f),
                 10.0f * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f),
                 10.0f * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f));
  for (int c = 0; c < 5; ++c) {
    const glm::vec3 centre = 8.0f * (glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f);
    for (int i = 0; i < 400; ++i) {
      const glm::vec3 p = centre + 0.3f * square_to_uniform_sphere(rng.next_2d()) * rng.next_float();
      add_triangle(&s, p, p + glm::vec3(0.01f, 0, 0), p + glm::vec3(0, 0.01f, 0.005f));
    }
  }
  expect_brute_force_answers(s);
}

TEST(Part2BvhBuild, BadOptionsAreRefused) {
  Scene s;
  add_triangle(&s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_THROW(Bvh(s, BvhOptions{BvhSplitMethod::sah, 0, 16, {}}), std::invalid_argument);
  EXPECT_THROW(Bvh(s, BvhOptions{BvhSplitMethod::sah, 1000, 16, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace pt
