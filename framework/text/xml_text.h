// Not needed for the assignment.
// Text as XML or HTML character data, for the SVG plots and the write-up's pages alike.
#pragma once

#include <string>

namespace pt {

/// `text` with the five characters markup gives a meaning (& < > " ') written as references, so
/// it can stand in element content and in quoted attribute values.
inline std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace pt
