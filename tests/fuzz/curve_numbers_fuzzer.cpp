// Fuzz target: the numeric entry points on arbitrary doubles. The bytes
// choose a kind (Bézier, piecewise Bézier, B-spline or NURBS curve, Bézier or
// B-spline surface), its shape, and then every coordinate, weight and knot
// as raw doubles (NaN, infinities, subnormals, 1e308 included). make() must
// refuse bad values with a message; what it accepts must evaluate, split and
// go through every operation (fuzz_support.hpp).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace casteljau;

/// Reads small numbers and doubles off the fuzzer's bytes; zeros once they run out.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  /// A number in [low, high].
  int small(int low, int high) {
    const int byte = at_ < size_ ? data_[at_++] : 0;
    return low + byte % (high - low + 1);
  }
  double number() {
    double value = 0.0;
    if (at_ + sizeof value <= size_) {
      std::memcpy(&value, data_ + at_, sizeof value);
      at_ += sizeof value;
    }
    return value;
  }
  std::vector<double> numbers(std::size_t count) {
    std::vector<double> out(count);
    for (double& v : out) v = number();
    return out;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

Expected<PointArray> points(Bytes& bytes, int dimension, std::size_t count) {
  return PointArray::make(dimension, bytes.numbers(static_cast<std::size_t>(dimension) * count));
}

/// Weights, when the bytes ask for them.
std::vector<double> weights(Bytes& bytes, std::size_t count) {
  return bytes.small(0, 1) ? bytes.numbers(count) : std::vector<double>{};
}

/// A refusal is an answer when it says why; the input ends here.
int refused(const Error& error, const char* what) {
  fuzz::require_message(error, what);
  return 0;
}

void check(const Expected<Model>& model, const char* what) {
  if (!model) {
    fuzz::require_message(model.error(), what);
    return;
  }
  fuzz::exercise_model(*model);
  if (const auto* bezier = std::get_if<BezierCurve>(&*model)) {
    // Splitting a valid curve strictly inside its domain gives two curves;
    // at an end it is refused with a message.
    for (double t : {0x1p-40, 0.37, 1.0 - 0x1p-53}) {
      fuzz::require(split_at(*bezier, t).has_value(), "split_at of a valid Bézier curve inside (0,1) succeeds");
    }
    for (double t : {0.0, 1.0}) {
      auto halves = split_at(*bezier, t);
      fuzz::require(!halves.has_value(), "split_at at an end of the domain is refused");
      fuzz::require_message(halves.error(), "split_at");
    }
  }
}

template <class T>
Expected<Model> as_model(Expected<T> value) {
  if (!value) return value.error();
  return Model(std::move(*value));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes bytes(data, size);
  const int kind = bytes.small(0, 4);
  const int dimension = bytes.small(1, 3);
  switch (kind) {
    case 0: {  // Bézier curve, degree 0..24
      const std::size_t count = static_cast<std::size_t>(bytes.small(1, 25));
      auto control = points(bytes, dimension, count);
      if (!control) return refused(control.error(), "PointArray::make");
      check(as_model(BezierCurve::make(std::move(*control), weights(bytes, count))), "BezierCurve::make");
      break;
    }
    case 1: {  // piecewise Bézier: 1..6 pieces of degree 1..5
      const int pieces = bytes.small(1, 6);
      std::vector<BezierCurve> curves;
      for (int i = 0; i < pieces; ++i) {
        const std::size_t count = static_cast<std::size_t>(bytes.small(2, 6));
        auto control = points(bytes, dimension, count);
        if (!control) return refused(control.error(), "PointArray::make");
        auto piece = BezierCurve::make(std::move(*control), weights(bytes, count));
        if (!piece) return refused(piece.error(), "BezierCurve::make");
        curves.push_back(std::move(*piece));
      }
      check(as_model(PiecewiseBezierCurve::make(std::move(curves))), "PiecewiseBezierCurve::make");
      break;
    }
    case 2: {  // B-spline or NURBS curve: degree 0..7, up to 40 control points, any knots
      const int degree = bytes.small(0, 7);
      const std::size_t count = static_cast<std::size_t>(bytes.small(1, 40));
      auto control = points(bytes, dimension, count);
      if (!control) return refused(control.error(), "PointArray::make");
      auto knots = bytes.numbers(count + static_cast<std::size_t>(degree) + 1);
      if (bytes.small(0, 1)) std::sort(knots.begin(), knots.end());  // often valid, so the operations run
      check(as_model(BSplineCurve::make(degree, std::move(knots), std::move(*control), weights(bytes, count))),
            "BSplineCurve::make");
      break;
    }
    case 3: {  // Bézier surface, up to 6 x 6
      const std::size_t rows = static_cast<std::size_t>(bytes.small(1, 6)), columns = static_cast<std::size_t>(bytes.small(1, 6));
      auto control = points(bytes, 3, rows * columns);
      if (!control) return refused(control.error(), "PointArray::make");
      auto net = ControlNet::make(rows, columns, std::move(*control));
      if (!net) return refused(net.error(), "ControlNet::make");
      check(as_model(BezierSurface::make(std::move(*net), weights(bytes, rows * columns))), "BezierSurface::make");
      break;
    }
    default: {  // B-spline surface: degrees 0..4, up to 8 x 8
      const int p = bytes.small(0, 4), q = bytes.small(0, 4);
      const std::size_t rows = static_cast<std::size_t>(bytes.small(1, 8)), columns = static_cast<std::size_t>(bytes.small(1, 8));
      auto control = points(bytes, 3, rows * columns);
      if (!control) return refused(control.error(), "PointArray::make");
      auto net = ControlNet::make(rows, columns, std::move(*control));
      if (!net) return refused(net.error(), "ControlNet::make");
      auto knots_u = bytes.numbers(rows + static_cast<std::size_t>(p) + 1);
      auto knots_v = bytes.numbers(columns + static_cast<std::size_t>(q) + 1);
      if (bytes.small(0, 1)) {
        std::sort(knots_u.begin(), knots_u.end());
        std::sort(knots_v.begin(), knots_v.end());
      }
      check(as_model(BSplineSurface::make(p, q, std::move(knots_u), std::move(knots_v), std::move(*net),
                                          weights(bytes, rows * columns))),
            "BSplineSurface::make");
      break;
    }
  }
  return 0;
}
