// casteljau_gcode_check MODEL MOTION.json TOLERANCE DIALECT READER_STEP:
// compares the motion an interpreter we did not write read from a program
// casteljau wrote (npm's gcode-toolpath through interpret.mjs, LinuxCNC's
// rs274 through rs274_motion.py; both write the same JSON) with the curves
// of MODEL the program was made from:
// - no interpreter error; no code it does not know, except G64 and G91.1
//   for the linuxcnc dialect (path blending and the arc centre mode, which
//   move nothing); no whole circle (an arc that ends where it starts);
// - every cut (a G1/G2/G3 in the plane at Z < 0; moves down are vertical)
//   sampled densely lies within TOLERANCE of the curves (closest_point),
//   and every sample of the curves within it of the cuts: the Hausdorff
//   distance, both ways. TOLERANCE is the program's whole budget, the
//   rounding of its numbers included; only the reader's own printing adds
//   to it: READER_STEP is the step of the numbers the interpreter reports
//   (0 when it reports doubles, 1e-4 of the unit for rs274's 4 decimals of
//   a program written with more), and 2 x READER_STEP is allowed on top;
// - the start and end radii of every arc, from the centre the interpreter
//   computed, agree within 1e-4 of the program's unit (+ 3 x READER_STEP);
// - every rapid move in the plane runs above the work (Z > 0).
// Prints the counts and the largest deviations measured; exit status 1 when
// a check fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/ops/bounds.hpp"
#include "casteljau/ops/closest_point.hpp"

namespace {

using namespace casteljau;

// What the writer promises of the radii (1e-4 of the unit), with room for
// the interpreter's inch-to-mm conversion (x 25.4, ~1e-15).
constexpr double kRadiusAgreement = 1e-4 * (1 + 1e-9);
// Samples of each cut and of each curve.
constexpr int kMoveSamples = 24;
constexpr int kCurveSamples = 4000;

struct Move {
  std::string motion;
  double from[3], to[3], centre[3];
};

/// A cut in the plane: a segment, or an arc from `from` about `centre`
/// turning `sweep` (> 0 counterclockwise) with the radius going from
/// start_radius to end_radius (a controller's spiral when they differ).
struct Cut {
  bool arc = false;
  double ax, ay, bx, by, cx, cy;
  double start_angle = 0, sweep = 0, start_radius = 0, end_radius = 0;

  void point(double f, double& x, double& y) const {
    if (!arc) {
      x = ax + f * (bx - ax);
      y = ay + f * (by - ay);
      return;
    }
    const double r = start_radius + f * (end_radius - start_radius), angle = start_angle + f * sweep;
    x = cx + r * std::cos(angle);
    y = cy + r * std::sin(angle);
  }

