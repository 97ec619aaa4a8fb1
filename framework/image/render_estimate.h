// Not needed for the assignment.
// A render as an estimator: what a film holds, an EXR carries and the graders compare.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

namespace pt {

/// Per pixel, the mean of its samples, the sample variance of one sample, and how many samples
/// were taken (row-major, top row first).
struct RenderEstimate {
  int width = 0, height = 0;
  std::vector<glm::vec3> mean;
  std::vector<glm::vec3> variance;
  std::vector<float> count;
};

}  // namespace pt
