#include "grader/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "framework/image/image.h"

namespace pt::grader {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The brightness ratio of a failing block as one number: the mean of its finite channels.
double block_ratio(const BlockDifference& b) {
  double sum = 0.0;
  int n = 0;
  for (int c = 0; c < 3; ++c) {
    if (std::isfinite(b.ratio[c])) {
      sum += b.ratio[c];
      ++n;
    }
  }
  return n ? sum / n : INFINITY;
}

/// A factor that a known mistake multiplies every pixel by, what to look at, and the kinds of
/// render whose estimator can make it (a hemisphere pdf only in a hemisphere render).
struct KnownFactor {
  double factor;
  const char* hint;
  bool hemisphere_only;
};

const KnownFactor kFactors[] = {
    {0.5, "half as bright everywhere: a factor 2 lost (the uniform hemisphere's pdf is 1/(2π), "
          "not 1/π), or the diffuse BSDF's albedo/(2π) in place of albedo/π?", true},
    {0.5, "half as bright everywhere: the diffuse BSDF's albedo/(2π) in place of albedo/π, or a "
          "density counted twice?", false},
    {2.0, "twice as bright everywhere: the hemisphere's pdf taken as 1/(4π), or a factor 2 "
          "counted twice?", true},
    {2.0, "twice as bright everywhere: a factor 2 counted twice, or the light counted both by "
          "light sampling and where a ray meets the emitter?", false},
    {1.0 / kPi, "about 1/π as bright everywhere: is the diffuse BSDF's albedo/π divided by π "
                "once more, or cos/pdf left out?", false},
    {kPi, "about π times too bright everywhere: did the diffuse BSDF forget its 1/π?", false},
    {1.0 / (2.0 * kPi), "about 1/(2π) as bright everywhere: is the division by the pdf left "
                        "out (the uniform hemisphere's pdf is 1/(2π))?", true},
    {2.0 * kPi, "about 2π times too bright: is the hemisphere's pdf multiplied instead of "
                "divided?", true},
};

/// Where a lit render is too bright in places only, what the kind of render can have wrong.
const char* too_bright_in_places(const std::string& kind) {
  if (kind == "direct")
    return "too bright in places: light leaking past an occluder or through a thin gap: shadow "
           "rays started with a fixed epsilon, or ending past the light? (start them with "
           "spawn_shadow_ray, which stops short of the light by its error bound)";
  if (kind == "hemisphere")
    return "too bright in places: light leaking past an occluder: hemisphere rays started with a "
           "fixed epsilon (use spawn_ray), or an emitter's back counted as glowing?";
  if (kind == "adaptive")
    return "too bright in places: is each pixel's value the mean of its estimate samples only "
           "(the decision samples kept out), over their own count?";
  return "too bright in places: is some light counted twice (emission added at every bounce as "
         "well as by light sampling), or is light leaking past an occluder (a fixed shadow-ray "
         "epsilon)?";
}

/// Where a lit render is too dark in places only, the same.
const char* too_dark_in_places(const std::string& kind) {
  if (kind == "direct" || kind == "hemisphere")
    return "light is missing in places: are shadow rays blocked (one that hits the surface it "
           "starts on, or a light's own panel taken for an occluder), or a light left out?";
  if (kind == "adaptive")
    return "light is missing in places: do pixels stop before their batch is done, or is the "
           "value averaged over the wrong count?";
  return "light is missing in places: is one kind of bounce left out (depth off by one, light "
         "seen through a mirror), a path ended without dividing by its q, or are shadow rays "
         "blocked?";
}

}  // namespace