  double distance_to(double px, double py) const {
    if (!arc) {
      const double dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
      const double f = length2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / length2, 0.0, 1.0) : 0.0;
      return std::hypot(px - (ax + f * dx), py - (ay + f * dy));
    }
    double turn = std::atan2(py - cy, px - cx) - start_angle;
    if (sweep < 0) turn = -turn;
    turn = std::fmod(turn, 2 * std::numbers::pi);
    if (turn < 0) turn += 2 * std::numbers::pi;
    const double ends = std::min(std::hypot(px - ax, py - ay), std::hypot(px - bx, py - by));
    if (turn > std::abs(sweep)) return ends;
    const double f = turn / std::abs(sweep);
    const double r = start_radius + f * (end_radius - start_radius);
    return std::min(ends, std::abs(std::hypot(px - cx, py - cy) - r));
  }
};

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int failures = 0;
void fail(const std::string& what) {
  std::printf("FAIL: %s\n", what.c_str());
  ++failures;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: casteljau_gcode_check MODEL MOTION.json TOLERANCE grbl|linuxcnc READER_STEP\n");
    return 2;
  }
  const std::string model_path = argv[1];
  const double tolerance = std::stod(argv[3]);
  const bool linuxcnc = std::string(argv[4]) == "linuxcnc";
  const double reader_step = std::stod(argv[5]);
  // 1e-9 of the tolerance: room for the rounding of the distances measured here.
  const double bound = tolerance * (1 + 1e-9) + 2 * reader_step;
  const double radius_agreement = kRadiusAgreement + 3 * reader_step;

  auto models = read_models(model_path);
  if (!models) {
    std::printf("FAIL: %s\n", models.error().message.c_str());
    return 1;
  }
  const nlohmann::json motion = nlohmann::json::parse(read_file(argv[2]));
  for (const auto& error : motion["errors"]) fail("the interpreter reported: " + error.get<std::string>());
  for (const auto& code : motion["unhandled"]) {
    const std::string name = code.get<std::string>();
    if (!(linuxcnc && (name == "G64" || name == "G91.1"))) fail("the interpreter does not know " + name);
  }
  // The interpreter works in mm: back to the program's unit.
  const double scale = motion["units"] == "G20" ? 1.0 / 25.4 : 1.0;

  std::vector<Cut> cuts;
  std::size_t arcs = 0, lines = 0;
  double worst_radii = 0;
  for (const auto& m : motion["moves"]) {
    Move move{m["motion"].get<std::string>(), {}, {}, {}};
    for (int k = 0; k < 3; ++k) {
      move.from[k] = m["from"][k].get<double>() * scale;
      move.to[k] = m["to"][k].get<double>() * scale;
      if (m.contains("centre")) move.centre[k] = m["centre"][k].get<double>() * scale;
    }
    const bool in_plane = move.from[0] != move.to[0] || move.from[1] != move.to[1];
    const bool arc = move.motion == "G2" || move.motion == "G3";
    if (move.motion == "G0") {
      if (in_plane && !(move.from[2] > 0 && move.to[2] > 0))
        fail("a rapid move in the plane at Z " + std::to_string(move.from[2]) + " (not above the work)");
      continue;
    }
    if (!arc && move.motion != "G1") {
      fail("unexpected motion " + move.motion);
      continue;
    }
    if (arc && !in_plane) {
      fail("an arc that ends where it starts: a whole circle");
      continue;
    }
    if (!in_plane) continue;  // a move down or up
    if (move.from[2] != move.to[2] || !(move.from[2] < 0)) {
      fail("a cut that is not in a plane below the work, from Z " + std::to_string(move.from[2]));
      continue;
    }
    Cut cut{arc, move.from[0], move.from[1], move.to[0], move.to[1], move.centre[0], move.centre[1]};
    if (arc) {
      ++arcs;
      cut.start_radius = std::hypot(cut.ax - cut.cx, cut.ay - cut.cy);
      cut.end_radius = std::hypot(cut.bx - cut.cx, cut.by - cut.cy);
      const double gap = std::abs(cut.start_radius - cut.end_radius);
      worst_radii = std::max(worst_radii, gap);
      if (gap > radius_agreement)
        fail("arc radii " + std::to_string(cut.start_radius) + " and " + std::to_string(cut.end_radius) + " differ by " +
             std::to_string(gap));
      cut.start_angle = std::atan2(cut.ay - cut.cy, cut.ax - cut.cx);
      double sweep = std::atan2(cut.by - cut.cy, cut.bx - cut.cx) - cut.start_angle;
      const bool counterclockwise = move.motion == "G3";
      if (counterclockwise && sweep <= 0) sweep += 2 * std::numbers::pi;
      if (!counterclockwise && sweep >= 0) sweep -= 2 * std::numbers::pi;
      cut.sweep = sweep;
    } else {
      ++lines;
    }
    cuts.push_back(cut);
  }
  if (cuts.empty()) fail("no cut at all");

  // The cuts to the curves.
  // A curve whose box (ops/bounds.hpp, tight) is farther than the nearest
  // distance found so far cannot be nearer: only the others are asked,
  // the one that was nearest for the previous sample first.
  std::vector<CurveView> curves;
  std::vector<Box> boxes;
  for (const Model& model : *models) {
    curves.push_back(curve_view(model));
    boxes.push_back(bounding_box(curves.back()));
  }
  const auto box_distance = [](const Box& box, double x, double y) {
    const double dx = std::max({box.lower[0] - x, 0.0, x - box.upper[0]});
    const double dy = std::max({box.lower[1] - y, 0.0, y - box.upper[1]});
    return std::hypot(dx, dy);
  };
  double worst_to_curve = 0;
  std::size_t last = 0;
  for (const Cut& cut : cuts)
    for (int s = 0; s <= kMoveSamples; ++s) {
      double x, y;
      cut.point(static_cast<double>(s) / kMoveSamples, x, y);
      double nearest = INFINITY;
      const std::size_t first = last;
      for (std::size_t k = 0; k < curves.size(); ++k) {
        const std::size_t c = k == 0 ? first : (k <= first ? k - 1 : k);
        if (box_distance(boxes[c], x, y) >= nearest) continue;
        auto found = closest_point(curves[c], {x, y});
        if (found && found->distance < nearest) {
          nearest = found->distance;
          last = c;
        }
      }
      worst_to_curve = std::max(worst_to_curve, nearest);
    }
  // The curves to the cuts: a cut whose box (an arc's: its whole circle's)
  // is farther than the nearest distance so far is skipped, the cut nearest
  // the previous sample tried first.
  struct CutBox {
    double lower_x, lower_y, upper_x, upper_y;
  };
  std::vector<CutBox> cut_boxes;
  for (const Cut& cut : cuts) {
    if (cut.arc) {
      const double r = std::max(cut.start_radius, cut.end_radius);
      cut_boxes.push_back({cut.cx - r, cut.cy - r, cut.cx + r, cut.cy + r});
    } else {
      cut_boxes.push_back({std::min(cut.ax, cut.bx), std::min(cut.ay, cut.by), std::max(cut.ax, cut.bx),
                           std::max(cut.ay, cut.by)});
    }
  }
  double worst_to_cuts = 0;
  std::size_t last_cut = 0;
  for (const CurveView& curve : curves) {
    const Interval domain = curve.domain();
    std::vector<double> parameters(kCurveSamples + 1), points((kCurveSamples + 1) * 2);
    for (int s = 0; s <= kCurveSamples; ++s)
      parameters[s] = domain.lower + (domain.upper - domain.lower) * s / kCurveSamples;
    points_at(curve, parameters, points);
    for (int s = 0; s <= kCurveSamples; ++s) {
      const double x = points[2 * s], y = points[2 * s + 1];
      double nearest = cuts[last_cut].distance_to(x, y);
      for (std::size_t c = 0; c < cuts.size(); ++c) {
        const CutBox& box = cut_boxes[c];
        if (box.lower_x - x >= nearest || x - box.upper_x >= nearest || box.lower_y - y >= nearest ||
            y - box.upper_y >= nearest)
          continue;
        const double d = cuts[c].distance_to(x, y);
        if (d < nearest) {
          nearest = d;
          last_cut = c;
        }
      }
      worst_to_cuts = std::max(worst_to_cuts, nearest);
    }
  }
  if (worst_to_curve > bound) fail("a cut is " + std::to_string(worst_to_curve) + " from the curves");
  if (worst_to_cuts > bound) fail("a point of the curves is " + std::to_string(worst_to_cuts) + " from the cuts");
  std::printf("%s: %zu curve%s, %zu arcs and %zu lines cut; largest distance cut to curve %.6g, curve to cut %.6g "
              "(bound %.6g); arc radii agree within %.2g\n",
              model_path.c_str(), curves.size(), curves.size() == 1 ? "" : "s", arcs, lines, worst_to_curve,
              worst_to_cuts, bound, worst_radii);
  return failures == 0 ? 0 : 1;
}
