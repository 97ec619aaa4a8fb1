// Not needed for the assignment: the definitions of framework/stats/variance_consistency.h.
#include "framework/stats/variance_consistency.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pt {

VarianceConsistencyResult check_variance_consistency(const RenderEstimate& render,
                                                     const RenderEstimate& reference,
                                                     const VarianceConsistencyOptions& o) {
  VarianceConsistencyResult r;
  char buf[300];
  if (render.width != reference.width || render.height != reference.height) {
    r.summary = "the render's size differs from the reference's";
    return r;
  }
  const int w = render.width, h = render.height;
  const size_t n = size_t(w) * size_t(h);
  if (render.variance.size() != n || render.count.size() != n || reference.variance.size() != n ||
      reference.mean.size() != n) {
    r.summary = "the render has no variance or count for every pixel";
    return r;
  }
  // The sample counts first: a count lower than the samples taken inflates the block mean's
  // variance (variance / count) just as an inflated variance does.
  if (o.expected_count > 0) {
    for (size_t i = 0; i < n; ++i) {
      float c = render.count[i];
      bool bad = !std::isfinite(c) || c < 1.0f ||
                 (o.adaptive ? c > float(o.expected_count) : c != float(o.expected_count));
      if (bad) {
        std::snprintf(buf, sizeof buf,
                      "pixel (%d, %d) says it took %g samples where the render was asked for %s%d",
                      int(i % size_t(w)), int(i / size_t(w)), double(c),
                      o.adaptive ? "at most " : "", o.expected_count);
        r.summary = buf;
        return r;
      }
    }
  }
  double sum_render = 0.0, sum_reference = 0.0;
  const int bs = std::max(1, o.block_size);
  for (int by = 0; by < h; by += bs) {
    for (int bx = 0; bx < w; bx += bs) {
      double vr[3] = {0, 0, 0}, vf[3] = {0, 0, 0}, mf[3] = {0, 0, 0};
      int pixels = 0;
      for (int y = by; y < std::min(h, by + bs); ++y) {
        for (int x = bx; x < std::min(w, bx + bs); ++x) {
          size_t i = size_t(y) * size_t(w) + size_t(x);
          for (int c = 0; c < 3; ++c) {
            double a = render.variance[i][c], b = reference.variance[i][c];
            if (!std::isfinite(a) || a < 0.0) {
              std::snprintf(buf, sizeof buf, "pixel (%d, %d) has a variance of %g", x, y, a);
              r.summary = buf;
              return r;
            }
            vr[c] += a;
            vf[c] += b;
            mf[c] += reference.mean[i][c];
          }
          ++pixels;
        }
      }
      ++r.blocks;
      bool failing = false;
      for (int c = 0; c < 3; ++c) {
        sum_render += vr[c];
        sum_reference += vf[c];
        double mean = mf[c] / pixels;
        double floor = o.relative_floor * mean * mean + 1e-12;
        double ratio = (vr[c] / pixels + floor) / (vf[c] / pixels + floor);
        r.worst_block_ratio = std::max(r.worst_block_ratio, ratio);
        failing = failing || ratio > o.max_block_ratio;
      }
      if (failing) ++r.failing_blocks;
    }
  }
  r.image_ratio = sum_reference > 0.0 ? sum_render / sum_reference : (sum_render > 0.0 ? INFINITY : 1.0);
  const bool image_ok = sum_render <= o.max_image_ratio * sum_reference + 1e-12 * double(n);
  const bool blocks_ok = r.failing_blocks <= int(o.max_failing_fraction * r.blocks);
  r.pass = image_ok && blocks_ok;
  if (!r.pass) {
    std::snprintf(buf, sizeof buf,
                  "the render's variance channels are not plausible for this estimator: %.3g "
                  "times the reference's over the image, more than %g times it in %d of %d blocks "
                  "(worst %.3g times); the block t-test would read a bias as noise, so the render "
                  "is not compared",
                  r.image_ratio, o.max_block_ratio, r.failing_blocks, r.blocks, r.worst_block_ratio);
    r.summary = buf;
  }
  return r;
}

}  // namespace pt
