// Not needed for the assignment.
// The image module: ImageCodec over OpenImageIO. Built as a shared module of its own, the only
// code linked against OpenImageIO, and opened by the framework when an image is first read or
// written (see image/image_codec.h).
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "framework/image/image_codec.h"

namespace pt {
namespace {

class OiioCodec final : public ImageCodec {
 public:
  std::string write(const std::string& path, int width, int height,
                    const std::vector<std::string>& channels, StoredPixels stored,
                    const void* pixels) const override {
    const OIIO::TypeDesc type =
        stored == StoredPixels::srgb_bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(width, height, int(channels.size()), type);
    spec.channelnames = channels;
    spec.attribute("oiio:ColorSpace", stored == StoredPixels::srgb_bytes ? "sRGB" : "Linear");
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return "cannot write: " + OIIO::geterror();
    if (!out->open(path, spec)) return "cannot write: " + out->geterror();
    bool ok = out->write_image(type, pixels);
    ok = out->close() && ok;
    return ok ? std::string() : "cannot write: " + out->geterror();
  }

  std::string read(const std::string& path, ChannelImage* image) const override {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return "cannot read: " + OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    image->width = spec.width;
    image->height = spec.height;
    image->channels = spec.channelnames;
    image->values.assign(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels), 0.0f);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image->values.data()))
      return "cannot read: " + in->geterror();
    in->close();
    return std::string();
  }
};

}  // namespace
}  // namespace pt

extern "C" __attribute__((visibility("default"))) const pt::ImageCodec* pt_image_codec_v1() {
  static const pt::OiioCodec codec;  // stateless; lives as long as the module
  return &codec;
}
