#pragma once
// Text inside SVG and HTML: one escaping function for both writers.

#include <string>
#include <string_view>

namespace casteljau::render::detail {

/// `text` with &, <, > and " replaced by entities, safe inside XML/HTML
/// elements and double-quoted attributes.
inline std::string xml_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace casteljau::render::detail
