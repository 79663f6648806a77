// tessellate(): the mesh stays within the tolerance of the surface, is
// watertight where patches (or a patch with itself) share edges, and has the
// surface's normals. Every deviation is measured here independently of the
// tessellator, on dense barycentric samples of every triangle (45 per
// triangle, the vertices, edges and interior):
// - the sphere |x - c| = r: the exact distance | |x - c| - r |;
// - the torus: the exact distance | sqrt((rho - R)^2 + z^2) - r | (rho the
//   distance to the axis);
// - surfaces that are graphs over a plane in their parameters (x = a u,
//   y = b v: a bicubic Bézier patch and a B-spline surface whose control
//   points sit at the Greville abscissae, a Coons patch of such boundaries,
//   the six curved faces of a box): the upper bound |S(u(x), v(x)) - x| with
//   (u, v) read back from the in-plane coordinates, a point of the surface at
//   least as far as the nearest one.
// Numbers (max deviation / tolerance, triangle counts, the uniform grid of the
// same accuracy) are printed as test properties for the closing note.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "casteljau/core/progress.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/mesh.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "casteljau/surfaces/ruled.hpp"
#include "casteljau/surfaces/surface_view.hpp"
#include "support/test_surfaces.hpp"

namespace casteljau {
namespace {

using test::bicubic_patch;

using Vec3 = std::array<double, 3>;
using Distance = std::function<double(const Vec3&)>;

constexpr double kHalfRoot2 = 0.70710678118654752440;

/// The sphere of centre c and radius r as one NURBS patch written by hand (The
/// NURBS Book §8.5, ex. 8.1's construction): the full circle of 9 control
/// points and weights 1, √½ (knots 0,0,0,¼,¼,½,½,¾,¾,1,1,1) along u, the
/// meridian semicircle from the south pole to the north pole (5 points, knots
/// 0,0,0,½,½,1,1,1) along v; P_ij = (x_j C_i, z_j), w_ij = w_i w_j. Its
/// v = 0 and v = 1 edges are the poles, u = 0 and u = 1 the seam.
BSplineSurface sphere(const Vec3& c, double r) {
  const double circle[9][3] = {{1, 0, 1},  {1, 1, kHalfRoot2},   {0, 1, 1},  {-1, 1, kHalfRoot2}, {-1, 0, 1},
                               {-1, -1, kHalfRoot2}, {0, -1, 1}, {1, -1, kHalfRoot2}, {1, 0, 1}};
  const double meridian[5][3] = {{0, -1, 1}, {1, -1, kHalfRoot2}, {1, 0, 1}, {1, 1, kHalfRoot2}, {0, 1, 1}};
  std::vector<double> points, weights;
  for (const auto& a : circle) {
    for (const auto& m : meridian) {
      points.insert(points.end(), {c[0] + r * m[0] * a[0], c[1] + r * m[0] * a[1], c[2] + r * m[1]});
      weights.push_back(a[2] * m[2]);
    }
  }
  return BSplineSurface::from_trusted(2, 2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                                      {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                                      ControlNet::from_trusted(9, 5, PointArray::from_trusted(3, points)), weights);
}

/// A bicubic B-spline surface over [0,7]^2 (10 x 10 control points at the
/// Greville abscissae, so x = u and y = v exactly), flat but for a sharp bump
/// of height 3 at control point (2, 2): most of it needs few triangles, a
/// uniform grid pays the bump's density everywhere.
BSplineSurface bump_surface() {
  const std::vector<double> knots = {0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 7, 7, 7};
  std::vector<double> points;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) {
      const double x = (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
      const double y = (knots[j + 1] + knots[j + 2] + knots[j + 3]) / 3.0;
      points.insert(points.end(), {x, y, i == 2 && j == 2 ? 3.0 : 0.0});
    }
  }
  return BSplineSurface::from_trusted(3, 3, knots, knots,
                                      ControlNet::from_trusted(10, 10, PointArray::from_trusted(3, points)));
}

/// A cubic Bézier curve as a B-spline on [0,1].
BSplineCurve cubic(const std::array<Vec3, 4>& points) {
  std::vector<double> coordinates;
  for (const Vec3& p : points) coordinates.insert(coordinates.end(), p.begin(), p.end());
  return BSplineCurve::from_trusted(3, {0, 0, 0, 0, 1, 1, 1, 1}, PointArray::from_trusted(3, coordinates));
}

/// A Coons patch over [0,2]^2 from four wavy cubic boundaries whose x and y
/// are linear in the parameter (control points equally spaced), so that the
/// bilinearly blended patch has x = 2u, y = 2v exactly.
CoonsPatch coons_patch() {
  const double t = 2.0 / 3.0;
  const BSplineCurve u0 = cubic({{{0, 0, 0}, {0, t, 1}, {0, 2 * t, -0.5}, {0, 2, 0.2}}});
  const BSplineCurve u1 = cubic({{{2, 0, 0.4}, {2, t, -0.8}, {2, 2 * t, 0.6}, {2, 2, 0}}});
  const BSplineCurve v0 = cubic({{{0, 0, 0}, {t, 0, -1}, {2 * t, 0, 1.2}, {2, 0, 0.4}}});
  const BSplineCurve v1 = cubic({{{0, 2, 0.2}, {t, 2, 0.9}, {2 * t, 2, -0.7}, {2, 2, 0}}});
  auto patch = CoonsPatch::make(u0, u1, v0, v1, CoonsBlending::linear);
  EXPECT_TRUE(patch.has_value());
  return *patch;
}

/// One face of the box [-1,1]^3: P(u,v) = o + 2u a + 2v b + bulge n on the
/// four inner control points, n = a x b outwards. Straight edges, so faces
/// meet along exact segments; `reversed` starts at the opposite corner (both
/// parameters run backwards), so some shared edges run in opposite directions.
struct BoxFace {
  Vec3 origin, a, b;
  BezierSurface patch;
};

std::vector<BoxFace> box(double bulge) {
  const std::array<std::array<Vec3, 3>, 6> frames = {{{{{-1, -1, 1}, {1, 0, 0}, {0, 1, 0}}},
                                                      {{{-1, -1, -1}, {0, 1, 0}, {1, 0, 0}}},
                                                      {{{1, -1, -1}, {0, 1, 0}, {0, 0, 1}}},
                                                      {{{-1, -1, -1}, {0, 0, 1}, {0, 1, 0}}},
                                                      {{{-1, 1, -1}, {0, 0, 1}, {1, 0, 0}}},
                                                      {{{-1, -1, -1}, {1, 0, 0}, {0, 0, 1}}}}};
  std::vector<BoxFace> faces;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    Vec3 o = frames[f][0], a = frames[f][1], b = frames[f][2];
    if (f == 1 || f == 2) {  // -Z and +X start at their opposite corner
      for (int k = 0; k < 3; ++k) {
        o[k] += 2 * a[k] + 2 * b[k];
        a[k] = -a[k];
        b[k] = -b[k];
      }
    }
    const Vec3 n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    std::vector<double> points;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const bool inner = i > 0 && i < 3 && j > 0 && j < 3;
        for (int k = 0; k < 3; ++k) {
          points.push_back(o[k] + 2.0 * i / 3 * a[k] + 2.0 * j / 3 * b[k] + (inner ? bulge * n[k] : 0.0));
        }
      }
    }
    faces.push_back({o, a, b, BezierSurface::from_trusted(ControlNet::from_trusted(4, 4, PointArray::from_trusted(3, points)))});
  }
  return faces;
}

