// SVG path data to Bézier pieces (io/svg_path.hpp says what and why).
#include "casteljau/io/svg_path.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "svg_scanner.hpp"

namespace casteljau {
namespace {

using io_detail::SvgScanner;

bool is_command(char c) {
  switch (c) {
    case 'M': case 'm': case 'Z': case 'z': case 'L': case 'l': case 'H': case 'h': case 'V': case 'v':
    case 'C': case 'c': case 'S': case 's': case 'Q': case 'q': case 'T': case 't': case 'A': case 'a':
      return true;
    default:
      return false;
  }
}

/// The arguments each command takes, as SVG 1.1 names them; 'f' marks a flag.
struct Arguments {
  const char* names;
  const char* kinds;  // 'n' number, 'f' flag
};
Arguments arguments_of(char command) {
  switch (command | 0x20) {  // lower case
    case 'm': case 'l': case 't': return {"x y", "nn"};
    case 'h': return {"x", "n"};
    case 'v': return {"y", "n"};
    case 'c': return {"x1 y1 x2 y2 x y", "nnnnnn"};
    case 's': return {"x2 y2 x y", "nnnn"};
    case 'q': return {"x1 y1 x y", "nnnn"};
    case 'a': return {"rx ry x-axis-rotation large-arc-flag sweep-flag x y", "nnnffnn"};
    default: return {"", ""};
  }
}

/// "'A' takes rx ry ...": what an error message says a command needed.
std::string takes(char command) { return fmt::format("'{}' takes {}", command, arguments_of(command).names); }

/// The pieces of the subpath being drawn and the state the commands share.
class Builder {
 public:
  Vec2 current() const { return current_; }
  /// The control point S (T) reflects: the last cubic's (quadratic's) second
  /// (only) control point when the previous segment was a C or S (Q or T),
  /// otherwise the current point.
  Vec2 cubic_reflection() const { return previous_ == 'c' ? 2.0 * current_ - last_control_ : current_; }
  Vec2 quadratic_reflection() const { return previous_ == 'q' ? 2.0 * current_ - last_control_ : current_; }

  void move_to(Vec2 point) {
    finish(false);
    start_ = current_ = point;
    previous_ = 'm';
  }
  Status close() {
    if (!(current_ == start_))
      if (Status drawn = add({current_, start_}, 'z'); !drawn) return drawn;
    finish(true);
    current_ = start_;  // the next subpath starts at this one's start (SVG 2 §9.3.4)
    previous_ = 'z';
    return {};
  }
  /// A polynomial piece from the current point through `points` (the first
  /// is the current point); `kind` is 'c' or 'q' for the reflections.
  Status add(std::initializer_list<Vec2> points, char kind) {
    std::vector<double> coordinates;
    coordinates.reserve(2 * points.size());
    for (const Vec2& p : points) coordinates.insert(coordinates.end(), {p[0], p[1]});
    auto piece = BezierCurve::make(PointArray::from_trusted(2, std::move(coordinates)));
    if (!piece) return piece.error();
    if (Status fits = count(points.size()); !fits) return fits;
    pieces_.push_back(std::move(*piece));
    const Vec2* last = points.end() - 1;
    if (kind == 'c' || kind == 'q') last_control_ = *(last - 1);
    current_ = *last;
    previous_ = kind;
    return {};
  }
  /// Pieces computed here (an arc's), whose ends are the current point and `end`.
  Status add_pieces(std::vector<BezierCurve> pieces, Vec2 end) {
    for (BezierCurve& piece : pieces) {
      if (Status fits = count(piece.control_points().size()); !fits) return fits;
      pieces_.push_back(std::move(piece));
    }
    current_ = end;
    previous_ = 'a';
    return {};
  }
  void set_previous(char kind) { previous_ = kind; }
  void finish(bool closed) {
    if (!pieces_.empty()) subpaths_.push_back({PiecewiseBezierCurve::make(std::move(pieces_)).value(), closed});
    pieces_.clear();
  }
  std::vector<SvgSubpath> take() {
    finish(false);
    return std::move(subpaths_);
  }

 private:
  Status count(std::size_t points) {
    total_points_ += points;
    if (total_points_ > tolerances::kMaxControlPoints)
      return Error{fmt::format("the path needs more than {} control points", tolerances::kMaxControlPoints),
                   ErrorKind::limit};
    return {};
  }

