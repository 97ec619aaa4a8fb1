// Not needed for the assignment: the definitions of framework/lights/environment_map.h.
#include "framework/lights/environment_map.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "framework/image/image.h"
#include "framework/sampling/warp.h"

namespace pt {

bool EnvironmentMap::load(const std::string& path, std::string* error) {
  ChannelImage image;
  try {
    image = read_channels(path);
  } catch (const ImageError& e) {
    // e.what() is "PATH: why"; say it once, as what an environment map needs.
    *error = path + ": cannot read the environment map: " +
             std::string(e.what()).substr(std::min(e.path().size() + 2, std::strlen(e.what())));
    return false;
  }
  const int channels = int(image.channels.size());
  if (image.width < 2 || image.height < 1 || channels < 1) {
    *error = path + ": the environment map is empty";
    return false;
  }
  std::vector<glm::vec3> rgb(size_t(image.width) * image.height);
  for (size_t i = 0; i < rgb.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      float v = image.values[i * channels + std::min(c, channels - 1)];
      if (!std::isfinite(v) || v < 0.0f) {
        *error = path + ": pixel " + std::to_string(i % image.width) + "," +
                 std::to_string(i / image.width) + " is negative or not finite";
        return false;
      }
      rgb[i][c] = v;
    }
  set_pixels(image.width, image.height, std::move(rgb));
  return true;
}

void EnvironmentMap::set_pixels(int width, int height, std::vector<glm::vec3> rgb) {
  width_ = width;
  height_ = height;
  pixels_ = std::move(rgb);
  build_distribution();
}

void EnvironmentMap::build_distribution() {
  // Distribution2D's row 0 is v = 0, which direction_to_uv puts at the top (+y): the same order
  // as the image's rows.
  std::vector<float> weight(pixels_.size());
  for (int y = 0; y < height_; ++y) {
    float sin_theta = std::sin(kPi * (float(y) + 0.5f) / float(height_));
    for (int x = 0; x < width_; ++x) {
      const glm::vec3& c = pixels_[size_t(y) * width_ + x];
      weight[size_t(y) * width_ + x] = (0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b) * sin_theta;
    }
  }
  distribution_ = Distribution2D(weight, width_, height_);
}

glm::vec2 EnvironmentMap::direction_to_uv(const glm::vec3& d) {
  float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
  float phi = std::atan2(d.z, -d.x);
  if (phi < 0) phi += 2.0f * kPi;
  return {std::min(phi * kInv2Pi, 0x1.fffffep-1f), std::min(theta * kInvPi, 0x1.fffffep-1f)};
}

glm::vec3 EnvironmentMap::uv_to_direction(glm::vec2 uv) {
  float phi = uv.x * 2.0f * kPi, theta = uv.y * kPi;
  float s = std::sin(theta);
  return {-s * std::cos(phi), std::cos(theta), s * std::sin(phi)};
}

glm::vec3 EnvironmentMap::radiance(const glm::vec3& dir) const {
  if (pixels_.empty()) return glm::vec3(0.0f);
  glm::vec2 uv = direction_to_uv(dir);
  int x = std::clamp(int(uv.x * width_), 0, width_ - 1);
  int y = std::clamp(int(uv.y * height_), 0, height_ - 1);
  return pixels_[size_t(y) * width_ + x];
}

glm::vec3 EnvironmentMap::sample(glm::vec2 u, float* pdf) const {
  float map_pdf = 0.0f;
  glm::vec2 uv = distribution_.sample_continuous(u, &map_pdf);
  float sin_theta = std::sin(uv.y * kPi);
  // dω = sinθ dθ dφ = 2π² sinθ du dv.
  *pdf = (sin_theta > 0.0f && map_pdf > 0.0f) ? map_pdf / (2.0f * kPi * kPi * sin_theta) : 0.0f;
  return uv_to_direction(uv);
}

float EnvironmentMap::pdf(const glm::vec3& dir) const {
  glm::vec2 uv = direction_to_uv(dir);
  float sin_theta = std::sin(uv.y * kPi);
  if (!(sin_theta > 0.0f)) return 0.0f;
  return distribution_.pdf(uv) / (2.0f * kPi * kPi * sin_theta);
}

}  // namespace pt
