// Toolpaths to RS-274/NGC programs (io/gcode.hpp says what is written).
// The program is built in memory: the contours ordered (io/gcode_order.hpp),
// each cut pass after pass, every number rounded to the grid of
// the decimals exactly as the controller will read it, then the header that
// counts what the body holds.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "casteljau/io/gcode.hpp"
#include "casteljau/io/gcode_order.hpp"
#include "casteljau/version.hpp"

namespace casteljau {

GcodeContour contour_of(const ArcSpline& spline) { return spline.segments; }

Expected<GcodeContour> contour_of(const Polyline& polyline) {
  const PointArray& points = polyline.points;
  if (points.dimension() != 2)
    return Error{fmt::format("G-code contours are plane, this polyline lives in R^{}", points.dimension())};
  GcodeContour contour;
  for (std::size_t i = 1; i < points.size(); ++i)
    contour.push_back(ArcSegment{Vec2::from(points[i - 1]), Vec2::from(points[i]), 0.0});
  return contour;
}

double gcode_rounding_allowance(int decimals) {
  return tolerances::kGcodeRoundingUnits * std::pow(10.0, -decimals);
}

Expected<int> gcode_decimals(Tolerance tolerance, GcodeUnits units, int requested) {
  const double budget = tolerance.distance;
  if (!(std::isfinite(budget) && budget > 0.0)) return Error{fmt::format("tolerance {} is not a distance > 0", budget)};
  const char* unit = units == GcodeUnits::millimetres ? "mm" : "inch";
  if (requested != 0) {
    if (requested < tolerances::kGcodeFewestDecimals || requested > tolerances::kGcodeMostDecimals)
      return Error{fmt::format("decimals {} is outside {}..{}", requested, tolerances::kGcodeFewestDecimals,
                               tolerances::kGcodeMostDecimals)};
    if (!(gcode_rounding_allowance(requested) < budget))
      return Error{fmt::format("tolerance {} {} is not above what rounding to {} decimals may move the path ({} {})",
                               budget, unit, requested, gcode_rounding_allowance(requested), unit)};
    return requested;
  }
  int decimals = units == GcodeUnits::millimetres ? tolerances::kGcodeDefaultDecimalsMillimetres
                                                  : tolerances::kGcodeDefaultDecimalsInches;
  while (decimals < tolerances::kGcodeMostDecimals &&
         gcode_rounding_allowance(decimals) > tolerances::kGcodeRoundingShare * budget)
    ++decimals;
  if (!(gcode_rounding_allowance(decimals) < budget))
    return Error{fmt::format("tolerance {} {} is below what {} decimals can carry (rounding moves the path by up to {} {})",
                             budget, unit, decimals, gcode_rounding_allowance(decimals), unit)};
  return decimals;
}

Expected<GcodeContour> contour_of(CurveView curve, Tolerance tolerance, int decimals, GcodeMotion motion) {
  if (curve.dimension() != 2)
    return Error{fmt::format("G-code cuts plane curves, this one lives in R^{}", curve.dimension())};
  const Tolerance fit{tolerance.distance - gcode_rounding_allowance(decimals)};
  if (!(fit.distance > 0.0))
    return Error{fmt::format("tolerance {} is not above what rounding to {} decimals may move the path ({})",
                             tolerance.distance, decimals, gcode_rounding_allowance(decimals))};
  if (motion == GcodeMotion::lines) {
    auto polyline = flatten(curve, fit);
    if (!polyline) return polyline.error();
    auto contour = contour_of(*polyline);
    if (contour && std::all_of(contour->begin(), contour->end(), [](const ArcSegment& s) { return s.start == s.end; }))
      return Error{"a toolpath needs a curve of nonzero length, this one is a single point"};
    return contour;
  }
  auto spline = fit_arcs(curve, fit);
  if (!spline) return spline.error();
  return contour_of(*spline);
}

GcodeOptions default_gcode_options(GcodeUnits units) {
  GcodeOptions options;
  options.units = units;
  if (units == GcodeUnits::inches) {
    options.safe_height = tolerances::kGcodeDefaultSafeHeightInches;
    options.depth = tolerances::kGcodeDefaultDepthInches;
    options.feed = tolerances::kGcodeDefaultFeedInches;
    options.plunge_feed = tolerances::kGcodeDefaultPlungeFeedInches;
  }
  return options;
}

namespace {

/// Numbers as a program writes them: `decimals` digits after the point, no
/// exponent, no "-0.0000"; rounded() is the double the controller reads.
class Numbers {
 public:
  explicit Numbers(int decimals)
      : decimals_(decimals), unit_(std::pow(10.0, -decimals)), scale_(std::pow(10.0, decimals)) {}