Vec3 vertex(const TriangleMesh& mesh, std::uint32_t i) {
  const auto p = mesh.vertices[i];
  return {p[0], p[1], p[2]};
}

/// The largest distance from the mesh to the surface: `distance` at 45
/// barycentric points (i, j, k) / 8 of every triangle.
double max_deviation(const TriangleMesh& mesh, const Distance& distance) {
  constexpr int kSteps = 8;
  double worst = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = vertex(mesh, t[0]), b = vertex(mesh, t[1]), c = vertex(mesh, t[2]);
    for (int i = 0; i <= kSteps; ++i) {
      for (int j = 0; i + j <= kSteps; ++j) {
        const double wa = double(i) / kSteps, wb = double(j) / kSteps, wc = 1.0 - wa - wb;
        const Vec3 x = {wa * a[0] + wb * b[0] + wc * c[0], wa * a[1] + wb * b[1] + wc * c[1],
                        wa * a[2] + wb * b[2] + wc * c[2]};
        worst = std::max(worst, distance(x));
      }
    }
  }
  return worst;
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

Distance sphere_distance(const Vec3& c, double r) {
  return [c, r](const Vec3& x) { return std::abs(norm({x[0] - c[0], x[1] - c[1], x[2] - c[2]}) - r); };
}

Distance torus_distance(double major, double minor) {
  return [major, minor](const Vec3& x) {
    const double rho = std::hypot(x[0], x[1]);
    return std::abs(std::hypot(rho - major, x[2]) - minor);
  };
}

