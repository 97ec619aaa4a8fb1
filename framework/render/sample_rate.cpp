// Not needed for the assignment: the definitions of framework/render/sample_rate.h.
#include "framework/render/sample_rate.h"

#include <algorithm>
#include <cmath>

namespace pt {

glm::vec3 sample_rate_colour(float r) {
  r = std::clamp(r, 0.0f, 1.0f);
  // Blue -> green -> red, piecewise linear in display (sRGB) values.
  glm::vec3 display = r < 0.5f ? glm::vec3(0.0f, 2.0f * r, 1.0f - 2.0f * r)
                               : glm::vec3(2.0f * r - 1.0f, 2.0f - 2.0f * r, 0.0f);
  auto linear = [](float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  return {linear(display.x), linear(display.y), linear(display.z)};
}

Image sample_rate_image(const Film& film, int max_samples) {
  Image image(film.width(), film.height());
  const float max = max_samples > 0 ? float(max_samples) : 1.0f;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      image.at(x, y) = sample_rate_colour(float(film.at(x, y).samples_taken()) / max);
  return image;
}

}  // namespace pt