  std::string text(double x) const {
    std::string out = fmt::format("{:.{}f}", x, decimals_);
    if (out.front() == '-' && out.find_first_not_of("-0.") == std::string::npos) out.erase(0, 1);
    return out;
  }
  /// What the controller reads for text(x): k / 10^d for the integer k
  /// nearest x 10^d (a quotient of two exact doubles, rounded once, as
  /// strtod rounds the decimal text), taken from the rounded product unless
  /// that lies within a few ulps of a tie, where only the text's exact
  /// decimal rounding decides. The same doubles as strtod(text(x)), without
  /// formatting: the centre search rounds 18 numbers an arc.
  double rounded(double x) const {
    const double scaled = x * scale_;
    const double whole = std::nearbyint(scaled);
    const double ulp = std::nextafter(std::abs(scaled), INFINITY) - std::abs(scaled);
    if (std::abs(scaled) < 0x1p52 && std::abs(std::abs(scaled - whole) - 0.5) > 8.0 * ulp)
      return whole == 0.0 ? 0.0 : whole / scale_;
    return std::strtod(text(x).c_str(), nullptr);
  }
  Vec2 rounded(Vec2 p) const { return {{rounded(p[0]), rounded(p[1])}}; }
  /// The value of the last decimal: 1e-4 for 4 decimals.
  double unit() const { return unit_; }

 private:
  int decimals_;
  double unit_;
  double scale_;  // 10^decimals, exact
};

const char* unit_name(GcodeUnits units) { return units == GcodeUnits::millimetres ? "mm" : "inch"; }

/// A box in the plane, empty until a point is added.
struct PlaneBox {
  Vec2 lower{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}};
  Vec2 upper{{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}};
  void add(Vec2 p) {
    for (int k = 0; k < 2; ++k) {
      lower[k] = std::min(lower[k], p[k]);
      upper[k] = std::max(upper[k], p[k]);
    }
  }
  bool empty() const { return !(lower[0] <= upper[0]); }
};

/// The diagonal of the box of every segment's ends (at least `floor`).
double drawing_size(const std::vector<GcodeContour>& contours, double floor) {
  PlaneBox box;
  for (const GcodeContour& contour : contours)
    for (const ArcSegment& segment : contour) {
      box.add(segment.start);
      box.add(segment.end);
    }
  if (box.empty()) return floor;
  return std::max(std::hypot(box.upper[0] - box.lower[0], box.upper[1] - box.lower[1]), floor);
}

/// The middle of the arc a controller moves along from `start` about
/// `centre` to `end`, clockwise or not: half its sweep, in (0, 2 pi], from the start.
Vec2 written_middle(Vec2 start, Vec2 end, Vec2 centre, bool clockwise) {
  const Vec2 from = start - centre, to = end - centre;
  double sweep = std::atan2(cross(from, to), dot(from, to));  // (-pi, pi]
  if (clockwise) sweep = -sweep;
  if (sweep <= 0.0) sweep += 2.0 * std::numbers::pi;
  const double half = (clockwise ? -sweep : sweep) / 2.0;
  return centre + Vec2{{from[0] * std::cos(half) - from[1] * std::sin(half),
                        from[0] * std::sin(half) + from[1] * std::cos(half)}};
}

/// The moves of the program, with the tool's position as the controller
/// knows it (the rounded numbers written).
class Moves {
 public:
  Moves(const GcodeOptions& options, const Numbers& numbers, double flat_radius)
      : options_(options), numbers_(numbers), flat_radius_(flat_radius) {}

  /// Up to the safe height (unless there), then a rapid move to `point`.
  void rapid_to(Vec2 point) {
    retract();
    const Vec2 target = numbers_.rounded(point);
    if (target == position_ && placed_) return;
    out_ += fmt::format("G0 X{} Y{}\n", numbers_.text(target[0]), numbers_.text(target[1]));
    program_.rapid_length += distance(position_, target);
    position_ = target;
    placed_ = true;
  }