/// |S(x / su, y / sv) - x|: for a surface with x = su u and y = sv v.
Distance graph_distance(SurfaceView surface, double su, double sv) {
  return [surface, su, sv](const Vec3& x) {
    const double u = std::clamp(x[0] / su, surface.domain_u().lower, surface.domain_u().upper);
    const double v = std::clamp(x[1] / sv, surface.domain_v().lower, surface.domain_v().upper);
    const Point s = surface.point_at(u, v);
    return norm({s[0] - x[0], s[1] - x[1], s[2] - x[2]});
  };
}

TriangleMesh tessellated(std::span<const SurfaceView> patches, double tolerance) {
  auto mesh = tessellate(patches, Tolerance{tolerance});
  EXPECT_TRUE(mesh.has_value()) << (mesh ? "" : mesh.error().message);
  return mesh ? *mesh : TriangleMesh{};
}

/// The mesh of an n x n grid over the domain, each cell split into two
/// triangles: the uniform tessellation the adaptive one is compared with.
TriangleMesh uniform_grid(const SurfaceView& surface, int n) {
  TriangleMesh mesh;
  std::vector<double> points;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const Point p = surface.point_at(surface.domain_u().lerp(double(i) / n), surface.domain_v().lerp(double(j) / n));
      points.insert(points.end(), p.begin(), p.end());
    }
  }
  mesh.vertices = PointArray::from_trusted(3, points);
  mesh.normals = PointArray::from_trusted(3, points);
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}


/// Every triangle's own normal agrees with the vertex normals (same side).
void expect_consistent_orientation(const TriangleMesh& mesh) {
  std::size_t disagreeing = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = vertex(mesh, t[0]), b = vertex(mesh, t[1]), c = vertex(mesh, t[2]);
    const Vec3 e = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, f = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 face = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
    for (const std::uint32_t i : t) {
      const auto n = mesh.normals[i];
      if (face[0] * n[0] + face[1] * n[1] + face[2] * n[2] <= 0.0) ++disagreeing;
    }
  }
  EXPECT_EQ(disagreeing, 0u);
}

void record(const std::string& name, double value) { ::testing::Test::RecordProperty(name, std::to_string(value)); }

TEST(Tessellate, SphereWithinToleranceWatertightWithExactNormals) {
  const Vec3 c = {1.0, -0.5, 0.25};
  const double r = 2.0;
  const BSplineSurface surface = sphere(c, r);
  const SurfaceView view[] = {surface};
  std::size_t previous = 0;
  for (const double fraction : {1e-2, 1e-3}) {
    const double tolerance = fraction * r;
    const TriangleMesh mesh = tessellated(view, tolerance);
    const double deviation = max_deviation(mesh, sphere_distance(c, r));
    EXPECT_LE(deviation, tolerance);
    EXPECT_TRUE(mesh_topology(mesh).watertight());
    // Euler's formula of a sphere: V - E + F = 2 with E = 3F/2.
    EXPECT_EQ(2 * mesh.vertices.size(), mesh.triangles.size() + 4);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const auto x = mesh.vertices[i];
      const auto n = mesh.normals[i];
      const Vec3 radial = {(x[0] - c[0]) / r, (x[1] - c[1]) / r, (x[2] - c[2]) / r};
      EXPECT_NEAR(norm(radial), 1.0, 1e-13);
      EXPECT_GE(radial[0] * n[0] + radial[1] * n[1] + radial[2] * n[2], 1.0 - 1e-12) << "vertex " << i;
    }
    expect_consistent_orientation(mesh);
    EXPECT_GT(mesh.triangles.size(), previous);
    previous = mesh.triangles.size();
    const std::string tag = "sphere_" + std::to_string(fraction);
    record(tag + "_deviation_over_tolerance", deviation / tolerance);
    record(tag + "_triangles", static_cast<double>(mesh.triangles.size()));
  }
}

