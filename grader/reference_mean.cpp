#include "grader/reference_mean.h"

#include <stdexcept>

namespace pt::grader {

RenderEstimate mean_of_renders(const std::vector<RenderEstimate>& renders) {
  if (renders.empty()) throw std::invalid_argument("a reference is the mean of at least one render");
  const RenderEstimate& first = renders.front();
  const size_t pixels = size_t(first.width) * size_t(first.height);
  for (const RenderEstimate& r : renders)
    if (r.width != first.width || r.height != first.height || r.mean.size() != pixels ||
        r.variance.size() != pixels || r.count.size() != pixels)
      throw std::invalid_argument("the renders a reference averages differ in size");
  RenderEstimate out;
  out.width = first.width;
  out.height = first.height;
  out.mean.assign(pixels, glm::vec3(0.0f));
  out.variance.assign(pixels, glm::vec3(0.0f));
  out.count.assign(pixels, 0.0f);
  for (size_t i = 0; i < pixels; ++i) {
    glm::dvec3 mean(0.0), squares(0.0);
    double count = 0.0, dof = 0.0;
    for (const RenderEstimate& r : renders) {
      mean += glm::dvec3(r.mean[i]);
      count += double(r.count[i]);
      if (r.count[i] > 1.0f) {
        squares += glm::dvec3(r.variance[i]) * double(r.count[i] - 1.0f);
        dof += double(r.count[i] - 1.0f);
      }
    }
    out.mean[i] = glm::vec3(mean / double(renders.size()));
    out.variance[i] = dof > 0.0 ? glm::vec3(squares / dof) : glm::vec3(0.0f);
    out.count[i] = float(count);
  }
  return out;
}

}  // namespace pt::grader