std::string diagnose(const BlockTestResult& result, const std::string& kind) {
  if (result.pass) return "";
  if (result.nonfinite) {
    return kind == "normals"
               ? "a NaN or infinite pixel: a normal of zero length normalized (a degenerate "
                 "triangle, or barycentric weights that do not sum to one)?"
               : "a NaN or infinite pixel: look for a division by a zero pdf or cosine, or a "
                 "normalize() of a zero vector.";
  }
  if (result.failing.empty()) return "";
  if (kind == "normals") {
    // The normals view has no light: what differs is which surface a ray hits and its normal.
    double overall = (result.overall_ratio.x + result.overall_ratio.y + result.overall_ratio.z) / 3.0;
    if (std::isfinite(overall) && overall < 0.02)
      return "the image is (almost) black: no camera ray hits anything. Is this step implemented "
             "yet (see the \"not implemented\" lines), and do the camera rays point into the scene?";
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "the surfaces seen differ from the reference's in %zu of %d blocks (a normals "
                  "image: no lighting involved). Compare the diff image with the scene: a flipped "
                  "or shifted image (camera ray, pixel offset), the far root of a sphere, hits "
                  "outside [min_t, max_t], or a face normal where the vertex normals should be "
                  "interpolated?",
                  result.failing.size(), result.blocks);
    return buf;
  }
  std::vector<double> ratios;
  int darker = 0, brighter = 0;
  for (const BlockDifference& b : result.failing) {
    double r = block_ratio(b);
    if (!std::isfinite(r)) {
      ++brighter;
      continue;
    }
    ratios.push_back(r);
    (b.t < 0 ? darker : brighter)++;
  }
  double overall = (result.overall_ratio.x + result.overall_ratio.y + result.overall_ratio.z) / 3.0;
  const int failing = int(result.failing.size());
  const bool most_blocks = failing * 2 >= result.blocks;
  if (std::isfinite(overall) && overall < 0.02) {
    return "the image is (almost) black: is this part implemented yet? Look for \"not "
           "implemented\" messages above.";
  }
  if (!ratios.empty()) {
    std::vector<double> sorted = ratios;
    std::sort(sorted.begin(), sorted.end());
    double median = sorted[sorted.size() / 2];
    double spread = 0.0;  // relative spread of the failing blocks' ratios around their median
    for (double r : ratios) spread = std::max(spread, std::fabs(r / median - 1.0));
    const bool uniform = spread < 0.25 && (darker == 0 || brighter == 0);
    if (uniform && most_blocks) {
      for (const KnownFactor& k : kFactors) {
        if (k.hemisphere_only != (kind == "hemisphere") && (k.factor == 0.5 || k.factor == 2.0))
          continue;  // the same factor has a hint of each kind
        if (k.hemisphere_only && kind != "hemisphere") continue;
        if (std::fabs(std::log(median / k.factor)) < 0.12) return k.hint;
      }
      char buf[200];
      if (std::fabs(median - 1.0) < 0.15) {
        std::snprintf(buf, sizeof buf,
                      "slightly too %s everywhere (%.1f%%): a small bias, such as a missing "
                      "term, a clamped value or a wrong constant.",
                      median < 1.0 ? "dark" : "bright", std::fabs(median - 1.0) * 100.0);
      } else {
        std::snprintf(buf, sizeof buf, "%.2f times the reference's brightness everywhere: a "
                      "constant factor is off.", median);
      }
      return buf;
    }
    if (darker > 0 && brighter == 0) {
      char buf[400];
      std::snprintf(buf, sizeof buf,
                    "too dark in %d of %d blocks by different amounts (%.0f%% to %.0f%% of the "
                    "reference) while the rest match: %s",
                    failing, result.blocks, sorted.front() * 100.0, sorted.back() * 100.0,
                    too_dark_in_places(kind));
      return buf;
    }
    if (brighter > 0 && darker == 0) return too_bright_in_places(kind);
  }
  return "too bright in some places and too dark in others: compare the diff image with the "
         "scene (wrong normals, a flipped direction, or light leaking through surfaces?).";
}

