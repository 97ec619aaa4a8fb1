#include "website/src/figure_html.h"

#include <cmath>
#include <cstdio>

#include "framework/text/xml_text.h"

namespace pt::web {
namespace {

std::string percent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g%%", v * 100.0);
  return buf;
}

std::string size_attributes(const PixelSize& s) {
  return " width=\"" + std::to_string(s.width) + "\" height=\"" + std::to_string(s.height) + "\"";
}

}  // namespace

std::string image_html(const PageImage& image, const std::string& css_class) {
  std::string img = "<img src=\"" + xml_escape(image.src) + "\"" +
                    (css_class.empty() ? "" : " class=\"" + css_class + "\"") +
                    size_attributes(image.size) + " alt=\"" + xml_escape(image.alt) + "\">";
  if (!image.marked || image.size.width <= 0 || image.size.height <= 0) return img;
  const PixelRect& r = *image.marked;
  const double w = image.size.width, h = image.size.height;
  return "<span class=\"marked\">" + img + "<span class=\"zoom-box\" style=\"left:" +
         percent(r.x / w) + ";top:" + percent(r.y / h) + ";width:" + percent(r.width / w) +
         ";height:" + percent(r.height / h) + "\"></span></span>";
}

std::string slider_html(const PageImage& over, const std::string& over_label,
                        const PageImage& under, const std::string& under_label) {
  // The view is as wide as the images and never wider; both images fill it, and the one on
  // top is clipped at --split, which compare.js moves. A zoomed region is outlined on the view
  // itself, over both.
  PageImage top = over, bottom = under;
  top.marked.reset();
  bottom.marked.reset();
  std::string box;
  if (over.marked && over.size.width > 0 && over.size.height > 0) {
    const PixelRect& r = *over.marked;
    const double w = over.size.width, h = over.size.height;
    box = "<span class=\"zoom-box\" style=\"left:" + percent(r.x / w) + ";top:" + percent(r.y / h) +
          ";width:" + percent(r.width / w) + ";height:" + percent(r.height / h) + "\"></span>";
  }
  return "<div class=\"slider\" style=\"width:" + std::to_string(over.size.width) +
         "px\" data-split=\"50\">"
         "<div class=\"slider-view\" style=\"--split:50%\">" +
         image_html(bottom, "slider-under") + image_html(top, "slider-over") + box +
         "<span class=\"slider-line\" aria-hidden=\"true\"></span>"
         "<span class=\"slider-label left\">" + over_label + "</span>"
         "<span class=\"slider-label right\">" + under_label + "</span></div>"
         "<input type=\"range\" class=\"slider-range\" min=\"0\" max=\"100\" value=\"50\" "
         "step=\"0.5\" aria-label=\"Where the two renders meet: left " +
         xml_escape(over.alt) + ", right " + xml_escape(under.alt) + "\"></div>";
}

std::string rate_key_html(int max_samples, int width) {
  std::string max = max_samples > 0 ? thousands(max_samples) : "the maximum";
  std::string half = max_samples > 1 ? thousands(max_samples / 2) : "";
  return "<div class=\"rate-key\" style=\"width:" + std::to_string(width) +
         "px\" role=\"img\" aria-label=\"colour key: blue 0 samples, green " +
         (half.empty() ? "half" : half) + ", red " + max + " samples per pixel\">"
         "<span class=\"rate-key-bar\"></span><span class=\"rate-key-labels\"><span>0</span><span>" +
         half + "</span><span>" + max + "</span></span>"
         "<span class=\"rate-key-title\">samples a pixel took</span></div>";
}

std::string seconds_text(double seconds) {
  char buf[64];
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "? s";
  if (seconds < 10) {
    std::snprintf(buf, sizeof buf, "%.2f s", seconds);
  } else if (seconds < 100) {
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  } else {
    long s = std::lround(seconds);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  }
  return buf;
}

std::string thousands(long long n) {
  std::string digits = std::to_string(n < 0 ? -n : n);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return (n < 0 ? "-" : "") + out;
}

}  // namespace pt::web
