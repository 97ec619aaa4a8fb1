// Not needed for the assignment.
// Images in memory and on disk: linear float RGB, written as sRGB PNG or linear float EXR.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace pt {

/// An image file that cannot be written or read. what() reads "PATH: what is wrong".
class ImageError : public std::runtime_error {
 public:
  ImageError(const std::string& path, const std::string& message)
      : std::runtime_error(path + ": " + message), path_(path) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Linear float RGB, width × height, row-major with the top row first (the order image files
/// use, so pixel (x, y) of the render is pixel (x, y) of the file).
class Image {
 public:
  Image() = default;
  Image(int width, int height, glm::vec3 fill = glm::vec3(0.0f));

  int width() const { return width_; }
  int height() const { return height_; }
  glm::vec3& at(int x, int y) { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  const glm::vec3& at(int x, int y) const { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  const std::vector<glm::vec3>& pixels() const { return pixels_; }
  std::vector<glm::vec3>& pixels() { return pixels_; }

 private:
  int width_ = 0, height_ = 0;
  std::vector<glm::vec3> pixels_;
};

/// A float image with any number of named channels, interleaved per pixel (R,G,B,varR,...):
/// what an EXR holds when a render carries its per-pixel variance and sample count along.
struct ChannelImage {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> values;  ///< width · height · channels.size(), row-major, top row first

  ChannelImage() = default;
  ChannelImage(int width, int height, std::vector<std::string> channels);
  float& at(int x, int y, int channel) { return values[index(x, y, channel)]; }
  float at(int x, int y, int channel) const { return values[index(x, y, channel)]; }
  /// Index of the channel called `name`, or -1.
  int channel_index(const std::string& name) const;

 private:
  size_t index(int x, int y, int c) const {
    return (size_t(y) * size_t(width) + size_t(x)) * channels.size() + size_t(c);
  }
};

/// The sRGB transfer curve (IEC 61966-2-1), on [0, 1]; encode clamps, and maps NaN to 0.
float srgb_encode(float linear);
float srgb_decode(float encoded);

/// Writes by extension (case-insensitive): .png as 8-bit sRGB (clamped, rounded), .exr as
/// linear 32-bit float. Throws ImageError naming the path for another extension, an empty
/// image, or a file that cannot be written.
void write_image(const std::string& path, const Image& image);

/// Writes `width` × `height` pixels as an 8-bit sRGB .png, asking `linear` for pixel i (row-major,
/// top row first) as it converts, so that the only image-sized buffer is the 3 bytes a pixel of
/// the PNG itself. Throws ImageError as write_image does.
void write_png(const std::string& path, int width, int height,
               const std::function<glm::vec3(size_t)>& linear);

/// Reads a .png (sRGB decoded to linear) or an .exr (its R, G, B channels, or its first
/// channels when they are not named so); grey images are spread to RGB. Throws ImageError.
Image read_image(const std::string& path);

/// Writes every channel of `image` to an .exr as 32-bit float. Throws ImageError.
void write_exr(const std::string& path, const ChannelImage& image);

/// Reads every channel of an .exr (or any file OpenImageIO reads) as float. Find channels with
/// channel_index: EXR files keep them sorted by name, so the order may differ from the writer's.
/// Throws ImageError.
ChannelImage read_channels(const std::string& path);

/// Whether write_image knows the extension of `path` (".png" or ".exr", any case).
bool is_supported_image_extension(const std::string& path);

}  // namespace pt