TEST(Tessellate, TorusWithTwoSeamsIsWatertight) {
  const double major = 3.0, minor = 1.0;
  const Vec3 origin = {0, 0, 0}, axis = {0, 0, 1};
  const auto surface = make_torus(origin, axis, major, minor);
  ASSERT_TRUE(surface.has_value());
  const SurfaceView view[] = {*surface};
  std::size_t previous = 0;
  for (const double tolerance : {1e-2, 3e-3}) {
    const TriangleMesh mesh = tessellated(view, tolerance);
    const double deviation = max_deviation(mesh, torus_distance(major, minor));
    EXPECT_LE(deviation, tolerance);
    EXPECT_TRUE(mesh_topology(mesh).watertight());
    // A torus has Euler characteristic 0: V = F/2.
    EXPECT_EQ(2 * mesh.vertices.size(), mesh.triangles.size());
    expect_consistent_orientation(mesh);
    EXPECT_GT(mesh.triangles.size(), previous);
    previous = mesh.triangles.size();
    const std::string tag = "torus_" + std::to_string(tolerance);
    record(tag + "_deviation_over_tolerance", deviation / tolerance);
    record(tag + "_triangles", static_cast<double>(mesh.triangles.size()));
  }
}

TEST(Tessellate, BicubicPatchWithinToleranceWithOneBoundaryLoop) {
  const BezierSurface patch = bicubic_patch();
  const SurfaceView view[] = {patch};
  std::size_t previous = 0;
  for (const double tolerance : {1e-2, 1e-3}) {
    const TriangleMesh mesh = tessellated(view, tolerance);
    const double deviation = max_deviation(mesh, graph_distance(view[0], 3.0, 2.0));
    EXPECT_LE(deviation, tolerance);
    const MeshTopology topology = mesh_topology(mesh);
    // The boundary is one loop through exactly the vertices on the domain's
    // edges (x = 0 or 3, y = 0 or 2 exactly: the patch interpolates its
    // boundary's linear x and y), so it has as many edges as those vertices.
    std::size_t on_boundary = 0;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const auto x = mesh.vertices[i];
      if (x[0] == 0.0 || x[0] == 3.0 || x[1] == 0.0 || x[1] == 2.0) ++on_boundary;
    }
    EXPECT_EQ(topology.boundary_edges, on_boundary);
    EXPECT_GE(on_boundary, 4u);
    EXPECT_EQ(topology.non_manifold_edges, 0u);
    EXPECT_EQ(topology.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(topology.degenerate_triangles, 0u);
    // A disc: V - E + F = 1.
    const std::size_t edges = (3 * mesh.triangles.size() + topology.boundary_edges) / 2;
    EXPECT_EQ(mesh.vertices.size() + mesh.triangles.size(), edges + 1);
    expect_consistent_orientation(mesh);
    EXPECT_GT(mesh.triangles.size(), previous);
    previous = mesh.triangles.size();
    const std::string tag = "bicubic_" + std::to_string(tolerance);
    record(tag + "_deviation_over_tolerance", deviation / tolerance);
    record(tag + "_triangles", static_cast<double>(mesh.triangles.size()));
  }
}

TEST(Tessellate, FlatPatchIsFourTriangles) {
  // A bilinear patch in a plane: one cell, its fan of four triangles.
  const BezierSurface patch =
      BezierSurface::from_trusted(ControlNet::from_trusted(2, 2, PointArray::from_trusted(3, {0, 0, 1, 0, 2, 1, 3, 0, 1, 3, 2, 1})));
  const SurfaceView view[] = {patch};
  const TriangleMesh mesh = tessellated(view, 1e-6);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh_topology(mesh).boundary_edges, 4u);
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) EXPECT_EQ(mesh.normals[i][2], 1.0);
}