  std::vector<SvgSubpath> subpaths_;
  std::vector<BezierCurve> pieces_;
  Vec2 start_{}, current_{}, last_control_{};
  char previous_ = 0;  // kind of the last segment: 'c', 'q', 'a', 'l', 'm', 'z'
  std::size_t total_points_ = 0;
};

/// The elliptical arc from the current point to `end` (SVG 2 implementation
/// notes B.2.4: endpoint to centre parameterization, B.2.5: out-of-range
/// radii), as the affine image of make_arc's unit-circle arc. Worked in
/// coordinates divided by the radii, so no square of a large radius overflows.
Status add_arc(Builder& path, double rx, double ry, double rotation_degrees, bool large_arc, bool sweep, Vec2 end) {
  const Vec2 start = path.current();
  if (start == end) {  // B.2.5 step 1: the segment is omitted
    path.set_previous('a');
    return {};
  }
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0.0 || ry == 0.0) return path.add({start, end}, 'a');  // step 2: a straight line
  const double phi = std::fmod(rotation_degrees, 360.0) * std::numbers::pi / 180.0;
  const double c = std::cos(phi), s = std::sin(phi);
  const double hx = (start[0] - end[0]) / 2.0, hy = (start[1] - end[1]) / 2.0;
  // (x1', y1') of B.2.4 step 1, divided by the radii: a and b.
  double a = (c * hx + s * hy) / rx, b = (-s * hx + c * hy) / ry;
  const double lambda = a * a + b * b;
  // Step 2 divided by rx² ry²: the centre (cx', cy') = k (rx b, -ry a) with
  // k = ±sqrt((1 - λ) / λ). Radii too small (λ >= 1, B.2.5 step 3) are scaled
  // by sqrt(λ) until the ellipse just fits: then k is 0 exactly, the centre
  // the midpoint (the formula after scaling would take the square root of
  // rounding noise and move the centre by sqrt(ε) of the radius).
  double k = 0.0;
  if (lambda >= 1.0) {
    const double grow = std::sqrt(lambda);
    rx *= grow;
    ry *= grow;
    a /= grow;
    b /= grow;
  } else {
    k = std::sqrt((1.0 - lambda) / lambda);
    if (large_arc == sweep) k = -k;
  }
  // The unit vectors from the centre to the ends (step 4's u and v, per radius).
  const double ux = a - k * b, uy = b + k * a;
  const double vx = -a - k * b, vy = -b + k * a;
  const double theta = std::atan2(uy, ux);
  double delta = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  if (!sweep && delta > 0.0) delta -= 2.0 * std::numbers::pi;
  if (sweep && delta < 0.0) delta += 2.0 * std::numbers::pi;
  if (delta == 0.0) return path.add({start, end}, 'a');  // ends apart by rounding only
  auto unit = make_arc(0.0, 0.0, 1.0, theta, delta);
  if (!unit) return unit.error();
  // x = C (rx X, ry Y) + centre, C the rotation by phi; the centre is step 3.
  const double cx = c * k * rx * b + s * k * ry * a + (start[0] + end[0]) / 2.0;
  const double cy = s * k * rx * b - c * k * ry * a + (start[1] + end[1]) / 2.0;
  std::vector<BezierCurve> pieces = to_bezier_pieces(*unit).pieces;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const PointArray& unit_points = pieces[p].control_points();
    std::vector<double> mapped;
    mapped.reserve(unit_points.size() * 2);
    for (std::size_t i = 0; i < unit_points.size(); ++i) {
      const double x = rx * unit_points[i][0], y = ry * unit_points[i][1];
      mapped.push_back(cx + c * x - s * y);
      mapped.push_back(cy + s * x + c * y);
    }
    // The ends are the path's points themselves, not their image to rounding.
    if (p == 0) mapped[0] = start[0], mapped[1] = start[1];
    if (p + 1 == pieces.size()) mapped[mapped.size() - 2] = end[0], mapped.back() = end[1];
    auto piece = BezierCurve::make(PointArray::from_trusted(2, std::move(mapped)),
                                   std::vector<double>(pieces[p].weights().begin(), pieces[p].weights().end()));
    if (!piece) return piece.error();
    pieces[p] = std::move(*piece);
  }
  return path.add_pieces(std::move(pieces), end);
}

