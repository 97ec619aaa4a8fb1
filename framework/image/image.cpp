// Not needed for the assignment: the definitions of framework/image/image.h.
#include "framework/image/image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "framework/image/image_codec.h"

namespace pt {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void check_writable_target(const std::string& path) {
  if (!is_supported_image_extension(path)) {
    std::string ext = std::filesystem::path(path).extension().string();
    throw ImageError(path, ext.empty() ? "no file extension: use .png or .exr"
                                       : "unknown image extension '" + ext + "': use .png or .exr");
  }
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
    throw ImageError(path, "cannot write: folder '" + parent.string() + "' does not exist");
}

// Writes interleaved pixels through the image module; `stored` says how they are held in memory
// (and so in the file).
void write_pixels(const std::string& path, int width, int height,
                  const std::vector<std::string>& channels, StoredPixels stored, const void* data) {
  const std::string error =
      load_image_codec(path).write(path, width, height, channels, stored, data);
  if (!error.empty()) throw ImageError(path, error);
}

void check_size(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0)
    throw ImageError(path, "cannot write an empty image (" + std::to_string(width) + "x" +
                               std::to_string(height) + ")");
}

}  // namespace

Image::Image(int width, int height, glm::vec3 fill)
    : width_(width), height_(height), pixels_(size_t(std::max(width, 0)) * size_t(std::max(height, 0)), fill) {}

ChannelImage::ChannelImage(int w, int h, std::vector<std::string> names)
    : width(w), height(h), channels(std::move(names)),
      values(size_t(std::max(w, 0)) * size_t(std::max(h, 0)) * channels.size(), 0.0f) {}

int ChannelImage::channel_index(const std::string& name) const {
  for (size_t i = 0; i < channels.size(); ++i)
    if (channels[i] == name) return int(i);
  return -1;
}

float srgb_encode(float linear) {
  if (!(linear > 0.0f)) return 0.0f;  // also NaN
  if (linear >= 1.0f) return 1.0f;
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
  if (!(encoded > 0.0f)) return 0.0f;
  if (encoded >= 1.0f) return 1.0f;
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

bool is_supported_image_extension(const std::string& path) {
  std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".exr";
}

void write_png(const std::string& path, int width, int height,
               const std::function<glm::vec3(size_t)>& linear) {
  check_writable_target(path);
  check_size(path, width, height);
  if (lower_extension(path) != ".png") throw ImageError(path, "write_png needs a .png file");
  const size_t pixels = size_t(width) * size_t(height);
  std::vector<unsigned char> bytes(pixels * 3);
  for (size_t i = 0; i < pixels; ++i) {
    const glm::vec3 v = linear(i);
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + size_t(c)] = (unsigned char)std::lround(255.0f * srgb_encode(v[c]));
  }
  write_pixels(path, width, height, {"R", "G", "B"}, StoredPixels::srgb_bytes, bytes.data());
}

void write_image(const std::string& path, const Image& image) {
  check_writable_target(path);
  check_size(path, image.width(), image.height());
  if (lower_extension(path) == ".png") {
    write_png(path, image.width(), image.height(), [&](size_t i) { return image.pixels()[i]; });
  } else {
    write_pixels(path, image.width(), image.height(), {"R", "G", "B"}, StoredPixels::linear_floats,
                 image.pixels().data());
  }
}

void write_exr(const std::string& path, const ChannelImage& image) {
  if (lower_extension(path) != ".exr")
    throw ImageError(path, "channels beyond RGB need an .exr file");
  check_writable_target(path);
  check_size(path, image.width, image.height);
  if (image.channels.empty()) throw ImageError(path, "cannot write an image with no channels");
  if (image.values.size() != size_t(image.width) * size_t(image.height) * image.channels.size())
    throw ImageError(path, "channel data does not match the image size");
  write_pixels(path, image.width, image.height, image.channels, StoredPixels::linear_floats,
               image.values.data());
}

ChannelImage read_channels(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw ImageError(path, "no such file");
  ChannelImage image;
  const std::string error = load_image_codec(path).read(path, &image);
  if (!error.empty()) throw ImageError(path, error);
  return image;
}

Image read_image(const std::string& path) {
  ChannelImage channels = read_channels(path);
  const bool srgb = lower_extension(path) != ".exr";
  int rgb[3];
  const int n = int(channels.channels.size());
  int r = channels.channel_index("R"), g = channels.channel_index("G"), b = channels.channel_index("B");
  if (r >= 0 && g >= 0 && b >= 0) {
    rgb[0] = r, rgb[1] = g, rgb[2] = b;
  } else if (n >= 3) {
    rgb[0] = 0, rgb[1] = 1, rgb[2] = 2;
  } else if (n >= 1) {
    rgb[0] = rgb[1] = rgb[2] = 0;  // grey (with or without alpha)
  } else {
    throw ImageError(path, "the image has no channels");
  }
  Image image(channels.width, channels.height);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        float v = channels.at(x, y, rgb[c]);
        image.at(x, y)[c] = srgb ? srgb_decode(v) : v;
      }
  return image;
}

}  // namespace pt