double noise_ratio(const RenderEstimate& render, const RenderEstimate& reference) {
  if (render.variance.size() != reference.variance.size() || reference.variance.empty()) return NAN;
  double a = 0.0, b = 0.0;
  for (size_t i = 0; i < render.variance.size(); ++i) {
    a += double(render.variance[i].x) + render.variance[i].y + render.variance[i].z;
    b += double(reference.variance[i].x) + reference.variance[i].y + reference.variance[i].z;
  }
  return b > 0.0 ? a / b : NAN;
}

std::string check_noise(const RenderEstimate& render, const RenderEstimate& reference, double limit) {
  const double r = noise_ratio(render, reference);
  if (!std::isfinite(r)) return "";
  char buf[400];
  if (r > limit) {
    std::snprintf(buf, sizeof buf,
                  "the mean matches, but each sample is %.2f times as noisy as the reference's at "
                  "the same settings (at most %.2f): fewer samples taken than asked for? Is -l "
                  "(samples per area light) honoured, and are they averaged?",
                  r, limit);
    return buf;
  }
  if (r < 1.0 / limit) {
    std::snprintf(buf, sizeof buf,
                  "the mean matches, but each sample is only %.2f times as noisy as the "
                  "reference's at the same settings (at least %.2f): more samples taken than "
                  "asked for (a point light sampled -l times?), or samples that are not independent?",
                  r, 1.0 / limit);
    return buf;
  }
  return "";
}

void write_diff_image(const std::string& path, const RenderEstimate& render,
                      const RenderEstimate& reference, const BlockTestResult& result,
                      int block_size) {
  const int w = reference.width, h = reference.height;
  Image image(w, h, glm::vec3(0.5f));
  if (render.width == w && render.height == h && render.mean.size() == size_t(w) * h) {
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        size_t i = size_t(y) * w + x;
        float a = render.mean[i].x + render.mean[i].y + render.mean[i].z;
        float b = reference.mean[i].x + reference.mean[i].y + reference.mean[i].z;
        if (!std::isfinite(a)) {
          image.at(x, y) = glm::vec3(1.0f, 0.0f, 1.0f);  // magenta: NaN or infinite
          continue;
        }
        float d = (a - b) / std::max(b, 1e-3f);
        float k = std::min(1.0f, std::fabs(d) * 2.0f);
        glm::vec3 towards = d > 0 ? glm::vec3(1.0f, 0.1f, 0.1f) : glm::vec3(0.1f, 0.2f, 1.0f);
        image.at(x, y) = glm::vec3(0.5f) * (1.0f - k) + towards * k;
      }
    }
  }
  for (const BlockDifference& b : result.failing) {
    int x0 = b.block_x * block_size, y0 = b.block_y * block_size;
    int x1 = std::min(w, x0 + block_size) - 1, y1 = std::min(h, y0 + block_size) - 1;
    for (int x = x0; x <= x1; ++x) image.at(x, y0) = image.at(x, y1) = glm::vec3(1.0f, 0.9f, 0.0f);
    for (int y = y0; y <= y1; ++y) image.at(x0, y) = image.at(x1, y) = glm::vec3(1.0f, 0.9f, 0.0f);
  }
  write_image(path, image);
}

Comparison compare_render(const RenderEstimate& render, const RenderEstimate& reference,
                          const BlockTestOptions& options, const std::string& kind,
                          const std::string& diff_path) {
  Comparison c;
  c.test = block_t_test(render, reference, options);
  c.pass = c.test.pass;
  c.message = c.test.summary;
  if (c.pass) return c;
  std::string hint = diagnose(c.test, kind);
  if (!hint.empty()) c.message += ": " + hint;
  if (!diff_path.empty() && reference.width > 0 && reference.height > 0) {
    try {
      write_diff_image(diff_path, render, reference, c.test, options.block_size);
      c.diff_path = diff_path;
      c.message += " (diff image: " + diff_path + ")";
    } catch (const std::exception& e) {
      c.message += std::string(" (no diff image: ") + e.what() + ")";
    }
  }
  return c;
}

}  // namespace pt::grader
