#pragma once
// Text inside XML and HTML: one escaping function for every writer (the
// SVG drawings of io, the figures and gallery of render).

#include <string>
#include <string_view>

namespace casteljau::io_detail {

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

}  // namespace casteljau::io_detail
