// View 6: NURBS. The exact circle as a rational quadratic B-spline whose
// weights one changes by hand, and seed 003's semicircle: exact (NURBS) against
// the cubic Bézier the seed uses, with the cubic's radial error.
'use strict';

(function () {
  const SAMPLES = 721;

  /// The largest | |C(u) - centre| - radius | over sampled points.
  function radialError(points, cx, cy, radius) {
    let error = 0;
    for (let i = 0; i < points.length; i += 2) error = Math.max(error, Math.abs(Math.hypot(points[i] - cx, points[i + 1] - cy) - radius));
    return error;
  }

  Playground.register({
    id: 'nurbs',
    title: 'NURBS',
    seed: 'Seed 003 §2–3 (rational curves, the exact circle, the CNC semicircle and its cubic approximation); seed 001 §5.',
    explanation: 'C(u) = Σ w_i N_{i,p}(u) P_i / Σ w_i N_{i,p}(u). With weights 1, √½, 1, √½, … on a square, the quadratic ' +
      'B-spline is exactly a circle; raise a weight and the curve is pulled towards its point. No polynomial curve is a circle: ' +
      'the seed\'s cubic semicircle misses by 1.8 % of the radius.',
    defaults: { weights: '', points: '' },
    mount(context) {
      const { library, controls, values } = context;
      const state = Object.assign({}, values);
      const circle = library.circle(0, 0, 2);
      const plot = context.plot({ label: 'NURBS circle with draggable control points and adjustable weights', editable: true, height: 380 });
      const seedPlot = context.plot({ label: 'seed 003 semicircle: exact NURBS and cubic Bézier', height: 380 });
      plot.handles = PageState.parsePoints(state.points) || PageState.handles(circle.control);
      if (plot.handles.length !== circle.control.length / 2) plot.handles = PageState.handles(circle.control);
      plot.canAdd = false;
      plot.minimumHandles = plot.handles.length;  // the knots fit nine points: no adding or removing here
      let weights = (state.weights || '').split(',').filter((s) => s).map(Number);
      if (weights.length !== plot.handles.length || !weights.every((w) => w > 0)) weights = Array.from(circle.weights);
      plot.selected = 1;
      plot.fit([circle.control], 0.12);
      const save = () => context.save(() => Object.assign(state, {
        points: PageState.formatPoints(plot.handles), weights: weights.map(PageState.formatNumber).join(',') }));
      plot.onchange = () => { save(); context.redraw(); };

      const weight = Controls.slider(controls, 'weight of the chosen point', { min: 0.05, max: 5, step: 'any', value: weights[plot.selected],
        format: (v) => v.toFixed(3) }, (v) => { weights[plot.selected] = v; save(); context.redraw(); });
      Controls.button(controls, 'Exact circle', () => {
        plot.handles = PageState.handles(circle.control);
        weights = Array.from(circle.weights);
        save();
        context.redraw();
      });
      const curve = () => ({ kind: 'bspline', degree: circle.degree, knots: circle.knots, control: PageState.flat(plot.handles), weights: Float64Array.from(weights) });

      const { exact, cubic } = library.seedSemicircles();
      seedPlot.fit([exact.control, cubic.control], 0.08);
      const ts = new Float64Array(SAMPLES).map((_, j) => j / (SAMPLES - 1));

      function draw() {
        const c = curve();
        weight.set(weights[plot.selected] ?? 1);
        plot.clear();
        plot.axes();
        plot.polyline(c.control, { color: '#9ca3af', width: 1.5, dash: [5, 4] });
        const line = library.polyline(c, 0.25 * plot.pixel());
        plot.polyline(line.points, { color: '#1f4e9c', width: 3 });
        plot.drawHandles();
        plot.labelHandles((i) => `w${i}=${PageState.formatNumber(weights[i])}`);
        const onCircle = radialError(library.pointsAt(c, ts.map((t) => t * (c.knots[c.knots.length - 1] - c.knots[0]) + c.knots[0])), 0, 0, 2);

        seedPlot.clear();
        seedPlot.axes();
        seedPlot.polyline(cubic.control, { color: '#fca5a5', width: 1, dash: [4, 4] });
        seedPlot.points(cubic.control, { color: '#dc2626', radius: 3 });
        const exactPoints = library.pointsAt(exact, ts);
        const cubicPoints = library.pointsAt(cubic, ts);
        seedPlot.polyline(exactPoints, { color: '#1f4e9c', width: 3 });
        seedPlot.polyline(cubicPoints, { color: '#dc2626', width: 2, dash: [7, 4] });
        const cubicError = radialError(cubicPoints, 0, 0, 3);

        const text = document.createElement('p');
        text.id = 'nurbs-errors';
        text.dataset.circle = String(onCircle);
        text.dataset.cubic = String(cubicError);
        text.innerHTML = `Left: largest distance to the circle of radius 2, ${onCircle.toExponential(2)} ` +
          `(${onCircle < 1e-12 ? 'exact to rounding' : 'no longer a circle'}). Right, radius 3: ` +
          '<span class="legend" style="background:#1f4e9c"></span>NURBS, exact; ' +
          `<span class="legend" style="background:#dc2626"></span>seed's cubic (−3,0) (−3,4) (3,4) (3,0), off by up to ${cubicError.toFixed(4)} ` +
          `(${((100 * cubicError) / 3).toFixed(2)} % of the radius).`;
        context.readout(text);
      }

      return { draw, model: curve, plot };
    },
  });
})();
