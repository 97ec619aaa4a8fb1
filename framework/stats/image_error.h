// Not needed for the assignment.
// How far a render is from a reference image: relative MSE and RMSE, the figures of a
// convergence study.
#pragma once

#include "framework/image/image.h"

namespace pt {

/// The ε in relative MSE's denominator: keeps black reference pixels from dividing by zero and
/// from dominating the mean (0.01, as in the denoising and rendering literature's relMSE).
constexpr double kRelMseEpsilon = 0.01;

/// Mean over pixels and channels of (x − ref)² / (ref² + ε). Throws std::invalid_argument
/// naming both sizes when the images differ in size or are empty, or naming the pixel when a
/// value is not finite (an error that NaN would hide as "no error at all").
double relative_mse(const Image& image, const Image& reference, double epsilon = kRelMseEpsilon);

/// √(mean over pixels and channels of (x − ref)²), in the images' radiance units. Throws as
/// relative_mse does.
double rmse(const Image& image, const Image& reference);

}  // namespace pt
