#pragma once
// Text inside SVG and HTML: the one escaping function, io's (src/io/markup.hpp).

#include "../io/markup.hpp"

namespace casteljau::render::detail {

using io_detail::xml_escaped;

}  // namespace casteljau::render::detail
