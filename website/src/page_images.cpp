#include "website/src/page_images.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/common.hpp>

#include "framework/image/image.h"

namespace fs = std::filesystem;

namespace pt::web {

PixelSize image_size(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) {
    std::string why = OIIO::geterror();
    throw PageImageError(file.string() + ": cannot be read as an image" +
                         (why.empty() ? "" : ": " + why));
  }
  PixelSize s{in->spec().width, in->spec().height};
  in->close();
  return s;
}

Region parse_region(const std::string& text) {
  std::istringstream in(text);
  Region r;
  if (!(in >> r.x >> r.y >> r.w >> r.h) || !(in >> std::ws).eof()) {
    throw std::invalid_argument("a region is four numbers \"x y w h\", fractions of the image's "
                                "width and height, not '" + text + "'");
  }
  auto fraction = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; };
  if (!fraction(r.x) || !fraction(r.y) || !(r.w > 0.0) || !(r.h > 0.0) ||
      !(r.x + r.w <= 1.0 + 1e-9) || !(r.y + r.h <= 1.0 + 1e-9)) {
    throw std::invalid_argument("the region \"" + text + "\" is not inside the image: x, y, w, h "
                                "are fractions with x + w and y + h at most 1");
  }
  return r;
}

PixelRect region_pixels(const Region& region, PixelSize size) {
  PixelRect p;
  p.x = std::clamp(int(std::floor(region.x * size.width)), 0, std::max(0, size.width - 1));
  p.y = std::clamp(int(std::floor(region.y * size.height)), 0, std::max(0, size.height - 1));
  p.width = std::clamp(int(std::lround(region.w * size.width)), 1, size.width - p.x);
  p.height = std::clamp(int(std::lround(region.h * size.height)), 1, size.height - p.y);
  return p;
}

PixelSize write_zoomed_crop(const fs::path& from, const Region& region, int width,
                            const fs::path& to) {
  OIIO::ImageBuf source(from.string());
  if (!source.read(0, 0, true, OIIO::TypeDesc::UINT8)) {
    throw PageImageError(from.string() + ": cannot be read: " + source.geterror());
  }
  const OIIO::ImageSpec& spec = source.spec();
  PixelRect p = region_pixels(region, {spec.width, spec.height});
  const int factor = std::max(1, width / p.width);
  OIIO::ROI cut(p.x, p.x + p.width, p.y, p.y + p.height, 0, 1, 0, std::min(spec.nchannels, 3));
  OIIO::ImageBuf crop = OIIO::ImageBufAlgo::cut(source, cut);
  OIIO::ROI big(0, p.width * factor, 0, p.height * factor, 0, 1, 0, crop.nchannels());
  // resample without interpolation: every enlarged pixel is one source pixel, exactly.
  OIIO::ImageBuf zoomed = OIIO::ImageBufAlgo::resample(crop, false, big);
  if (zoomed.has_error() || !zoomed.write(to.string(), OIIO::TypeDesc::UINT8)) {
    throw PageImageError(to.string() + ": cannot write the zoomed crop: " + zoomed.geterror());
  }
  return {p.width * factor, p.height * factor};
}

void write_difference(const fs::path& minuend, const fs::path& subtrahend, const fs::path& to) {
  Image a, b;
  try {
    a = read_image(minuend.string());
    b = read_image(subtrahend.string());
  } catch (const ImageError& e) {
    throw PageImageError(e.what());
  }
  if (a.width() != b.width() || a.height() != b.height()) {
    throw PageImageError(minuend.string() + " is " + std::to_string(a.width()) + "x" +
                         std::to_string(a.height()) + " but " + subtrahend.string() + " is " +
                         std::to_string(b.width()) + "x" + std::to_string(b.height()) +
                         ": a difference needs two renders of the same size");
  }
  Image d(a.width(), a.height());
  for (size_t i = 0; i < d.pixels().size(); ++i) {
    d.pixels()[i] = glm::max(a.pixels()[i] - b.pixels()[i], glm::vec3(0.0f));
  }
  try {
    write_image(to.string(), d);
  } catch (const ImageError& e) {
    throw PageImageError(e.what());
  }
}

}  // namespace pt::web
