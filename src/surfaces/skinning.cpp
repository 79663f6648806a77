// Skinning through section curves (The NURBS Book §10.3).
#include "casteljau/surfaces/skinning.hpp"

#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/interpolation/spline_interpolation.hpp"
#include "../core/number_text.hpp"
#include "construction_support.hpp"

namespace casteljau {
namespace {

/// The checks of skin() on the count of sections and degree_v.
Status check_counts(std::size_t sections, int degree_v) {
  if (sections < 2) {
    return Error{"skinning needs at least 2 sections, found " + std::to_string(sections)};
  }
  if (degree_v < 1) return Error{"degree_v is " + std::to_string(degree_v) + ", it must be >= 1"};
  if (static_cast<std::size_t>(degree_v) + 1 > sections) {
    return Error{"degree_v " + std::to_string(degree_v) + " needs at least " + std::to_string(degree_v + 1) +
                 " sections, found " + std::to_string(sections)};
  }
  return {};
}

/// v_k of compatible sections: column i of the control points across them.
Expected<std::vector<double>> parameters_of_compatible(const std::vector<BSplineCurve>& sections,
                                                       Parameterization parameterization) {
  const std::size_t count = sections[0].control_points().size();
  std::vector<PointArray> columns;
  columns.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    PointArray column = PointArray::zeros(sections[0].dimension(), 0);
    for (const auto& section : sections) column.push_back(section.control_points()[i]);
    columns.push_back(std::move(column));
  }
  return detail::averaged_parameters(columns, parameterization, "section");
}

}  // namespace

Expected<std::vector<double>> section_parameters(std::span<const BSplineCurve> sections,
                                                 Parameterization parameterization) {
  if (sections.size() < 2) {
    return Error{"skinning needs at least 2 sections, found " + std::to_string(sections.size())};
  }
  auto compatible = detail::make_compatible_named(sections, "section");
  if (!compatible) return compatible.error();
  return parameters_of_compatible(*compatible, parameterization);
}

Expected<BSplineSurface> skin(std::span<const BSplineCurve> sections, int degree_v, Parameterization parameterization) {
  if (auto ok = check_counts(sections.size(), degree_v); !ok) return ok.error();
  auto compatible = detail::make_compatible_named(sections, "section");
  if (!compatible) return compatible.error();
  auto parameters = parameters_of_compatible(*compatible, parameterization);
  if (!parameters) return parameters.error();

  // Section k as one wide point: its whole (homogeneous) control polygon.
  const bool rational = (*compatible)[0].is_rational();
  PointArray wide;
  for (const auto& section : *compatible) {
    const PointArray polygon = rational ? homogeneous_points(section) : section.control_points();
    if (wide.empty()) wide = PointArray::zeros(static_cast<int>(polygon.coordinates().size()), 0);
    wide.push_back(polygon.coordinates());
  }
  auto curve = interpolate_bspline(wide, *parameters, degree_v);
  if (!curve) return with_context(curve.error(), "skinning");

  const BSplineCurve& first = (*compatible)[0];
  const std::size_t rows = first.control_points().size();
  const std::size_t columns = curve->control_points().size();
  const int d = first.dimension();
  const std::size_t w = static_cast<std::size_t>(d + (rational ? 1 : 0));
  std::vector<double> coordinates(rows * columns * w);
  for (std::size_t j = 0; j < columns; ++j) {
    const auto column = curve->control_points()[j];
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t c = 0; c < w; ++c) coordinates[(i * columns + j) * w + c] = column[i * w + c];
      if (rational && !(coordinates[(i * columns + j) * w + w - 1] > 0.0)) {
        return Error{"the skinned surface's weight [" + std::to_string(i) + "][" + std::to_string(j) + "] is " +
                     detail::number_text(coordinates[(i * columns + j) * w + w - 1]) +
                     ": the sections' weights vary too much for degree_v " + std::to_string(degree_v) +
                     " (try a lower degree_v or sections with closer weights)"};
      }
    }
  }
  ControlNet net = ControlNet::from_trusted(rows, columns, PointArray::from_trusted(static_cast<int>(w), std::move(coordinates)));
  std::vector<double> knots_u(first.knots().begin(), first.knots().end());
  std::vector<double> knots_v(curve->knots().begin(), curve->knots().end());
  if (rational) return from_homogeneous(first.degree(), degree_v, std::move(knots_u), std::move(knots_v), net);
  return BSplineSurface::from_trusted(first.degree(), degree_v, std::move(knots_u), std::move(knots_v), std::move(net));
}

}  // namespace casteljau