TEST(Tessellate, AdaptiveBeatsTheUniformGridOnALocalBump) {
  const BSplineSurface surface = bump_surface();
  const SurfaceView view[] = {surface};
  const double tolerance = 1e-3;
  const TriangleMesh mesh = tessellated(view, tolerance);
  const Distance distance = graph_distance(view[0], 1.0, 1.0);
  const double deviation = max_deviation(mesh, distance);
  EXPECT_LE(deviation, tolerance);
  // The uniform grid with twice the adaptive mesh's triangles still misses
  // the surface by more than the tolerance (near the bump).
  const int n = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(mesh.triangles.size()))));
  const double uniform_deviation = max_deviation(uniform_grid(view[0], n), distance);
  EXPECT_GT(uniform_deviation, tolerance);
  record("bump_deviation_over_tolerance", deviation / tolerance);
  record("bump_triangles", static_cast<double>(mesh.triangles.size()));
  record("bump_uniform_deviation_over_tolerance_at_twice_the_triangles", uniform_deviation / tolerance);
}

TEST(Tessellate, CoonsPatchWithinTolerance) {
  const CoonsPatch patch = coons_patch();
  const SurfaceView view[] = {patch};
  std::size_t previous = 0;
  for (const double tolerance : {1e-2, 1e-3}) {
    const TriangleMesh mesh = tessellated(view, tolerance);
    const double deviation = max_deviation(mesh, graph_distance(view[0], 2.0, 2.0));
    EXPECT_LE(deviation, tolerance);
    const MeshTopology topology = mesh_topology(mesh);
    EXPECT_GT(topology.boundary_edges, 0u);
    EXPECT_EQ(topology.non_manifold_edges + topology.inconsistently_oriented_edges + topology.degenerate_triangles, 0u);
    EXPECT_GT(mesh.triangles.size(), previous);
    previous = mesh.triangles.size();
    const std::string tag = "coons_" + std::to_string(tolerance);
    record(tag + "_deviation_over_tolerance", deviation / tolerance);
    record(tag + "_triangles", static_cast<double>(mesh.triangles.size()));
  }
}

TEST(Tessellate, SixCurvedFacesOfABoxAreWatertight) {
  const std::vector<BoxFace> faces = box(0.4);
  std::vector<SurfaceView> views;
  for (const BoxFace& face : faces) views.emplace_back(face.patch);
  // The distance to the nearest face, each face a graph over its plane.
  const Distance distance = [&faces](const Vec3& x) {
    double best = INFINITY;
    for (const BoxFace& face : faces) {
      const Vec3 d = {x[0] - face.origin[0], x[1] - face.origin[1], x[2] - face.origin[2]};
      const double u = std::clamp((d[0] * face.a[0] + d[1] * face.a[1] + d[2] * face.a[2]) / 2, 0.0, 1.0);
      const double v = std::clamp((d[0] * face.b[0] + d[1] * face.b[1] + d[2] * face.b[2]) / 2, 0.0, 1.0);
      const Point s = point_at(face.patch, u, v);
      best = std::min(best, norm({s[0] - x[0], s[1] - x[1], s[2] - x[2]}));
    }
    return best;
  };
  for (const double tolerance : {1e-2, 3e-3}) {
    const TriangleMesh mesh = tessellated(views, tolerance);
    const MeshTopology topology = mesh_topology(mesh);
    EXPECT_TRUE(topology.watertight()) << topology.boundary_edges << " boundary, "
                                       << topology.inconsistently_oriented_edges << " inconsistent, "
                                       << topology.non_manifold_edges << " non-manifold, "
                                       << topology.degenerate_triangles << " degenerate";
    EXPECT_EQ(2 * mesh.vertices.size(), mesh.triangles.size() + 4);
    const double deviation = max_deviation(mesh, distance);
    EXPECT_LE(deviation, tolerance);
    expect_consistent_orientation(mesh);
    record("box_" + std::to_string(tolerance) + "_deviation_over_tolerance", deviation / tolerance);
    record("box_" + std::to_string(tolerance) + "_triangles", static_cast<double>(mesh.triangles.size()));
  }
}

