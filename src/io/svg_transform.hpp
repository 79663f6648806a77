#pragma once
// The plane affine maps of SVG (its matrix(a b c d e f): x' = a x + c y + e,
// y' = b x + d y + f), the transform attribute's grammar (SVG 1.1 §7.6) and
// the viewBox-to-viewport map (SVG 1.1 §7.8, preserveAspectRatio §7.8): what
// places every element of a drawing in the root's user space.

#include <array>
#include <string_view>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau::io_detail {

/// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct SvgMatrix {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;

  Vec2 apply(Vec2 p) const { return Vec2{{a * p[0] + c * p[1] + e, b * p[0] + d * p[1] + f}}; }
  /// |det| of the linear part: how areas scale.
  double area_scale() const;
  bool is_invertible() const;
};

/// The composition (outer after inner): x -> outer(inner(x)).
SvgMatrix operator*(const SvgMatrix& outer, const SvgMatrix& inner);

SvgMatrix svg_translate(double tx, double ty);
SvgMatrix svg_scale(double sx, double sy);
/// Rotation by `degrees` about the origin (clockwise on screen, y down).
SvgMatrix svg_rotate(double degrees);

/// A transform list: matrix(a b c d e f), translate(tx [ty]), scale(sx [sy]),
/// rotate(angle [cx cy]), skewX(angle), skewY(angle), angles in degrees,
/// separated by comma-wsp, the first applied last (the list is one matrix:
/// their product left to right). Empty text is the identity. Errors name the
/// character: "transform, character 8 (')'): rotate takes 1 or 3 numbers,
/// found 2"; a list whose matrix is not invertible is accepted (SVG 2 draws
/// such an element as nothing; the caller decides).
Expected<SvgMatrix> parse_svg_transform(std::string_view text);

/// A viewBox "min-x min-y width height" (comma-wsp between): errors for the
/// wrong count, a negative width or height; a zero one is returned (SVG:
/// the element is then not drawn).
Expected<std::array<double, 4>> parse_svg_view_box(std::string_view text);

/// The map from a viewBox to the viewport (x, y, width, height) under
/// preserveAspectRatio `aspect` ("" is the default "xMidYMid meet"; "none",
/// x{Min,Mid,Max}Y{Min,Mid,Max} with "meet" or "slice"; a leading "defer" is
/// read and ignored). Errors name the value.
Expected<SvgMatrix> svg_view_box_map(const std::array<double, 4>& view_box, double x, double y, double width,
                                     double height, std::string_view aspect);

}  // namespace casteljau::io_detail
