// Curves and surfaces to an IGES 5.3 file (io/cad_exchange.hpp says what).
// The record layout follows the IGES 5.3 specification (US PRO/IPO-100,
// 1996), section 2: 80-column records, columns 1-72 data, 73 the section
// letter, 74-80 the sequence number within the section; Parameter Data
// records keep columns 1-64 for data and 66-72 for the pointer back to the
// entity's Directory Entry. No parameter is split across records.
#include <fmt/format.h>

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "casteljau/io/cad_exchange.hpp"
#include "casteljau/io/tolerance.hpp"
#include "casteljau/version.hpp"
#include "exchange_geometry.hpp"

namespace casteljau {
namespace {

using detail::exchange_real;

/// The sections of an IGES file being built, each a list of 72-column data fields.
class IgesFile {
 public:
  /// Appends a record of `section` ('S', 'G', 'D', 'P'): `data` padded to 72 columns.
  void record(char section, std::string_view data) {
    int& count = counts_[index(section)];
    fmt::format_to(std::back_inserter(out_), "{:<72}{}{:>7}\n", data, section, ++count);
  }
  int count(char section) const { return counts_[index(section)]; }
  std::string finish() {
    record('T', fmt::format("S{:>7}G{:>7}D{:>7}P{:>7}", count('S'), count('G'), count('D'), count('P')));
    return std::move(out_);
  }

 private:
  static int index(char section) {
    return section == 'S' ? 0 : section == 'G' ? 1 : section == 'D' ? 2 : section == 'P' ? 3 : 4;
  }
  std::string out_;
  int counts_[5] = {0, 0, 0, 0, 0};
};

/// The free-format parameters of one record (Global, or one entity's
/// Parameter Data), joined by ',' and ended by ';', cut into lines of at
/// most `width` columns between parameters.
std::vector<std::string> parameter_lines(const std::vector<std::string>& parameters, std::size_t width) {
  std::vector<std::string> lines(1);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const std::string field = parameters[i] + (i + 1 == parameters.size() ? ';' : ',');
    if (!lines.back().empty() && lines.back().size() + field.size() > width) lines.emplace_back();
    lines.back() += field;
  }
  return lines;
}

/// A Hollerith string constant "nHtext" of printable ASCII (other bytes
/// become '?'), cut to `limit` characters so that it fits a record.
std::string hollerith(std::string_view text, std::size_t limit = 48) {
  std::string ascii;
  for (char c : text.substr(0, limit)) ascii += (c >= 0x20 && c < 0x7F) ? c : '?';
  return fmt::format("{}H{}", ascii.size(), ascii);
}

std::string integer(long long value) { return std::to_string(value); }

void append_reals(std::vector<std::string>& out, const std::vector<double>& values) {
  for (double value : values) out.push_back(exchange_real(value));
}

/// Entity 126's parameters (IGES 5.3, 4.23): K, M, the four flags, knots
/// T(-M)..T(N+1), weights, control points, V(0), V(1), the plane's normal.
std::vector<std::string> curve_parameters(const detail::ExchangeCurve& curve) {
  const std::size_t points = curve.weights.size();
  std::vector<std::string> p = {"126", integer(static_cast<long long>(points) - 1), integer(curve.degree),
                                curve.plane_axis >= 0 ? "1" : "0", curve.closed ? "1" : "0",
                                curve.rational ? "0" : "1", "0"};
  append_reals(p, curve.knots);
  append_reals(p, curve.weights);
  append_reals(p, curve.points);
  p.push_back(exchange_real(curve.domain.lower));
  p.push_back(exchange_real(curve.domain.upper));
  for (int k = 0; k < 3; ++k) p.push_back(curve.plane_axis == k ? "1." : "0.");
  return p;
}

/// Entity 128's parameters (IGES 5.3, 4.24): K1, K2, M1, M2, the five flags,
/// knots in u then v, weights and control points with the u index running
/// fastest, U(0), U(1), V(0), V(1).
std::vector<std::string> surface_parameters(const detail::ExchangeSurface& surface) {
  std::vector<std::string> p = {"128",
                                integer(static_cast<long long>(surface.rows) - 1),
                                integer(static_cast<long long>(surface.columns) - 1),
                                integer(surface.degree_u),
                                integer(surface.degree_v),
                                surface.closed_u ? "1" : "0",
                                surface.closed_v ? "1" : "0",
                                surface.rational ? "0" : "1",
                                "0",
                                "0"};
  append_reals(p, surface.knots_u);
  append_reals(p, surface.knots_v);
  for (std::size_t j = 0; j < surface.columns; ++j)
    for (std::size_t i = 0; i < surface.rows; ++i) p.push_back(exchange_real(surface.weights[i * surface.columns + j]));
  for (std::size_t j = 0; j < surface.columns; ++j)
    for (std::size_t i = 0; i < surface.rows; ++i)
      for (int k = 0; k < 3; ++k) p.push_back(exchange_real(surface.points[3 * (i * surface.columns + j) + k]));
  p.push_back(exchange_real(surface.domain_u.lower));
  p.push_back(exchange_real(surface.domain_u.upper));
  p.push_back(exchange_real(surface.domain_v.lower));
  p.push_back(exchange_real(surface.domain_v.upper));
  return p;
}

struct Entity {
  int type;
  std::vector<std::string> parameter_lines;
};

}  // namespace

