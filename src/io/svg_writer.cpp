// SVG drawings written from curves (io/svg_writer.hpp says what).
#include "casteljau/io/svg_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/bounds.hpp"
#include "casteljau/ops/cubic_approximation.hpp"
#include "casteljau/version.hpp"
#include "markup.hpp"

namespace casteljau {
namespace {

/// "x y" of a model point in SVG's user space (y down: -y, exact), in
/// shortest round-trip form (fmt's {} for a double), -0 as 0.
void append_point(std::string& out, std::span<const double> p) {
  fmt::format_to(std::back_inserter(out), "{} {}", p[0] == 0.0 ? 0.0 : p[0], p[1] == 0.0 ? 0.0 : -p[1]);
}

bool same_element(const SvgCurve& a, const SvgCurve& b) {
  return a.line != 0 && a.line == b.line && a.id == b.id && a.element == b.element;
}

}  // namespace

std::string svg_path_data(const PiecewiseBezierCurve& curve, bool closed) {
  std::string out;
  const auto& pieces = curve.pieces();
  std::span<const double> current;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const PointArray& p = pieces[i].control_points();
    if (i == 0 || !std::equal(current.begin(), current.end(), p[0].begin())) {
      if (!out.empty()) out += ' ';
      out += 'M';
      append_point(out, p[0]);
    }
    const int degree = pieces[i].degree();
    out += degree == 3 ? " C" : degree == 2 ? " Q" : " L";
    for (std::size_t k = degree == 0 ? 0 : 1; k < p.size(); ++k) {
      if (k > 1) out += ' ';
      append_point(out, p[k]);
    }
    current = p[p.size() - 1];
  }
  if (closed) out += " Z";
  return out;
}

Expected<SvgText> write_svg_drawing(std::span<const SvgCurve> curves, Tolerance tolerance) {
  SvgText result;
  std::vector<PiecewiseBezierCurve> written;
  written.reserve(curves.size());
  double lower[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double upper[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  double widest = 0.0;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const CurveView view(curves[i].curve);
    if (view.dimension() != 2)
      return Error{fmt::format("curve {} lives in R^{}, SVG drawings are plane", i, view.dimension())};
    auto cubics = approximate_by_cubics(view, tolerance);
    if (!cubics) return with_context(cubics.error(), fmt::format("curve {}", i));
    // The pieces kept are the curve's pieces less those replaced.
    const std::size_t kept = breakpoints(view).size() - 1 - cubics->approximated_pieces;
    result.approximated_pieces += cubics->approximated_pieces;
    result.cubics += cubics->curve.pieces().size() - kept;
    result.deviation_bound = std::max(result.deviation_bound, cubics->deviation_bound);
    const Box box = bounding_box(view);
    for (int k = 0; k < 2; ++k) {
      lower[k] = std::min(lower[k], box.lower[k]);
      upper[k] = std::max(upper[k], box.upper[k]);
    }
    widest = std::max(widest, curves[i].stroke_width);
    written.push_back(std::move(cubics->curve));
  }
  if (curves.empty()) lower[0] = lower[1] = upper[0] = upper[1] = 0.0;
  // The page: the curves' box grown by half the widest stroke, its bottom
  // edge at y = 0 when no curve goes below it (a stroke along y = 0 shows
  // half its width), so that reading the file (y = page bottom - y_svg,
  // docs/formats.md "The frame") gives back the same doubles; a drawing
  // reaching below y = 0 has its page's bottom under its lowest stroke.
  const double margin = widest / 2.0;
  const double x = lower[0] - margin;
  const double top = upper[1] + margin, bottom = lower[1] >= 0.0 ? 0.0 : lower[1] - margin;
  const double width = std::max(upper[0] - lower[0] + 2 * margin, 1e-300);
  const double height = std::max(top - bottom, 1e-300);
  const double y = top == 0.0 ? 0.0 : -top;
  std::string& out = result.text;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" viewBox=\"{} {} {} {}\" "
                     "width=\"{}\" height=\"{}\">\n",
                     x, y, width, height, width, height);
  out += fmt::format("<!-- casteljau {}: {} curve{}", CASTELJAU_VERSION_STRING, curves.size(),
                     curves.size() == 1 ? "" : "s");
  if (result.approximated_pieces > 0)
    out += fmt::format("; {} rational or higher-degree piece{} replaced by {} cubics within {:.3g} (tolerance {:.3g})",
                       result.approximated_pieces, result.approximated_pieces == 1 ? "" : "s", result.cubics,
                       result.deviation_bound, tolerance.distance);
  else
    out += "; every piece exact";
  out += " -->\n";
  for (std::size_t i = 0; i < curves.size();) {
    std::size_t end = i + 1;
    while (end < curves.size() && same_element(curves[i], curves[end])) ++end;
    std::string data;
    for (std::size_t j = i; j < end; ++j) {
      if (!data.empty()) data += ' ';
      data += svg_path_data(written[j], curves[j].closed);
    }
    const SvgCurve& first = curves[i];
    out += "<path";
    if (!first.id.empty()) out += fmt::format(" id=\"{}\"", io_detail::xml_escaped(first.id));
    out += fmt::format(" d=\"{}\" fill=\"none\" stroke=\"black\" stroke-width=\"{}\"", data, first.stroke_width);
    if (first.fill_rule == FillRule::evenodd) out += " fill-rule=\"evenodd\"";
    out += "/>\n";
    i = end;
  }
  out += "</svg>\n";
  return result;
}

}  // namespace casteljau