TEST(Tessellate, RefusesBadRequests) {
  const BSplineSurface surface = sphere({0, 0, 0}, 1.0);
  const SurfaceView view[] = {surface};
  const auto message = [&view](double tolerance) {
    auto mesh = tessellate(view, Tolerance{tolerance});
    return mesh ? std::string("no error") : mesh.error().message;
  };
  EXPECT_EQ(tessellate({}, Tolerance{0.1}).error().message, "no surface to tessellate");
  EXPECT_NE(message(0.0).find("must be finite and > 0"), std::string::npos) << message(0.0);
  EXPECT_NE(message(-1.0).find("must be finite and > 0"), std::string::npos);
  EXPECT_NE(message(NAN).find("must be finite and > 0"), std::string::npos) << message(NAN);
  EXPECT_NE(message(INFINITY).find("must be finite"), std::string::npos);
  EXPECT_NE(message(1e-14).find("below what double precision can check"), std::string::npos) << message(1e-14);
  const BezierSurface flat =
      BezierSurface::from_trusted(ControlNet::from_trusted(2, 2, PointArray::from_trusted(2, {0, 0, 0, 1, 1, 0, 1, 1})));
  const SurfaceView two[] = {surface, flat};
  auto mesh = tessellate(two, Tolerance{0.1});
  ASSERT_FALSE(mesh.has_value());
  EXPECT_EQ(mesh.error().message, "patch 1 is in R^2, tessellation needs 3D surfaces");
}

/// Every fraction a Progress hears.
struct Heard {
  std::vector<double> fractions;
  Progress progress() {
    return Progress{[](void* self, double fraction) { static_cast<Heard*>(self)->fractions.push_back(fraction); },
                    this};
  }
};

// Issue 15: --tolerance 1e-9 on the sphere worked 14.6 s before refusing for
// 10^7 triangles. The estimate refuses before any refinement (the progress
// callback never hears), says what it estimated and suggests a tolerance; at
// that tolerance the estimate leaves the margin of kMeshEstimateMargin.
TEST(Tessellate, RefusesAnImpossibleToleranceBeforeAnyRefinement) {
  const BSplineSurface surface = sphere({0, 0, 0}, 1.0);
  const SurfaceView view[] = {surface};
  Heard heard;
  auto mesh = tessellate(view, Tolerance{1e-9}, heard.progress());
  ASSERT_FALSE(mesh.has_value());
  const std::string& message = mesh.error().message;
  EXPECT_EQ(message.rfind("the tessellation needs at least ", 0), 0u) << message;
  EXPECT_NE(message.find(" triangles at tolerance 1e-09 (estimated from the surfaces' second differences), more "
                         "than the limit of 10000000; a tolerance of "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(" or larger should fit"), std::string::npos) << message;
  EXPECT_TRUE(heard.fractions.empty());
}

// Issue 42 (found by the model_json fuzzer): a sphere with one control point
// moved onto its neighbour has a crease, where the normal flips at every
// scale. The normals' turn split the cells along it down to the finest level,
// millions of them, and the triangle limit refused the surface after 51 s.
// A cell flat at the tolerance's scale (kMeshFlatCellFraction) is no longer
// split for its normals: the crease costs cells of about the tolerance's size.
TEST(Tessellate, ACreaseIsRefinedToTheToleranceNotToTheFinestCells) {
  const BSplineSurface round = sphere({0, 0, 0}, 1.0);
  std::vector<double> points(round.control_net().points().coordinates().begin(),
                             round.control_net().points().coordinates().end());
  // Row 0 (u = 0, the seam), column 3 onto column 2: the meridian folds back on itself.
  for (int c = 0; c < 3; ++c) points[3 * 3 + c] = points[3 * 2 + c];
  const BSplineSurface creased =
      BSplineSurface::make(2, 2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                           ControlNet::make(9, 5, PointArray::make(3, points).value()).value(),
                           std::vector<double>(round.weights().begin(), round.weights().end()))
          .value();
  const SurfaceView view[] = {creased};
  auto mesh = tessellate(view, Tolerance{0.1});
  ASSERT_TRUE(mesh.has_value()) << mesh.error().message;
  EXPECT_LT(mesh->triangles.size(), 20000u);
}

// Issue 42 (the model_json fuzzer): the sphere's u knots with 0.5 three times
// (degree + 1: the two halves no longer meet) was refined along u = 0.5 to the
// finest cells for 48 s before the triangle limit. A jump across a knot line
// is refused at once, named, with what to do.
TEST(Tessellate, RefusesAPatchThatJumpsAcrossAKnotLine) {
  const BSplineSurface round = sphere({0, 0, 0}, 1.0);
  const BSplineSurface broken =
      BSplineSurface::make(2, 2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.5, 0.75, 1, 1, 1}, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                           round.control_net(), std::vector<double>(round.weights().begin(), round.weights().end()))
          .value();
  const SurfaceView view[] = {broken};
  auto mesh = tessellate(view, Tolerance{0.1});
  ASSERT_FALSE(mesh.has_value());
  EXPECT_EQ(mesh.error().message.rfind("patch 0 is not continuous across u = 0.5: it jumps by ", 0), 0u)
      << mesh.error().message;
  EXPECT_NE(mesh.error().message.find("(a knot of multiplicity degree + 1 there, or weights many orders of magnitude "
                                      "apart, make such a jump); split it at that knot"),
            std::string::npos)
      << mesh.error().message;
  // The sphere itself (knots of multiplicity 2 = degree: continuous) is not refused.
  const SurfaceView whole[] = {round};
  EXPECT_TRUE(tessellate(whole, Tolerance{0.1}).has_value());
}