  /// A G0 up to the safe height, unless the tool is there.
  void retract() {
    const double safe = numbers_.rounded(options_.safe_height);
    if (z_ == safe) return;
    out_ += fmt::format("G0 Z{}\n", numbers_.text(safe));
    z_ = safe;
  }

  /// A G1 straight down (or up) to z at the plunge feed.
  void plunge_to(double z) {
    const double target = numbers_.rounded(z);
    if (target == z_) return;
    out_ += fmt::format("G1 Z{}{}\n", numbers_.text(target), feed(options_.plunge_feed));
    if (std::isfinite(z_)) program_.plunge_length += std::abs(z_ - target);
    z_ = target;
  }

  /// The contour at the cutting feed, from where the tool is: a G1 first to
  /// a segment's start where the tool is not there (a closed contour's ends
  /// are only within the tolerance).
  void cut(const GcodeContour& contour) {
    for (const ArcSegment& segment : contour) {
      if (numbers_.rounded(segment.start) != position_) line_to(segment.start);
      if (segment.bulge == 0.0) {
        line_to(segment.end);
      } else {
        arc(segment, 0);
      }
    }
  }

  std::string& text() { return out_; }
  GcodeProgram& program() { return program_; }

 private:
  /// " F<feed>" when the feed changes, else "".
  std::string feed(double value) {
    const double target = numbers_.rounded(value);
    if (target == feed_) return {};
    feed_ = target;
    return " F" + numbers_.text(target);
  }

  void line_to(Vec2 point) {
    const Vec2 target = numbers_.rounded(point);
    if (target == position_) return;
    out_ += fmt::format("G1 X{} Y{}{}\n", numbers_.text(target[0]), numbers_.text(target[1]), feed(options_.feed));
    program_.cut_length += distance(position_, target);
    position_ = target;
    ++program_.lines;
  }

  /// The arc as one G2/G3 when a centre on the grid near its own gives
  /// start and end radii within kGcodeRadiusAgreement; else halved, or a
  /// G1 chord when its sagitta is within the rounding (or halvings run out).
  void arc(const ArcSegment& segment, int halvings) {
    if (arc_move(segment)) return;
    const double sagitta = std::abs(segment.bulge) * distance(segment.start, segment.end) / 2.0;
    if (sagitta <= tolerances::kGcodeChordSagittaUnits * numbers_.unit() ||
        halvings >= tolerances::kGcodeMostArcHalvings) {
      const std::size_t before = program_.lines;
      line_to(segment.end);
      program_.arcs_as_lines += program_.lines - before;
      return;
    }
    // tan(sweep / 8) from tan(sweep / 4): the half angle formula, |sweep / 4| < pi / 2.
    const double half = segment.bulge / (1.0 + std::sqrt(1.0 + segment.bulge * segment.bulge));
    const Vec2 middle = point_along(segment, 0.5);
    arc(ArcSegment{segment.start, middle, half}, halvings + 1);
    arc(ArcSegment{middle, segment.end, half}, halvings + 1);
  }