Expected<std::string> write_iges(std::span<const Model> models, const ExchangeHeader& header) {
  // IGES dates are YYYYMMDD.HHNNSS (5.3, 2.2.4.3.18).
  const auto digits = detail::timestamp_digits(header.timestamp);
  if (!digits) return digits.error();
  const std::string date = digits->substr(0, 8) + '.' + digits->substr(8);
  auto geometry = detail::exchange_geometry(models, "IGES");
  if (!geometry) return geometry.error();

  // Entities in model order (entity e is model e); Parameter Data lines hold 64 columns.
  std::vector<Entity> entities;
  for (const auto& item : geometry->items) {
    if (const auto* curve = std::get_if<detail::ExchangeCurve>(&item))
      entities.push_back({126, parameter_lines(curve_parameters(*curve), 64)});
    else
      entities.push_back({128, parameter_lines(surface_parameters(std::get<detail::ExchangeSurface>(item)), 64)});
  }

  IgesFile file;
  file.record('S', fmt::format("casteljau {}: {} B-spline curve{} and surface{} (entities 126, 128)",
                               CASTELJAU_VERSION_STRING, entities.size(), entities.size() == 1 ? "" : "s",
                               entities.size() == 1 ? "" : "s"));
  const std::string system = hollerith(fmt::format("casteljau {}", CASTELJAU_VERSION_STRING));
  const bool inch = header.unit == ExchangeUnit::inch;
  const double size = geometry->size > 0.0 ? geometry->size : 1.0;
  const std::vector<std::string> global = {
      "1H,",                           // 1 parameter delimiter
      "1H;",                           // 2 record delimiter
      hollerith(header.file_name),     // 3 product identification from the sender
      hollerith(header.file_name),     // 4 file name
      system,                          // 5 native system
      system,                          // 6 preprocessor version
      "32",                            // 7 bits of an integer
      "38", "6",                       // 8, 9 single precision: largest power of ten, digits
      "308", "15",                     // 10, 11 double precision (the reals below have up to 17 digits)
      hollerith(header.file_name),     // 12 product identification for the receiver
      "1.",                            // 13 model space scale
      inch ? "1" : "2",                // 14 units flag: 1 inches, 2 millimetres
      inch ? "4HINCH" : "2HMM",        // 15 units name
      "1",                             // 16 line weight gradations
      exchange_real(size * 1e-3),      // 17 width of the heaviest line
      fmt::format("15H{}", date),      // 18 when the file was written
      exchange_real(size * tolerances::kExchangeResolutionRelative),  // 19 smallest distance the model means (the exactness the numbers keep)
      exchange_real(geometry->largest_coordinate > 0.0 ? geometry->largest_coordinate : 1.0),  // 20 largest coordinate
      hollerith(header.author),        // 21 author
      hollerith(header.organization),  // 22 organization
      "11",                            // 23 version: IGES 5.3
      "0",                             // 24 drafting standard: none
      fmt::format("15H{}", date),      // 25 when the model was made
  };
  for (const std::string& line : parameter_lines(global, 72)) file.record('G', line);

  // Directory Entries: two records of nine 8-column fields per entity.
  int parameter_line = 1;
  for (std::size_t e = 0; e < entities.size(); ++e) {
    const Entity& entity = entities[e];
    const int lines = static_cast<int>(entity.parameter_lines.size());
    file.record('D', fmt::format("{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}", entity.type, parameter_line, 0, 0, 0,
                                 0, 0, 0, "00000000"));
    file.record('D', fmt::format("{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}", entity.type, 0, 0, lines, 0, "", "",
                                 entity.type == 126 ? "CURVE" : "SURFACE", e % 100000000));
    parameter_line += lines;
  }
  for (std::size_t e = 0; e < entities.size(); ++e) {
    const int directory_line = static_cast<int>(2 * e + 1);
    for (const std::string& line : entities[e].parameter_lines)
      file.record('P', fmt::format("{:<64} {:>7}", line, directory_line));
  }
  return file.finish();
}

}  // namespace casteljau
