// Curves and surfaces to a STEP file (io/cad_exchange.hpp says what).
// ISO 10303-21 (the exchange structure: header, entity instances #n=...;,
// complex instances as their partial types in alphabetical order), of the
// AP214 schema AUTOMOTIVE_DESIGN; the geometry is ISO 10303-42's, the
// product structure and the units those AP214 readers look up to find the
// shape (application context, product, definition, shape, representation and
// its context with units and uncertainty).
#include <fmt/format.h>

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "casteljau/io/cad_exchange.hpp"
#include "casteljau/io/tolerance.hpp"
#include "casteljau/version.hpp"
#include "exchange_geometry.hpp"
#include "text.hpp"

namespace casteljau {
namespace {

using detail::exchange_real;

/// A STEP string literal: ' and \ doubled, printable ASCII as it is, any
/// other character by its code point (\X2\hhhh\X0\ for the basic plane,
/// \X4\hhhhhhhh\X0\ beyond; ISO 10303-21, 6.4.3). Text that is not UTF-8
/// keeps its ASCII and loses the rest.
std::string step_string(std::string_view text) {
  const auto characters = io_detail::code_points(text);
  std::u32string all;
  if (characters) {
    all = *characters;
  } else {
    for (char c : text)
      if (static_cast<unsigned char>(c) < 0x80) all += static_cast<char32_t>(c);
  }
  std::string out = "'";
  for (std::size_t i = 0; i < all.size();) {
    const char32_t c = all[i];
    if (c >= 0x20 && c < 0x7F) {
      if (c == '\'' || c == '\\') out += static_cast<char>(c);
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    // A run of characters outside printable ASCII, in one \X2\ or \X4\ group.
    const bool wide = c > 0xFFFF;
    out += wide ? "\\X4\\" : "\\X2\\";
    for (; i < all.size() && !(all[i] >= 0x20 && all[i] < 0x7F) && (all[i] > 0xFFFF) == wide; ++i)
      out += wide ? fmt::format("{:08X}", static_cast<unsigned>(all[i])) : fmt::format("{:04X}", static_cast<unsigned>(all[i]));
    out += "\\X0\\";
  }
  return out + "'";
}

/// The instances of a DATA section, numbered from 1 as they are added.
class StepData {
 public:
  /// Adds `#n=text;` and returns n.
  int add(std::string_view text) {
    fmt::format_to(std::back_inserter(out_), "#{}={};\n", ++count_, text);
    return count_;
  }
  /// The number the next add() returns.
  int next() const { return count_ + 1; }
  const std::string& text() const { return out_; }

 private:
  std::string out_;
  int count_ = 0;
};

/// "(a,b,c)" of the items, each written by `item`.
template <class T, class F>
std::string list(const std::vector<T>& items, F item) {
  std::string out = "(";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ',';
    out += item(items[i]);
  }
  return out + ')';
}

std::string reference(int n) { return fmt::format("#{}", n); }
std::string real_list(const std::vector<double>& values) { return list(values, exchange_real); }
std::string integer_list(const std::vector<int>& values) {
  return list(values, [](int k) { return std::to_string(k); });
}

/// A CARTESIAN_POINT per x y z triple of `xyz`, their instance numbers in order.
std::vector<int> add_points(StepData& data, const std::vector<double>& xyz) {
  std::vector<int> refs;
  refs.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i < xyz.size(); i += 3)
    refs.push_back(data.add(fmt::format("CARTESIAN_POINT('',({},{},{}))", exchange_real(xyz[i]),
                                        exchange_real(xyz[i + 1]), exchange_real(xyz[i + 2]))));
  return refs;
}

const char* logical(bool value) { return value ? ".T." : ".F."; }

/// A curve: B_SPLINE_CURVE_WITH_KNOTS, or the rational complex instance.
int add_curve(StepData& data, const detail::ExchangeCurve& curve, const std::string& name) {
  const std::string points = list(add_points(data, curve.points), reference);
  const detail::DistinctKnots knots = detail::distinct_knots(curve.knots);
  const std::string with_knots =
      fmt::format("{},{},.UNSPECIFIED.", integer_list(knots.multiplicities), real_list(knots.values));
  if (!curve.rational)
    return data.add(fmt::format("B_SPLINE_CURVE_WITH_KNOTS({},{},{},.UNSPECIFIED.,{},.U.,{})", name, curve.degree,
                                points, logical(curve.closed), with_knots));
  return data.add(fmt::format("(BOUNDED_CURVE()B_SPLINE_CURVE({},{},.UNSPECIFIED.,{},.U.)"
                              "B_SPLINE_CURVE_WITH_KNOTS({})CURVE()GEOMETRIC_REPRESENTATION_ITEM()"
                              "RATIONAL_B_SPLINE_CURVE({})REPRESENTATION_ITEM({}))",
                              curve.degree, points, logical(curve.closed), with_knots, real_list(curve.weights),
                              name));
}

/// A surface: B_SPLINE_SURFACE_WITH_KNOTS, or the rational complex instance;
/// control points and weights as lists of rows (the u index outside).
int add_surface(StepData& data, const detail::ExchangeSurface& surface, const std::string& name) {
  const std::vector<int> refs = add_points(data, surface.points);
  std::string net = "(", weights = "(";
  for (std::size_t i = 0; i < surface.rows; ++i) {
    const auto first = refs.begin() + static_cast<std::ptrdiff_t>(i * surface.columns);
    const auto first_weight = surface.weights.begin() + static_cast<std::ptrdiff_t>(i * surface.columns);
    if (i > 0) {
      net += ',';
      weights += ',';
    }
    net += list(std::vector<int>(first, first + static_cast<std::ptrdiff_t>(surface.columns)), reference);
    weights += real_list(std::vector<double>(first_weight, first_weight + static_cast<std::ptrdiff_t>(surface.columns)));
  }
  net += ')';
  weights += ')';
  const detail::DistinctKnots u = detail::distinct_knots(surface.knots_u), v = detail::distinct_knots(surface.knots_v);
  const std::string with_knots =
      fmt::format("{},{},{},{},.UNSPECIFIED.", integer_list(u.multiplicities), integer_list(v.multiplicities),
                  real_list(u.values), real_list(v.values));
  const std::string form = fmt::format(".UNSPECIFIED.,{},{},.U.", logical(surface.closed_u), logical(surface.closed_v));
  if (!surface.rational)
    return data.add(fmt::format("B_SPLINE_SURFACE_WITH_KNOTS({},{},{},{},{},{})", name, surface.degree_u,
                                surface.degree_v, net, form, with_knots));
  return data.add(fmt::format("(BOUNDED_SURFACE()B_SPLINE_SURFACE({},{},{},{})B_SPLINE_SURFACE_WITH_KNOTS({})"
                              "GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE({})REPRESENTATION_ITEM({})"
                              "SURFACE())",
                              surface.degree_u, surface.degree_v, net, form, with_knots, weights, name));
}

/// The length unit: the SI millimetre, or the inch as a conversion-based unit.
int add_length_unit(StepData& data, ExchangeUnit unit) {
  if (unit == ExchangeUnit::millimetre) return data.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))");
  const int metre = data.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.))");
  const int measure = data.add(fmt::format("LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(0.0254),#{})", metre));
  const int exponents = data.add("DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.)");
  return data.add(fmt::format("(CONVERSION_BASED_UNIT('INCH',#{})LENGTH_UNIT()NAMED_UNIT(#{}))", measure, exponents));
}

}  // namespace