  /// Writes the arc from the tool's position to its rounded end with the
  /// best centre of the grid points around its own; false (nothing written)
  /// when none meets the radius rule, the arc is flat or smaller than
  /// kGcodeSmallestArcRadiusInches, or its ends coincide once rounded (a
  /// G2/G3 would then be a whole circle).
  bool arc_move(const ArcSegment& segment) {
    const Vec2 start = position_;
    const Vec2 end = numbers_.rounded(segment.end);
    if (end == start || radius_of(segment) > flat_radius_) return false;
    const Vec2 centre = center_of(segment);
    if (std::max(std::abs(centre[0]), std::abs(centre[1])) > tolerances::kGcodeLargestCoordinate) return false;
    const Vec2 offset = centre - start;
    const Vec2 nearest = numbers_.rounded(offset);
    // The nearest centre with a margin, else the one whose radii agree best.
    const double margin = tolerances::kGcodeRadiusMargin * tolerances::kGcodeRadiusAgreement;
    double best_gap = std::numeric_limits<double>::infinity(), best_shift = best_gap;
    Vec2 best{};
    const int steps = tolerances::kGcodeCentreSearchSteps;
    for (int di = -steps; di <= steps; ++di)
      for (int dj = -steps; dj <= steps; ++dj) {
        const Vec2 ij = numbers_.rounded(Vec2{{nearest[0] + di * numbers_.unit(), nearest[1] + dj * numbers_.unit()}});
        const Vec2 written_centre = start + ij;
        const double gap = std::abs(distance(end, written_centre) - distance(start, written_centre));
        const double shift = distance(ij, offset);
        const bool better = gap <= margin ? best_gap > margin || shift < best_shift
                                          : best_gap > margin && (gap < best_gap || (gap == best_gap && shift < best_shift));
        if (better) {
          best_gap = gap;
          best_shift = shift;
          best = ij;
        }
      }
    if (!(best_gap <= tolerances::kGcodeRadiusAgreement)) return false;
    const Vec2 written_centre = start + best;
    const double smallest = tolerances::kGcodeSmallestArcRadiusInches *
                            (options_.units == GcodeUnits::millimetres ? 25.4 : 1.0);
    const double start_radius = distance(start, written_centre), end_radius = distance(end, written_centre);
    if (std::min(start_radius, end_radius) < smallest) return false;
    // Every point the controller moves along (its radius going from the
    // start's to the end's) is within shift + max |written radius - true
    // radius| of the true circle; the middle places it on the true arc.
    const double allowance = tolerances::kGcodeRoundingUnits * numbers_.unit();
    const double radius = radius_of(segment);
    const double moved = distance(written_centre, centre) +
                         std::max(std::abs(start_radius - radius), std::abs(end_radius - radius));
    if (!(moved <= allowance)) return false;
    if (distance(written_middle(start, end, written_centre, segment.bulge < 0.0), point_along(segment, 0.5)) > allowance)
      return false;
    out_ += fmt::format("{} X{} Y{} I{} J{}{}\n", segment.bulge < 0.0 ? "G2" : "G3", numbers_.text(end[0]),
                        numbers_.text(end[1]), numbers_.text(best[0]), numbers_.text(best[1]), feed(options_.feed));
    position_ = end;
    program_.cut_length += length_of(segment);
    ++program_.arcs;
    return true;
  }