namespace {

/// The unit sphere of tessellate's tests with the weight of control point
/// (row, column) replaced, as the model_json fuzzer mutated it.
BSplineSurface sphere_with_weight(int row, int column, double weight) {
  const BSplineSurface round = sphere({0, 0, 0}, 1.0);
  std::vector<double> weights(round.weights().begin(), round.weights().end());
  weights[static_cast<std::size_t>(row * 5 + column)] = weight;
  return BSplineSurface::make(2, 2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                              round.control_net(), weights)
      .value();
}

}  // namespace

// Issue 42 (the model_json fuzzer): the sphere with the weight beside its
// north pole, (-1, 0, 1), at 7e13. Inside that control point's support the
// surface is the point itself; it reaches the pole only within 10^-13 of
// v = 1, finer than the quadtree's finest cells (2^-40 of a span). Those cells
// could not be halved in v, so they were halved in u instead, ten million
// triangles before the limit refused the sphere (49 s). A cell that must be
// halved where it cannot be is refused at once, with where and by how much.
TEST(Tessellate, RefusesASurfaceThatMovesWithinItsFinestCells) {
  const BSplineSurface pulled = sphere_with_weight(4, 3, 7e13);
  const SurfaceView view[] = {pulled};
  auto mesh = tessellate(view, Tolerance{0.1});
  ASSERT_FALSE(mesh.has_value());
  EXPECT_NE(mesh.error().kind, ErrorKind::limit);
  const std::string& message = mesh.error().message;
  EXPECT_EQ(message.rfind("patch 0: the surface cannot be followed by triangles near (u, v) = (0.", 0), 0u) << message;
  EXPECT_NE(message.find(" in v, continuous only in exact arithmetic (look for weights or control points many orders "
                         "of magnitude apart)"),
            std::string::npos)
      << message;
  // At 1e10 the same surface follows its weight within the finest cells.
  const BSplineSurface steep = sphere_with_weight(4, 3, 1e10);
  const SurfaceView followed[] = {steep};
  auto meshed = tessellate(followed, Tolerance{0.1});
  ASSERT_TRUE(meshed.has_value()) << meshed.error().message;
  EXPECT_TRUE(mesh_topology(*meshed).watertight());
}

// Issue 42: where a huge or tiny weight pulls a side of a cell to one point,
// the normal along that side is meaningless; compared anyway, it split cells
// at the poles until they stood at the depth limit (and, before the limit was
// refused, 1.5 times the triangles elsewhere). Normals are compared only
// along edges longer than the flat scale (kMeshFlatCellFraction): every
// such sphere is meshed, watertight, in fewer triangles than before (1,374,
// 1,730 and 2,516, where the whole-cell test refused the first two and took
// 3,436 for the third).
TEST(Tessellate, NormalsAreComparedOnlyAlongEdgesThatAreNotFlat) {
  for (const auto& [row, column, weight] : {std::tuple{4, 0, 1e-6}, std::tuple{7, 4, 1e6}, std::tuple{4, 0, 1e10}}) {
    const BSplineSurface pulled = sphere_with_weight(row, column, weight);
    const SurfaceView view[] = {pulled};
    auto mesh = tessellate(view, Tolerance{0.1});
    ASSERT_TRUE(mesh.has_value()) << row << ", " << column << ", " << weight << ": " << mesh.error().message;
    EXPECT_TRUE(mesh_topology(*mesh).watertight()) << row << ", " << column << ", " << weight;
    EXPECT_LT(mesh->triangles.size(), 3000u) << row << ", " << column << ", " << weight;
  }
}

