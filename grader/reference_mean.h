// A reference made of several renders of the graded settings: their mean image, for an estimator
// whose expectation only such a render has (Part 5's course stopping rule is biased by design).
#pragma once

#include <vector>

#include "framework/image/render_estimate.h"

namespace pt::grader {

/// The mean of renders made with the same settings and other seeds: per pixel, the plain mean of
/// their means (each render is one draw of the estimator, whatever its sample count, so a render
/// that stopped early weighs as much as one that did not); the pooled variance of one sample
/// (each render's weighted by its count - 1); the total count, so that variance / count is about
/// the variance of that mean. Throws std::invalid_argument when there are none or their sizes
/// differ.
RenderEstimate mean_of_renders(const std::vector<RenderEstimate>& renders);

}  // namespace pt::grader
