// Not needed for the assignment: the definitions of framework/stats/image_error.h.
#include "framework/stats/image_error.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pt {
namespace {

std::string size_text(const Image& image) {
  return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

/// Mean over pixels and channels of term(x, ref), with the checks both errors share.
template <typename Term>
double mean_over_channels(const Image& image, const Image& reference, Term term) {
  if (image.width() != reference.width() || image.height() != reference.height() ||
      image.pixels().empty())
    throw std::invalid_argument("image error: the image is " + size_text(image) +
                                " and the reference " + size_text(reference) +
                                "; they must be the same, non-empty size");
  double sum = 0.0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = image.at(x, y)[c], r = reference.at(x, y)[c];
        if (!std::isfinite(v) || !std::isfinite(r))
          throw std::invalid_argument("image error: pixel (" + std::to_string(x) + ", " +
                                      std::to_string(y) + ") channel " + std::to_string(c) +
                                      " is not finite in the " +
                                      (std::isfinite(v) ? "reference" : "image"));
        sum += term(v, r);
      }
  return sum / (3.0 * double(image.pixels().size()));
}

}  // namespace

double relative_mse(const Image& image, const Image& reference, double epsilon) {
  return mean_over_channels(image, reference, [epsilon](double v, double r) {
    return (v - r) * (v - r) / (r * r + epsilon);
  });
}

double rmse(const Image& image, const Image& reference) {
  return std::sqrt(
      mean_over_channels(image, reference, [](double v, double r) { return (v - r) * (v - r); }));
}

}  // namespace pt