  const GcodeOptions& options_;
  const Numbers& numbers_;
  double flat_radius_;
  std::string out_;
  GcodeProgram program_;
  Vec2 position_{};      // the controller's position (rapid lengths count from the origin)
  bool placed_ = false;  // whether a move has set the position yet (the machine may be anywhere)
  double z_ = std::numeric_limits<double>::quiet_NaN();     // unknown until the first Z move
  double feed_ = std::numeric_limits<double>::quiet_NaN();  // no feed written yet
};

/// A finite option in (lowest, kGcodeLargestCoordinate] (or [lowest, ...] when `zero_allowed`).
Status check_length(const char* name, double value, bool zero_allowed) {
  const bool in_range = std::isfinite(value) && (zero_allowed ? value >= 0.0 : value > 0.0) &&
                        value <= tolerances::kGcodeLargestCoordinate;
  if (in_range) return {};
  return Error{fmt::format("{} {} is not a length {} 0 and at most {}", name, value, zero_allowed ? ">=" : ">",
                           tolerances::kGcodeLargestCoordinate)};
}

Status check_options(const std::vector<GcodeContour>& contours, const GcodeOptions& options) {
  for (auto [name, value, zero_allowed] :
       {std::tuple{"safe height", options.safe_height, false}, std::tuple{"depth", options.depth, false},
        std::tuple{"step down", options.step_down, true}, std::tuple{"feed", options.feed, false},
        std::tuple{"plunge feed", options.plunge_feed, false}}) {
    if (auto status = check_length(name, value, zero_allowed); !status) return status;
  }
  for (std::size_t c = 0; c < contours.size(); ++c)
    for (std::size_t s = 0; s < contours[c].size(); ++s)
      for (const Vec2& p : {contours[c][s].start, contours[c][s].end})
        if (!(std::max(std::abs(p[0]), std::abs(p[1])) <= tolerances::kGcodeLargestCoordinate))
          return Error{fmt::format("contour {}, segment {}: point ({}, {}) is beyond the {} a G-code coordinate "
                                   "may reach",
                                   c + 1, s + 1, p[0], p[1], tolerances::kGcodeLargestCoordinate),
                       ErrorKind::limit};
  return {};
}

/// The box of the contours: every segment's ends and the points where an
/// arc reaches its circle's leftmost, rightmost, lowest or highest point.
PlaneBox box_of(const std::vector<GcodeContour>& contours) {
  PlaneBox box;
  for (const GcodeContour& contour : contours)
    for (const ArcSegment& segment : contour) {
      box.add(segment.start);
      box.add(segment.end);
      if (segment.bulge == 0.0) continue;
      const Vec2 centre = center_of(segment);
      const double radius = radius_of(segment), sweep = sweep_of(segment);
      const Vec2 from = segment.start - centre;
      const double start_angle = std::atan2(from[1], from[0]);
      for (int quarter = 0; quarter < 4; ++quarter) {
        // The turn from the start to the axis direction, in the arc's sense.
        double turn = quarter * std::numbers::pi / 2.0 - start_angle;
        if (sweep < 0.0) turn = -turn;
        turn = std::fmod(turn, 2.0 * std::numbers::pi);
        if (turn < 0.0) turn += 2.0 * std::numbers::pi;
        if (turn <= std::abs(sweep))
          box.add(centre + Vec2{{radius * std::cos(quarter * std::numbers::pi / 2.0),
                                 radius * std::sin(quarter * std::numbers::pi / 2.0)}});
      }
    }
  return box;
}

/// How far the contours move so that their box's lower-left corner or
/// centre is at the origin (nothing for GcodeOrigin::drawing, or no contour).
Vec2 origin_shift(const std::vector<GcodeContour>& contours, GcodeOrigin origin) {
  const PlaneBox box = box_of(contours);
  if (origin == GcodeOrigin::drawing || box.empty()) return Vec2{};
  return origin == GcodeOrigin::lower_left ? box.lower : (box.lower + box.upper) * 0.5;
}

/// The contours moved by -shift.
std::vector<GcodeContour> moved(std::vector<GcodeContour> contours, Vec2 shift) {
  for (GcodeContour& contour : contours)
    for (ArcSegment& segment : contour) {
      segment.start = segment.start - shift;
      segment.end = segment.end - shift;
    }
  return contours;
}

/// Text for a comment: printable ASCII, parentheses (which would nest or end
/// the comment) as brackets, anything else as '?'.
std::string comment_text(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    out += c == '(' ? '[' : c == ')' ? ']' : (byte >= 0x20 && byte < 0x7F) ? c : '?';
  }
  return out;
}

std::string header(const Toolpath& toolpath, const GcodeOptions& options, const Numbers& numbers, int decimals,
                   const GcodeProgram& program, const PlaneBox& box, Vec2 shift) {
  const char* unit = unit_name(options.units);
  std::string out = fmt::format("(casteljau {}: RS-274/NGC program for {})\n", CASTELJAU_VERSION_STRING,
                                options.dialect == GcodeDialect::grbl ? "GRBL" : "LinuxCNC");
  for (const std::string& source : toolpath.sources) out += fmt::format("(source: {})\n", comment_text(source));
  out += fmt::format("(tolerance {} {}: the path within it of the curves; the rounding of its numbers to {} decimals "
                     "takes at most {} of it)\n",
                     toolpath.tolerance.distance, unit, decimals, gcode_rounding_allowance(decimals));
  out += fmt::format("(units {} [{}], absolute [G90], XY plane [G17], feed per minute [G94])\n", unit,
                     options.units == GcodeUnits::millimetres ? "G21" : "G20");
  out += fmt::format("(depth {} in {} pass{}, safe height {}, feed {}, plunge feed {})\n", numbers.text(options.depth),
                     program.passes, program.passes == 1 ? "" : "es", numbers.text(options.safe_height),
                     numbers.text(options.feed), numbers.text(options.plunge_feed));
  out += fmt::format("({} contour{}: {} arc{} [G2 G3], {} line{} [G1]", program.contours,
                     program.contours == 1 ? "" : "s", program.arcs, program.arcs == 1 ? "" : "s", program.lines,
                     program.lines == 1 ? "" : "s");
  if (program.arcs_as_lines > 0)
    out += fmt::format(", {} of them chords of arcs too small or flat for G2 G3 once rounded", program.arcs_as_lines);
  out += ")\n";
  if (options.origin != GcodeOrigin::drawing)
    out += fmt::format("(the drawing moved by X {} Y {}: its box's {} at X0 Y0)\n", numbers.text(-shift[0]),
                       numbers.text(-shift[1]), options.origin == GcodeOrigin::lower_left ? "lower-left corner" : "centre");
  if (program.contours > 0)
    out += fmt::format("(box of the cuts: X {} to {}, Y {} to {})\n", numbers.text(box.lower[0]),
                       numbers.text(box.upper[0]), numbers.text(box.lower[1]), numbers.text(box.upper[1]));
  const double minutes = program.cut_length / options.feed + program.plunge_length / options.plunge_feed;
  out += fmt::format("(cuts {} {}, plunges {}, rapid moves {} in the plane [{} in the input's order]; "
                     "about {} at the feeds, rapid moves not counted)\n",
                     numbers.text(program.cut_length), unit, numbers.text(program.plunge_length),
                     numbers.text(program.rapid_length), numbers.text(program.rapid_length_unordered),
                     minutes < 1.0 ? fmt::format("{:.0f} s", minutes * 60.0) : fmt::format("{:.1f} min", minutes));
  return out;
}

}  // namespace

