#include "app/accelerator.h"

#include <cstdio>
#include <memory>
#include <string>

#include "parts/2-bvh/bvh.h"
#include "pipeline/1-raygen/scene_intersect.h"
#ifdef PT_HAVE_WIDE_BVH
#include "app/accel/wide_bvh.h"
#endif

namespace pt {

namespace {

/// The binary tree's options the command line asked for (--bvh, --leaf-size).
BvhOptions bvh_options(const RenderSettings& settings) {
  BvhOptions options;
  options.split =
      settings.accel == AccelKind::bvh_median ? BvhSplitMethod::median : BvhSplitMethod::sah;
  options.max_leaf_size = settings.bvh_leaf_size;
  return options;
}

}  // namespace

std::unique_ptr<RayQuery> make_ray_query(const RenderSettings& settings, const Scene& scene) {
  if (settings.accel == AccelKind::brute_force) return std::make_unique<BruteForce>(scene);
  auto binary = std::make_unique<Bvh>(scene, bvh_options(settings));
#ifdef PT_HAVE_WIDE_BVH
  static_assert(kWideBvhWidth == WideNode::kWidth, "--bvh-width must name the wide tree's width");
  if (settings.bvh_width == kWideBvhWidth) return std::make_unique<WideBvh>(scene, *binary);
#endif
  return binary;  // --bvh-width 2, or a handout, which has no wide tree
}

std::string describe_bvh(const RenderSettings& settings, const Scene& scene) {
  if (settings.accel == AccelKind::brute_force) return "accelerator: none (brute force)\n";
  const Bvh binary(scene, bvh_options(settings));
  const BvhStats& s = binary.stats();
  char line[512];
  std::snprintf(line, sizeof line,
                "bvh: %s, leaf size %d: %u nodes, %u leaves (mean %.2f, max %u primitives), "
                "depth %u, SAH cost %.2f, built in %.1f ms\n",
                s.split == BvhSplitMethod::sah ? "sah" : "median", settings.bvh_leaf_size, s.nodes,
                s.leaves, s.mean_leaf_size, s.max_leaf_size, s.depth, s.sah_cost, s.build_ms);
  std::string text = line;
  if (settings.bvh_width == kWideBvhWidth) {
#ifdef PT_HAVE_WIDE_BVH
    const WideBvh wide(scene, binary);  // kept alive: stats() is a reference into it
    const WideBvhStats& w = wide.stats();
    std::snprintf(line, sizeof line,
                  "bvh width %d (traced): %u nodes (mean %.2f children), depth %u, collapsed in "
                  "%.1f ms\n",
                  kWideBvhWidth, w.nodes, w.mean_children, w.depth, w.build_ms);
    text += line;
#else
    text += "bvh width " + std::to_string(kWideBvhWidth) +
            ": not in this build (the handout); the binary tree above is traced\n";
#endif
  }
  return text;
}

}  // namespace pt
