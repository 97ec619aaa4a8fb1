#include "framework/render/film.h"

#include <algorithm>

namespace pt {

Film::Film(int width, int height)
    : width_(width), height_(height),
      pixels_(size_t(std::max(width, 0)) * size_t(std::max(height, 0))) {}

Image Film::mean_image() const {
  Image image(width_, height_);
  for (size_t i = 0; i < pixels_.size(); ++i) image.pixels()[i] = glm::vec3(pixels_[i].mean);
  return image;
}

RenderEstimate Film::estimate() const {
  RenderEstimate e;
  e.width = width_;
  e.height = height_;
  e.mean.reserve(pixels_.size());
  e.variance.reserve(pixels_.size());
  e.count.reserve(pixels_.size());
  for (const PixelStats& p : pixels_) {
    e.mean.emplace_back(p.mean);
    e.variance.emplace_back(p.variance());
    e.count.push_back(float(p.count));
  }
  return e;
}

long Film::total_samples() const {
  long total = 0;
  for (const PixelStats& p : pixels_) total += p.samples_taken();
  return total;
}

}  // namespace pt