Expected<std::string> write_step(std::span<const Model> models, const ExchangeHeader& header) {
  if (auto digits = detail::timestamp_digits(header.timestamp); !digits) return digits.error();
  auto geometry = detail::exchange_geometry(models, "STEP");
  if (!geometry) return geometry.error();

  StepData data;
  const std::string name = step_string(header.file_name);
  const int application = data.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
  data.add(fmt::format("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{})",
                       application));
  const int product_context = data.add(fmt::format("PRODUCT_CONTEXT('',#{},'mechanical')", application));
  const int product = data.add(fmt::format("PRODUCT({},{},'',(#{}))", name, name, product_context));
  data.add(fmt::format("PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#{}))", product));
  const int formation = data.add(fmt::format("PRODUCT_DEFINITION_FORMATION('','',#{})", product));
  const int definition_context = data.add(fmt::format("PRODUCT_DEFINITION_CONTEXT('part definition',#{},'design')",
                                                      application));
  const int definition = data.add(fmt::format("PRODUCT_DEFINITION('design','',#{},#{})", formation, definition_context));
  const int definition_shape = data.add(fmt::format("PRODUCT_DEFINITION_SHAPE('','',#{})", definition));
  // The shape representation is added after its items; its number is known now.
  const int length = add_length_unit(data, header.unit);
  const int angle = data.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))");
  const int solid_angle = data.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())");
  const double size = geometry->size > 0.0 ? geometry->size : 1.0;
  const int uncertainty = data.add(fmt::format("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE({}),#{},"
                                               "'distance_accuracy_value','the numbers are exact to the last digit')",
                                               exchange_real(size * tolerances::kExchangeResolutionRelative), length));
  const int context = data.add(fmt::format("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{}))"
                                           "GLOBAL_UNIT_ASSIGNED_CONTEXT((#{},#{},#{}))REPRESENTATION_CONTEXT('','3D'))",
                                           uncertainty, length, angle, solid_angle));

  std::vector<int> items;  // item m is model m, named so
  for (std::size_t m = 0; m < geometry->items.size(); ++m) {
    const std::string item_name = step_string(fmt::format("model {}", m));
    if (const auto* curve = std::get_if<detail::ExchangeCurve>(&geometry->items[m]))
      items.push_back(add_curve(data, *curve, item_name));
    else
      items.push_back(add_surface(data, std::get<detail::ExchangeSurface>(geometry->items[m]), item_name));
  }
  const bool wireframe = !geometry->has_surfaces;
  const int set = data.add(fmt::format("{}('',{})", wireframe ? "GEOMETRIC_CURVE_SET" : "GEOMETRIC_SET",
                                       list(items, reference)));
  const int representation =
      data.add(fmt::format("{}({},(#{}),#{})",
                           wireframe ? "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION"
                                     : "GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION",
                           name, set, context));
  data.add(fmt::format("SHAPE_DEFINITION_REPRESENTATION(#{},#{})", definition_shape, representation));

  const std::string system = step_string(fmt::format("casteljau {}", CASTELJAU_VERSION_STRING));
  std::string out = "ISO-10303-21;\nHEADER;\n";
  out += "FILE_DESCRIPTION(('B-spline curves and surfaces written by casteljau'),'2;1');\n";
  out += fmt::format("FILE_NAME({},'{}',({}),({}),{},{},'');\n", name, header.timestamp, step_string(header.author),
                     step_string(header.organization), system, system);
  out += "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";
  out += data.text();
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

}  // namespace casteljau
