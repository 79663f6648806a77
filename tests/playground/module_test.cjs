// The playground's WebAssembly module under node (node --test): the same
// build-wasm/playground/casteljau.js the page loads. Reference values come
// from the seeds' worked examples and from formulas evaluated here in
// JavaScript, never from the module itself.
'use strict';
const test = require('node:test');
const assert = require('node:assert/strict');

const modulePath = process.env.CASTELJAU_PLAYGROUND_MODULE;
if (!modulePath) throw new Error('set CASTELJAU_PLAYGROUND_MODULE to build-wasm/playground/casteljau.js');
const createCasteljau = require(modulePath);
const ready = createCasteljau();

const notebook = { kind: 'bezier', control: [0, 0, 1, 2, 2, 2, 4, 1, 4, 0] };

test('the notebook polygon: C(0.5) = (2.25, 1.5) by points and by the construction (seed 004)', async () => {
  const m = await ready;
  assert.deepEqual(Array.from(m.pointsAt(notebook, [0.5])), [2.25, 1.5]);
  const levels = m.casteljauConstruction(notebook, 0.5);
  assert.equal(levels.length, 5);
  assert.deepEqual(Array.from(levels[4]), [2.25, 1.5]);
  // Level 1 at t = 1/2: the midpoints of the polygon's sides.
  assert.deepEqual(Array.from(levels[1]), [0.5, 1, 1.5, 2, 3, 1.5, 4, 0.5]);
});

test('the halves of a split join at C(t) and start and end where the curve does', async () => {
  const m = await ready;
  const [left, right] = m.splitAt(notebook, 0.3);
  const point = m.pointsAt(notebook, [0.3]);
  assert.deepEqual(Array.from(left.control.slice(8, 10)), Array.from(point));
  assert.deepEqual(Array.from(right.control.slice(0, 2)), Array.from(point));
  assert.deepEqual(Array.from(left.control.slice(0, 2)), [0, 0]);
  assert.deepEqual(Array.from(right.control.slice(8, 10)), [4, 0]);
});

test('bad input comes back as an error value naming what is wrong', async () => {
  const m = await ready;
  const result = m.pointsAt({ kind: 'bezier', control: [0, 0, NaN, 1] }, [0.5]);
  assert.match(result.error, /NaN/);
  assert.match(m.polyline({ kind: 'nurbs' }, 0.1).error, /kind must be/);
  assert.match(m.polyline({ kind: 'bezier', control: [0, 0, 1] }, 0.1).error, /control points/);
  assert.match(m.interpolateCubic([0, 0, 1, 1, 2, 0], 'not-a-knot', 'uniform').error, /4 points/);
  assert.match(m.interpolateCubic([0, 0, 1, 1, 2, 0, 3, 1], 'sideways', 'uniform').error, /natural/);
});

test('the Bernstein basis sums to 1 and matches C(n,k) t^k (1-t)^(n-k)', async () => {
  const m = await ready;
  const ts = [0, 0.1, 0.5, 0.77, 1];
  const n = 6;
  const values = m.bernsteinBasis(n, ts);
  const binomial = [1, 6, 15, 20, 15, 6, 1];
  ts.forEach((t, j) => {
    let sum = 0;
    for (let k = 0; k <= n; ++k) {
      const expected = binomial[k] * t ** k * (1 - t) ** (n - k);
      assert.ok(Math.abs(values[k * ts.length + j] - expected) <= 1e-15, `B_${k},${n}(${t})`);
      sum += values[k * ts.length + j];
    }
    assert.ok(Math.abs(sum - 1) <= 1e-15);
  });
});

test('C1 Bezier interpolation: Q_i and R_i are seed 000\'s formulas', async () => {
  const m = await ready;
  const P = [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1]];
  const alpha = 1.5;
  const curve = m.interpolateC1Bezier(P.flat(), alpha, false);
  assert.equal(curve.kind, 'piecewise');
  assert.equal(curve.pieces.length, 4);
  const near = (a, b) => Math.abs(a - b) <= 1e-14 * 6;
  for (let i = 1; i + 1 < P.length - 1; ++i) {  // interior pieces: both tangents central
    const c = curve.pieces[i].control;
    for (let d = 0; d < 2; ++d) {
      const Q = P[i][d] + (P[i + 1][d] - P[i - 1][d]) / (3 * alpha);
      const R = P[i + 1][d] - (P[i + 2][d] - P[i][d]) / (3 * alpha);
      assert.ok(near(c[2 + d], Q), `Q_${i}`);
      assert.ok(near(c[4 + d], R), `R_${i}`);
    }
  }
});