Expected<GcodeProgram> write_gcode(const Toolpath& toolpath, const GcodeOptions& options) {
  const auto digits = gcode_decimals(toolpath.tolerance, options.units, options.decimals);
  if (!digits) return digits.error();
  const int decimals = *digits;
  const Vec2 shift = origin_shift(toolpath.contours, options.origin);
  const std::vector<GcodeContour> contours = moved(toolpath.contours, shift);
  if (auto status = check_options(contours, options); !status) return status.error();
  const Numbers numbers(decimals);

  int passes = 1;
  if (options.step_down > 0.0) {
    const double count = std::ceil(options.depth / options.step_down * (1.0 - tolerances::kGcodePassSlack));
    if (!(count <= tolerances::kGcodeMostPasses))
      return Error{fmt::format("depth {} in steps of {} takes more than {} passes", options.depth, options.step_down,
                               tolerances::kGcodeMostPasses),
                   ErrorKind::limit};
    passes = std::max(1, static_cast<int>(count));
  }
  std::size_t segments = 0;
  for (const GcodeContour& contour : contours) segments += contour.size();
  if (static_cast<double>(segments) * passes > static_cast<double>(tolerances::kGcodeMostMoves))
    return Error{fmt::format("{} segments in {} passes are more than the {} moves a program may hold", segments,
                             passes, tolerances::kGcodeMostMoves),
                 ErrorKind::limit};

  const double size = drawing_size(contours, numbers.unit());
  Moves moves(options, numbers, tolerances::kGcodeFlatArcRadius * size);
  std::string& body = moves.text();
  body += options.units == GcodeUnits::millimetres ? "G21 G90 G17 G94\n" : "G20 G90 G17 G94\n";
  if (options.dialect == GcodeDialect::linuxcnc) body += fmt::format("G91.1 G64 P{}\n", numbers.text(numbers.unit()));
  const std::vector<GcodeContour> order = cutting_order(contours, toolpath.tolerance, passes);
  for (const GcodeContour& contour : order) {
    const bool closed = contour_is_closed(contour, toolpath.tolerance);
    const GcodeContour backwards = closed ? GcodeContour{} : reversed_contour(contour);
    moves.rapid_to(contour.front().start);
    for (int pass = 1; pass <= passes; ++pass) {
      moves.plunge_to(-options.depth * pass / passes);
      moves.cut(closed || pass % 2 == 1 ? contour : backwards);
    }
  }
  moves.retract();
  body += "M2\n";

  GcodeProgram program = std::move(moves.program());
  program.contours = order.size();
  program.passes = passes;
  program.decimals = decimals;
  program.rapid_length_unordered = rapid_length_of(contours, toolpath.tolerance, passes);
  program.text = header(toolpath, options, numbers, decimals, program, box_of(order), shift) + body;
  return program;
}

}  // namespace casteljau
