// SVG path data to Bézier pieces (io/svg_path.hpp says what and why).
#include "casteljau/io/svg_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"
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
/// notes B.2.4, B.2.5: out-of-range radii grow until the ellipse just fits),
/// as rational quadratic pieces of at most a quarter turn each (weights 1,
/// cos h, 1 for a piece over 2h of the circle; The NURBS Book §7.3). Worked
/// in the ellipse's frame divided by its shape, where it is a circle, and
/// built from the chord's midpoint M: with T the half chord from M to the end,
/// N the same turned towards the arc's middle, ℓ = |T| / radius and β the half
/// sweep (sin β = ℓ), the circle's point at angle φ from the middle is
/// M + (sin φ T + (cos φ − cos β) N) / ℓ. Every offset is of the chord's size,
/// so an arc of radius 1e12 over a chord of 10 keeps its sagitta (1.25e-11)
/// where a centre 1e12 away would round it to 1e-4, and neither a tiny radius
/// (divided into) nor a huge one (squared) overflows.
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
  // The ellipse's shape (the larger radius 1) and size.
  const double size = std::max(rx, ry), shape_x = rx / size, shape_y = ry / size;
  // T: the half chord in the ellipse's frame, divided by the shape.
  const double hx = (end[0] - start[0]) / 2.0, hy = (end[1] - start[1]) / 2.0;
  const double tx = (c * hx + s * hy) / shape_x, ty = (-s * hx + c * hy) / shape_y;
  const double reach = std::hypot(tx, ty);
  if (!std::isfinite(reach))
    return Error{fmt::format("the arc's radii {:g} and {:g} make an ellipse too flat to reach its end point", rx, ry)};
  // ℓ, the half chord of the unit circle: radii too small for the chord
  // (B.2.5 step 3, λ = (reach / size)² >= 1) grow until it is a diameter.
  const bool grown = reach >= size;
  const double lambda = grown ? 1.0 : (tx / size) * (tx / size) + (ty / size) * (ty / size);
  const double half = grown ? 1.0 : std::sqrt(lambda);
  const double beta = large_arc ? std::numbers::pi - std::asin(half) : std::asin(half);
  // N: T turned a quarter towards the arc's middle, to the right of the chord
  // for a positive sweep (the centre is on its left).
  const double nx = sweep ? ty : -ty, ny = sweep ? -tx : tx;
  // A quarter turn per piece; a piece of 2h has the weight cos h.
  const int count = std::max(1, static_cast<int>(std::ceil(2.0 * beta / (std::numbers::pi / 2.0) - 1e-9)));
  const double h = beta / count;
  const Vec2 middle{{start[0] + hx, start[1] + hy}};
  // A point of the frame, from M, back to the drawing.
  const auto placed = [&](double along, double across) {
    const double x = shape_x * (along * tx + across * nx), y = shape_y * (along * ty + across * ny);
    return Vec2{{middle[0] + c * x - s * y, middle[1] + s * x + c * y}};
  };
  // The circle's point at angle f from the middle: cos f − cos β written as
  // a product, exact to rounding however small both are.
  const auto on_circle = [&](double f) {
    return placed(std::sin(f) / half, 2.0 * std::sin((beta + f) / 2.0) * std::sin((beta - f) / 2.0) / half);
  };
  std::vector<BezierCurve> pieces;
  for (int j = 0; j < count; ++j) {
    const double from = -beta + 2.0 * h * j, centre = from + h;
    // The tangents' meeting point: the circle's point at `centre` divided by
    // cos h. One piece (a small arc): (ℓ / cos β) N, ℓ / cos β = sqrt(λ / (1 − λ)),
    // exact where λ is (a quarter circle's corner).
    const Vec2 apex = count == 1 ? placed(0.0, std::sqrt(lambda / (1.0 - lambda)))
                                 : placed(std::sin(centre) / std::cos(h) / half,
                                          (2.0 * std::sin((h + centre) / 2.0) * std::sin((h - centre) / 2.0) /
                                               std::cos(h) +
                                           2.0 * std::sin(beta / 2.0) * std::sin(beta / 2.0)) /
                                              half);
    const Vec2 first = j == 0 ? start : on_circle(from);
    const Vec2 last = j + 1 == count ? end : on_circle(from + 2.0 * h);
    const double weight = count == 1 ? std::sqrt(1.0 - lambda) : std::cos(h);
    auto piece = BezierCurve::make(
        PointArray::from_trusted(2, {first[0], first[1], apex[0], apex[1], last[0], last[1]}), {1.0, weight, 1.0});
    if (!piece) return piece.error();
    pieces.push_back(std::move(*piece));
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
