// Not needed for the assignment.
// What the image library does for the framework, behind a small interface: the framework's image
// functions call it, and it lives in a module of its own (image/oiio/) opened on first use, so a
// command that reads and writes no image never loads the image library's shared objects.
#pragma once

#include <string>
#include <vector>

#include "framework/image/image.h"

namespace pt {

/// How write() gets its pixels: 8-bit sRGB-encoded values, or linear 32-bit floats.
enum class StoredPixels { srgb_bytes, linear_floats };

/// Reads and writes image files. Implemented by the image module (OpenImageIO); the framework
/// gets one from load_image_codec(). Errors come back as text, so nothing is thrown across the
/// module's boundary.
class ImageCodec {
 public:
  virtual ~ImageCodec() = default;
  /// Writes width × height pixels of channels.size() interleaved values each, in `pixels`
  /// (unsigned char or float, as `stored` says), to `path`, in the format its extension names.
  /// Returns "" on success, else what went wrong (without the path).
  virtual std::string write(const std::string& path, int width, int height,
                            const std::vector<std::string>& channels, StoredPixels stored,
                            const void* pixels) const = 0;
  /// Reads every channel of the file at `path` as float into *image. Returns "" on success,
  /// else what went wrong (without the path).
  virtual std::string read(const std::string& path, ChannelImage* image) const = 0;
};

/// The image module's entry point, looked up by this name: bumped with any change to ImageCodec,
/// so a stale module is refused rather than called through a different layout.
#define PT_IMAGE_CODEC_ENTRY "pt_image_codec_v1"
extern "C" {
using ImageCodecEntry = const ImageCodec* (*)();
}

/// The file name of the image module, as the build makes it.
constexpr const char* kImageModuleName = "pt_image_oiio.so";

/// The image module's codec, opened on first use and kept for the life of the process (the
/// dynamic loader keeps it; asking again costs a lookup). It is looked for in the folder named by
/// the environment variable PT_IMAGE_MODULE_DIR when set, else beside the running executable,
/// else where this build put it. Throws ImageError naming `path` (the image that needed it) and
/// every place looked in, when none has a module that loads.
const ImageCodec& load_image_codec(const std::string& path);

}  // namespace pt
