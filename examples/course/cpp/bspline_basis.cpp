// Exercise (seed 001 §1.2.3): compute the B-spline basis functions by the
// Cox–de Boor recursion on a clamped knot vector, check that they add up to 1
// over the domain (partition of unity), and plot them. The seed counts the
// order k, casteljau the degree p = k - 1: order 4 is degree 3 here.
//
// casteljau calls: clamped_uniform_knots, validate_knots (a Status; knots
// typed by hand are checked, here by bspline_basis_panel too), basis_function
// (one N_{i,p}(u)), render::bspline_basis_panel, render::BernsteinGraphItem.
//
// What to look at: each printed row sums to 1 up to rounding, also at the
// ends u = 0 and u = 4. In bspline_basis.svg, left: the seven cubic N_i on
// 0 0 0 0 1 2 3 4 4 4 4, each non-zero on at most 4 spans (local control),
// their sum dashed; right: with no interior knot the clamped basis is the
// Bernstein basis of degree 3 (dotted on top), the basis of a Bézier curve.
#include <casteljau/bspline/basis.hpp>         // basis_function
#include <casteljau/bspline/knot_vector.hpp>   // clamped_uniform_knots, validate_knots
#include <casteljau/render/bspline_plots.hpp>  // bspline_basis_panel
#include <casteljau/render/write.hpp>          // write_svg

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "course.hpp"  // fail, write_into

using namespace casteljau;
using course::fail;

int main(int argc, char** argv) {
  if (argc < 2) return fail(Error{std::string("usage: ") + argv[0] + " OUTPUT_DIR"});
  const std::filesystem::path out = argv[1];
  const int degree = 3, count = 7;  // 7 functions N_0..N_6, so 7 + 3 + 1 = 11 knots
  const std::vector<double> knots = clamped_uniform_knots(degree, count, Interval{0.0, 4.0});
  if (auto ok = validate_knots(knots, degree, count); !ok) return fail(ok.error());

  for (const double u : {0.0, 0.5, 1.7, 2.5, 4.0}) {
    double sum = 0.0;
    std::printf("u = %-3g  N_0..N_6 =", u);
    for (int i = 0; i < count; ++i) {
      const double n = basis_function(knots, degree, i, u);  // N_{i,3}(u), Cox–de Boor
      std::printf(" %.4f", n);
      sum += n;
    }
    std::printf("  sum - 1 = %.1e\n", sum - 1.0);
  }

  auto clamped = render::bspline_basis_panel(knots, degree);
  if (!clamped) return fail(clamped.error());
  auto bezier = render::bspline_basis_panel(std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}, degree);
  if (!bezier) return fail(bezier.error());
  for (int k = 0; k <= degree; ++k)  // B_{3,k} from its closed form, dotted on top
    bezier->bernstein_graphs.push_back({degree, k, render::dotted(render::colors::black, 2.5), k ? "" : "B_{3,k}"});
  clamped->title = "knots 0 0 0 0 1 2 3 4 4 4 4";
  bezier->title = "knots 0 0 0 0 1 1 1 1: the Bernstein basis";
  render::Figure figure;
  figure.title = "B-spline basis functions of degree 3 (order 4)";
  figure.width = 1400; figure.height = 520; figure.columns = 2;
  figure.panels = {*clamped, *bezier};

  auto written = course::write_into(out, "bspline_basis.svg", [&](const auto& path) { return render::write_svg(figure, path); });
  if (!written) return fail(written.error());
  return 0;
}
