// Model JSON, writing (docs/formats.md, "Writing"): one object per model on
// one line, fields in the documented order, numbers in the shortest text
// that reads back to the same double, so parse_models_json(to_json(m)) gives
// m back bit for bit. The public entry points to_json and models_to_json.
#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <span>
#include <utility>
#include <variant>

#include "casteljau/io/model_json.hpp"

namespace casteljau {
namespace {

/// A coordinate in the shortest text that reads back to the same double.
/// -0 is written "-0.0": JSON readers take "-0" for the integer 0 and lose the sign.
void write_number(fmt::memory_buffer& out, double x) {
  if (x == 0.0 && std::signbit(x)) {
    fmt::format_to(std::back_inserter(out), "-0.0");
  } else {
    fmt::format_to(std::back_inserter(out), "{}", x);
  }
}

void write_numbers(fmt::memory_buffer& out, std::span<const double> values) {
  out.push_back('[');
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out.push_back(',');
    write_number(out, values[i]);
  }
  out.push_back(']');
}

void write_points(fmt::memory_buffer& out, const PointArray& points) {
  out.push_back('[');
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out.push_back(',');
    write_numbers(out, points[i]);
  }
  out.push_back(']');
}

void write_bezier(fmt::memory_buffer& out, const BezierCurve& curve) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bezier\",\"control_points\":");
  write_points(out, curve.control_points());
  if (curve.is_rational()) {
    fmt::format_to(std::back_inserter(out), ",\"weights\":");
    write_numbers(out, curve.weights());
  }
  out.push_back('}');
}

/// Always the full knot vector (n + p + 2 knots), whatever convention was read.
void write_bspline(fmt::memory_buffer& out, const BSplineCurve& curve) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bspline\",\"degree\":{},\"knots\":", curve.degree());
  write_numbers(out, curve.knots());
  fmt::format_to(std::back_inserter(out), ",\"control_points\":");
  write_points(out, curve.control_points());
  if (curve.is_rational()) {
    fmt::format_to(std::back_inserter(out), ",\"weights\":");
    write_numbers(out, curve.weights());
  }
  out.push_back('}');
}

/// "control_points": [[P_00, P_01, ...], ...] of a net, row by row, and,
/// for a rational surface, "weights" in the same shape.
void write_net(fmt::memory_buffer& out, const ControlNet& net, std::span<const double> weights) {
  fmt::format_to(std::back_inserter(out), "\"control_points\":[");
  for (std::size_t i = 0; i < net.rows(); ++i) {
    if (i > 0) out.push_back(',');
    out.push_back('[');
    for (std::size_t j = 0; j < net.columns(); ++j) {
      if (j > 0) out.push_back(',');
      write_numbers(out, net(i, j));
    }
    out.push_back(']');
  }
  out.push_back(']');
  if (weights.empty()) return;
  fmt::format_to(std::back_inserter(out), ",\"weights\":[");
  for (std::size_t i = 0; i < net.rows(); ++i) {
    if (i > 0) out.push_back(',');
    write_numbers(out, weights.subspan(i * net.columns(), net.columns()));
  }
  out.push_back(']');
}

void write_bezier_surface(fmt::memory_buffer& out, const BezierSurface& surface) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bezier_surface\",");
  write_net(out, surface.control_net(), surface.weights());
  out.push_back('}');
}

/// Always the full knot vectors, whatever convention was read.
void write_bspline_surface(fmt::memory_buffer& out, const BSplineSurface& surface) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bspline_surface\",\"degree\":[{},{}],\"knots\":[",
                 surface.degree_u(), surface.degree_v());
  write_numbers(out, surface.knots_u());
  out.push_back(',');
  write_numbers(out, surface.knots_v());
  fmt::format_to(std::back_inserter(out), "],");
  write_net(out, surface.control_net(), surface.weights());
  out.push_back('}');
}

/// The boundaries as the B-spline curves the patch holds (on [0,1]).
void write_coons(fmt::memory_buffer& out, const CoonsPatch& patch) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"coons\",\"blending\":\"{}\",\"boundaries\":{{",
                 blending_name(patch.blending()));
  const std::pair<const char*, const BSplineCurve*> boundaries[] = {
      {"u0", &patch.u0()}, {"u1", &patch.u1()}, {"v0", &patch.v0()}, {"v1", &patch.v1()}};
  for (std::size_t k = 0; k < 4; ++k) {
    if (k > 0) out.push_back(',');
    fmt::format_to(std::back_inserter(out), "\"{}\":", boundaries[k].first);
    write_bspline(out, *boundaries[k].second);
  }
  fmt::format_to(std::back_inserter(out), "}}}}");
}

void write_piecewise(fmt::memory_buffer& out, const PiecewiseBezierCurve& piecewise) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"piecewise_bezier\",\"pieces\":[");
  for (std::size_t i = 0; i < piecewise.pieces().size(); ++i) {
    if (i > 0) out.push_back(',');
    const auto& piece = piecewise.pieces()[i];
    if (piece.is_rational()) {
      write_bezier(out, piece);
    } else {
      write_points(out, piece.control_points());
    }
  }
  fmt::format_to(std::back_inserter(out), "]}}");
}

/// The writer of each Model alternative, by overload.
void write_one(fmt::memory_buffer& out, const BezierCurve& curve) { write_bezier(out, curve); }
void write_one(fmt::memory_buffer& out, const BSplineCurve& curve) { write_bspline(out, curve); }
void write_one(fmt::memory_buffer& out, const PiecewiseBezierCurve& curve) { write_piecewise(out, curve); }
void write_one(fmt::memory_buffer& out, const BezierSurface& surface) { write_bezier_surface(out, surface); }
void write_one(fmt::memory_buffer& out, const BSplineSurface& surface) { write_bspline_surface(out, surface); }
void write_one(fmt::memory_buffer& out, const CoonsPatch& patch) { write_coons(out, patch); }

void write_model(fmt::memory_buffer& out, const Model& model) {
  std::visit([&out](const auto& alternative) { write_one(out, alternative); }, model);
}

}  // namespace

std::string to_json(const Model& model) {
  fmt::memory_buffer out;
  write_model(out, model);
  return fmt::to_string(out);
}

std::string models_to_json(const std::vector<Model>& models) {
  fmt::memory_buffer out;
  if (models.size() == 1) {
    write_model(out, models.front());
  } else {
    fmt::format_to(std::back_inserter(out), "{{\"models\":[\n");
    for (std::size_t i = 0; i < models.size(); ++i) {
      write_model(out, models[i]);
      if (i + 1 < models.size()) out.push_back(',');
      out.push_back('\n');
    }
    out.push_back(']');
    out.push_back('}');
  }
  out.push_back('\n');
  return fmt::to_string(out);
}

}  // namespace casteljau
