// Part 2, step 2 (split): where a BVH node splits its primitives (midpoint, or the surface area
// heuristic).
#pragma once

#include <cstdint>
#include <limits>

#include "framework/math/bounds.h"

namespace pt {

/// Which way BVH construction chooses its splits.
enum class BvhSplitMethod {
  median,  ///< the first heuristic a student writes: the longest axis, at the centroid midpoint
  sah,     ///< the surface area heuristic over binned centroids (Wald 2007)
};

/// A plane: primitives whose centroid lies below `position` on `axis` go to the first child.
struct MidpointSplit {
  int axis = 0;
  float position = 0.0f;
};

/// Step 2 (split).
/// The midpoint split of a node whose primitives' centroids span `centroid_bounds`: the axis along
/// which the centroids spread the most, cut halfway.
MidpointSplit midpoint_split(const Bounds3& centroid_bounds);

/// One bin of the SAH: the primitives whose centroids fall into a slice of the node along one
/// axis, and the box around them.
struct SahBin {
  Bounds3 bounds;
  uint32_t count = 0;
};

/// The costs the SAH weighs: one traversal step against one primitive test.
struct SahCosts {
  float traversal = 1.0f;
  float intersection = 1.0f;
};

/// The best plane between bins: bins [0, plane] go to the first child, the rest to the second.
/// plane == -1 (and an infinite cost) when no plane leaves primitives on both sides.
struct SahSplit {
  int plane = -1;
  float cost = std::numeric_limits<float>::infinity();
};

/// The cheapest of the bin_count - 1 planes between `bins` by the surface area heuristic:
/// cost = traversal + intersection · (area(L)·count(L) + area(R)·count(R)) / parent_area,
/// where L and R are the boxes around the bins on either side. Planes with an empty side are
/// not splits. Ties go to the lower plane. bin_count <= kMaxSahBins.
SahSplit best_sah_split(const SahBin* bins, int bin_count, float parent_area, const SahCosts& costs);

inline constexpr int kMaxSahBins = 32;

}  // namespace pt