// Issue 15: a surface whose control points are all equal gave a 0-triangle
// mesh called watertight. A surface without area (a point, or a curve such as
// the ruled surface between a curve and itself) is refused, named; one edge
// collapsed to a point (a pole) is a surface like any other.
TEST(Tessellate, RefusesPatchesWithoutArea) {
  const auto message = [](std::span<const SurfaceView> views) {
    auto mesh = tessellate(views, Tolerance{0.01});
    return mesh ? "a mesh of " + std::to_string(mesh->triangles.size()) + " triangles" : mesh.error().message;
  };
  const BezierSurface point =
      BezierSurface::from_trusted(ControlNet::from_trusted(2, 2, PointArray::from_trusted(3, {1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3})));
  const SurfaceView one[] = {point};
  EXPECT_EQ(message(one), "patch 0 is degenerate: every point of it is (1, 2, 3), and a point has no triangles");
  const BezierSurface square =
      BezierSurface::from_trusted(ControlNet::from_trusted(2, 2, PointArray::from_trusted(3, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0})));
  const SurfaceView second[] = {square, point};
  EXPECT_EQ(message(second), "patch 1 is degenerate: every point of it is (1, 2, 3), and a point has no triangles");
  const BSplineCurve arc = cubic({{{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0, 0}}});
  const BSplineSurface ruled = ruled_surface(arc, arc).value();
  const SurfaceView curve[] = {ruled};
  EXPECT_EQ(message(curve), "patch 0 is degenerate: it has zero area (its points lie on one curve), so it has no triangles");
  const BSplineCurve dot = cubic({{{4, 4, 4}, {4, 4, 4}, {4, 4, 4}, {4, 4, 4}}});
  const CoonsPatch coons = CoonsPatch::make(dot, dot, dot, dot, CoonsBlending::linear).value();
  const SurfaceView collapsed[] = {coons};
  EXPECT_EQ(message(collapsed), "patch 0 is degenerate: every point of it is (4, 4, 4), and a point has no triangles");
  // A triangle-like patch: the edge u = 0 is the point (0, 0, 1).
  const BezierSurface cone =
      BezierSurface::from_trusted(ControlNet::from_trusted(2, 2, PointArray::from_trusted(3, {0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1, 0})));
  const SurfaceView pole[] = {cone};
  auto mesh = tessellate(pole, Tolerance{0.01});
  ASSERT_TRUE(mesh.has_value()) << mesh.error().message;
  EXPECT_GT(mesh->triangles.size(), 0u);
  EXPECT_EQ(mesh_topology(*mesh).degenerate_triangles, 0u);
}

// Issue 15: long tessellations show progress. The library reports
// non-decreasing fractions in [0, 1], ending at 1, at most
// kMeshProgressReports + 1 times, and often enough to move a progress line.
TEST(Tessellate, ReportsProgressUpToOne) {
  const BSplineSurface surface = sphere({0, 0, 0}, 1.0);
  const SurfaceView view[] = {surface};
  Heard heard;
  ASSERT_TRUE(tessellate(view, Tolerance{1e-3}, heard.progress()).has_value());
  ASSERT_FALSE(heard.fractions.empty());
  EXPECT_EQ(heard.fractions.back(), 1.0);
  EXPECT_GE(heard.fractions.front(), 0.0);
  for (std::size_t i = 1; i < heard.fractions.size(); ++i) EXPECT_LE(heard.fractions[i - 1], heard.fractions[i]);
  EXPECT_LE(heard.fractions.size(), static_cast<std::size_t>(tolerances::kMeshProgressReports) + 1);
  EXPECT_GE(heard.fractions.size(), 50u);
}

}  // namespace
}  // namespace casteljau
