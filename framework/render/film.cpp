// Not needed for the assignment: the definitions of framework/render/film.h.
#include "framework/render/film.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "framework/image/estimate_exr.h"

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

namespace {

bool is_exr(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower((unsigned char)c));
  return ext == ".exr";
}

}  // namespace

void write_film(const std::string& path, const Film& film) {
  const std::vector<PixelStats>& px = film.pixels();
  if (!is_exr(path)) {
    write_png(path, film.width(), film.height(), [&](size_t i) { return glm::vec3(px[i].mean); });
    return;
  }
  ChannelImage image = estimate_channels(film.width(), film.height());
  const size_t n = image.channels.size();
  for (size_t i = 0; i < px.size(); ++i) {
    float* v = &image.values[i * n];
    const glm::dvec3 var = px[i].variance();
    for (int c = 0; c < 3; ++c) v[c] = float(px[i].mean[c]), v[3 + c] = float(var[c]);
    v[6] = float(px[i].count);
  }
  write_exr(path, image);
}

uint64_t film_peak_bytes(int width, int height, const std::string& output_path, bool adaptive) {
  const uint64_t pixels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
  uint64_t output = is_exr(output_path) ? 7 * sizeof(float) : 3;
  if (adaptive) output = std::max<uint64_t>(output, sizeof(glm::vec3) + 3);
  return pixels * (Film::kBytesPerPixel + output);
}

}  // namespace pt