/// One segment of `command` (its arguments read from the scanner).
Status read_segment(SvgScanner& in, Builder& path, char command) {
  const Arguments wanted = arguments_of(command);
  std::array<double, 7> value{};
  for (std::size_t i = 0; wanted.kinds[i] != '\0'; ++i) {
    if (i > 0) in.skip_separator();
    if (wanted.kinds[i] == 'f') {
      // flag: '0' or '1', one character, needing no separator after it.
      if (in.done() || (in.peek() != '0' && in.peek() != '1'))
        return in.error(fmt::format("expected a flag (0 or 1), {}", takes(command)));
      value[i] = in.peek() == '1' ? 1.0 : 0.0;
      in.advance();
    } else {
      // The command's arguments are named only when no number is there.
      if (!in.at_number()) return in.error(fmt::format("expected a number, {}", takes(command)));
      auto number = in.number();
      if (!number) return number.error();
      value[i] = *number;
    }
  }
  const bool relative = command >= 'a';
  const Vec2 here = path.current();
  const auto point = [&](std::size_t i) {
    return relative ? Vec2{{here[0] + value[i], here[1] + value[i + 1]}} : Vec2{{value[i], value[i + 1]}};
  };
  switch (command | 0x20) {
    case 'm':
      path.move_to(point(0));
      return {};
    case 'l':
      return path.add({here, point(0)}, 'l');
    case 'h':
      return path.add({here, Vec2{{relative ? here[0] + value[0] : value[0], here[1]}}}, 'l');
    case 'v':
      return path.add({here, Vec2{{here[0], relative ? here[1] + value[0] : value[0]}}}, 'l');
    case 'c':
      return path.add({here, point(0), point(2), point(4)}, 'c');
    case 's':
      return path.add({here, path.cubic_reflection(), point(0), point(2)}, 'c');
    case 'q':
      return path.add({here, point(0), point(2)}, 'q');
    case 't':
      return path.add({here, path.quadratic_reflection(), point(0)}, 'q');
    case 'a':
      return add_arc(path, value[0], value[1], value[2], value[3] != 0.0, value[4] != 0.0, point(5));
    default:
      return {};
  }
}

}  // namespace

SvgPathData read_svg_path(std::string_view data) {
  SvgScanner in(data, "path data");
  Builder path;
  SvgPathData result;
  const auto stop = [&](Error error) {
    result.subpaths = path.take();
    result.error = std::move(error);
    return std::move(result);
  };
  in.skip_spaces();
  if (in.done()) return result;  // empty data draws nothing and is no error
  if (in.peek() != 'M' && in.peek() != 'm')
    return stop(in.error("path data must begin with a moveto, 'M' or 'm'"));
  while (true) {
    in.skip_spaces();
    if (in.done()) break;
    const std::size_t at = in.position();
    const char command = in.peek();
    if (!is_command(command)) return stop(in.error("expected a command letter (M L H V C S Q T A Z, or m l h ...)"));
    in.advance();
    if (command == 'Z' || command == 'z') {
      if (Status closed = path.close(); !closed) return stop(in.error_at(at, closed.error().message));
      continue;
    }
    in.skip_spaces();
    // The first segment, then implicit repeats while numbers follow (after a
    // moveto they are lineto's, SVG 1.1 §8.3.2).
    char segment = command;
    std::size_t segment_start = at;
    while (true) {
      if (Status ok = read_segment(in, path, segment); !ok) {
        // A make() refusal names no place: put it at the segment's start.
        const std::string& message = ok.error().message;
        if (message.rfind("path data", 0) == 0) return stop(ok.error());
        return stop(Error{in.error_at(segment_start, message).message, ok.error().kind});
      }
      if (segment == 'M') segment = 'L';
      if (segment == 'm') segment = 'l';
      // A comma after a command's last number ("L1,1, L2 2") is outside the
      // grammar, but Chromium reads on past it, and so does this reader
      // (tests/svg/ compares the two); what follows must still be a command.
      in.skip_separator();
      if (!in.at_number()) break;
      segment_start = in.position();
    }
  }
  result.subpaths = path.take();
  return result;
}

}  // namespace casteljau