test('the NURBS circle lies on the circle; the seed cubic semicircle does not', async () => {
  const m = await ready;
  const circle = m.circle(1, -2, 3);
  const ts = Array.from({ length: 50 }, (_, i) => i / 49);
  const points = m.pointsAt(circle, ts);
  for (let i = 0; i < points.length; i += 2) {
    assert.ok(Math.abs(Math.hypot(points[i] - 1, points[i + 1] + 2) - 3) <= 1e-14 * 3);
  }
  const { exact, cubic } = m.seedSemicircles();
  const onCubic = m.pointsAt(cubic, [0.5]);
  assert.deepEqual(Array.from(onCubic), [0, 3]);  // (-3+3·(-3)+3·3+3)/8, (0+12+12+0)/8
  assert.equal(exact.kind, 'bspline');
  assert.equal(exact.weights.length, 5);
});

test('the B-spline basis is a partition of unity and knot insertion keeps the curve', async () => {
  const m = await ready;
  const knots = [0, 0, 0, 0, 0.3, 0.5, 0.5, 1, 1, 1, 1];
  const us = [0, 0.2, 0.3, 0.45, 0.5, 0.9, 1];
  const basis = m.bsplineBasis(3, knots, 7, 0, 6, us);
  assert.deepEqual(Array.from(m.bsplineBasis(3, knots, 7, 2, 3, us)), Array.from(basis.slice(2 * us.length, 4 * us.length)));
  assert.match(m.bsplineBasis(3, knots, 7, 5, 7, us).error, /range/);
  us.forEach((u, j) => {
    let sum = 0;
    for (let i = 0; i < 7; ++i) sum += basis[i * us.length + j];
    assert.ok(Math.abs(sum - 1) <= 1e-15, `sum at ${u}`);
  });
  const curve = { kind: 'bspline', degree: 3, knots, control: [0, 0, 1, 2, 2, 3, 4, 3, 5, 1, 6, 0, 7, 2] };
  const refined = m.insertKnot(curve, 0.7, 1);
  assert.equal(refined.control.length, curve.control.length + 2);
  const before = m.pointsAt(curve, us), after = m.pointsAt(refined, us);
  for (let i = 0; i < before.length; ++i) assert.ok(Math.abs(before[i] - after[i]) <= 1e-14 * 7);
});

test('Lagrange on Chebyshev nodes passes through the nodes; the nodes are -cos(j pi / n)', async () => {
  const m = await ready;
  const xs = m.chebyshevParameters(9, -1, 1);
  xs.forEach((x, j) => assert.ok(Math.abs(x + Math.cos((j * Math.PI) / 8)) <= 1e-15));
  const points = Array.from(xs).flatMap((x) => [x, 1 / (1 + 25 * x * x)]);
  const at = m.lagrangePoints(points, xs, xs);
  for (let i = 0; i < points.length; ++i) assert.ok(Math.abs(at[i] - points[i]) <= 1e-15);
});

test('queries: nearest point, intersections and arc length on known curves', async () => {
  const m = await ready;
  const line = { kind: 'bezier', control: [0, 0, 4, 4] };
  const nearest = m.closestPoint(line, 0, 4);
  assert.ok(Math.abs(nearest.parameter - 0.5) <= 1e-15 && Math.abs(nearest.distance - Math.SQRT2 * 2) <= 1e-14);
  const other = { kind: 'bezier', control: [0, 4, 4, 0] };
  const meetings = m.intersections(line, other);
  assert.equal(meetings.length, 1);
  assert.deepEqual(Array.from(meetings[0].point), [2, 2]);
  assert.ok(Math.abs(m.arcLength(line) - 4 * Math.SQRT2) <= 1e-9 * 4);
  const us = m.equalArcLengthParameters(line, 5);
  assert.deepEqual(Array.from(us).map((u) => Math.round(u * 1e12) / 1e12), [0, 0.25, 0.5, 0.75, 1]);
});

test('an arc spline of the NURBS circle: arcs on the circle within the tolerance, drawn end to end', async () => {
  const m = await ready;
  const arcs = m.fitArcs(m.circle(0, 0, 5), 1e-6, 8);
  assert.ok(arcs.deviationBound <= 1e-6);
  const count = arcs.segments.length / 5;
  assert.equal(arcs.points.length, count * 9 * 2);
  for (let i = 0; i < arcs.points.length; i += 2) {
    assert.ok(Math.abs(Math.hypot(arcs.points[i], arcs.points[i + 1]) - 5) <= 1e-6 + 1e-12, `point ${i / 2}`);
  }
  assert.match(m.fitArcs(m.circle(0, 0, 5), 1e-6, 0).error, /points per arc/);
});
