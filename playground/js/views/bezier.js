// View 2: a Bézier curve under the hand: its control polygon, de Casteljau's
// construction at t (every level), the split at t, degree elevation, Bézier's
// vector form (seed 003's "pantin") and the convex hull.
'use strict';

(function () {
  const LEVEL_COLORS = ['#9ca3af', '#0f766e', '#7c3aed', '#b45309', '#be185d', '#2563eb', '#4d7c0f'];

  /// The convex hull of handles (Andrew's monotone chain), counter-clockwise, flat.
  function convexHull(handles) {
    const p = handles.map((h) => [h.x, h.y]).sort((a, b) => a[0] - b[0] || a[1] - b[1]);
    if (p.length < 3) return p.flat();
    const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    const lower = [], upper = [];
    for (const q of p) {
      while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
      lower.push(q);
    }
    for (const q of p.slice().reverse()) {
      while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
      upper.push(q);
    }
    return lower.slice(0, -1).concat(upper.slice(0, -1)).flat();
  }

  function formatPoint(flat, i = 0) {
    return `(${PageState.formatNumber(flat[i])}, ${PageState.formatNumber(flat[i + 1])})`;
  }

  Playground.register({
    id: 'bezier',
    title: 'Bézier curve',
    seed: 'Seed 004 §2–4 (de Casteljau, subdivision); seed 003 §1 (vector form, the "pantin"); seed 001 §2 (degree elevation, convex hull).',
    explanation: 'C(t) = Σ B_{k,n}(t) P_k. De Casteljau\'s construction repeats the division at ratio t on every side: ' +
      'its last point is C(t), its first and last points per level are the control polygons of the two halves. ' +
      'The curve stays in the convex hull of its control points.',
    defaults: { points: PageState.formatPoints(PageState.handles(window.PlaygroundData.notebook)), t: '0.5', levels: '1', hull: '0', split: '0', vector: '0' },
    mount(context) {
      const { library, controls, values } = context;
      const plot = context.plot({ label: 'Bézier curve with draggable control points', editable: true, height: 420 });
      plot.handles = PageState.parsePoints(values.points) || PageState.handles(window.PlaygroundData.notebook);
      plot.minimumHandles = 2;
      let t = Number(values.t);
      if (!(t >= 0 && t <= 1)) t = 0.5;
      const flags = { levels: values.levels === '1', hull: values.hull === '1', split: values.split === '1', vector: values.vector === '1' };
      const control = () => PageState.flat(plot.handles);
      const curve = () => ({ kind: 'bezier', control: control() });
      const save = () => context.save(() => ({ points: PageState.formatPoints(plot.handles), t: String(t),
        levels: flags.levels ? '1' : '0', hull: flags.hull ? '1' : '0', split: flags.split ? '1' : '0', vector: flags.vector ? '1' : '0' }));
      plot.onchange = () => { save(); context.redraw(); };
      plot.fit([control()], 0.15);

      Controls.slider(controls, 't', { min: 0, max: 1, step: 0.01, value: t }, (v) => { t = v; save(); context.redraw(); });
      for (const [key, text] of [['levels', 'construction'], ['hull', 'convex hull'], ['split', 'split at t'], ['vector', 'vector form']]) {
        Controls.checkbox(controls, text, flags[key], (checked) => { flags[key] = checked; save(); context.redraw(); });
      }
      Controls.button(controls, 'Elevate degree', () => {
        const elevated = library.elevateDegree(curve());
        plot.handles = PageState.handles(elevated.control);
        save();
        context.redraw();
      });
      Controls.button(controls, 'Fit view', () => { plot.fit([control()], 0.15); context.redraw(); });

      function draw() {
        const c = curve();
        plot.clear();
        plot.axes();
        if (flags.hull) plot.polyline(convexHull(plot.handles), { fill: 'rgba(31, 78, 156, 0.08)', color: '#93c5fd', width: 1, close: true });
        plot.polyline(c.control, { color: '#9ca3af', width: 1.5, dash: [5, 4] });
        const line = library.polyline(c, 0.25 * plot.pixel());
        const levels = library.casteljauConstruction(c, t);
        if (flags.split) {
          const [left, right] = library.splitAt(c, t);
          plot.polyline(library.polyline(left, 0.25 * plot.pixel()).points, { color: '#0f766e', width: 4 });
          plot.polyline(library.polyline(right, 0.25 * plot.pixel()).points, { color: '#b45309', width: 4 });
          plot.polyline(left.control, { color: '#0f766e', width: 1 });
          plot.points(left.control, { color: '#0f766e', radius: 3 });
          plot.polyline(right.control, { color: '#b45309', width: 1 });
          plot.points(right.control, { color: '#b45309', radius: 3 });
        } else {
          plot.polyline(line.points, { color: '#1f4e9c', width: 3 });
        }
        if (flags.levels) {
          levels.slice(1, -1).forEach((level, r) => {
            const color = LEVEL_COLORS[(r + 1) % LEVEL_COLORS.length];
            plot.polyline(level, { color, width: 1.5 });
            plot.points(level, { color, radius: 3 });
          });
        }
        if (flags.vector) drawVectorForm(c);
        const point = levels[levels.length - 1];
        plot.points(point, { color: '#111827', radius: 6 });
        plot.drawHandles();
        plot.labelHandles();

        const readout = document.createElement('p');
        const shown = document.createElement('span');
        shown.id = 'point-at-t';
        shown.dataset.x = String(point[0]);
        shown.dataset.y = String(point[1]);
        shown.textContent = `C(${PageState.formatNumber(t)}) = ${formatPoint(point)}`;
        readout.append(shown, ` · degree ${plot.handles.length - 1} · drawn with ${line.points.length / 2} certified vertices ` +
          `(within ¼ pixel of the curve)`);
        context.readout(readout);
      }

      /// P(t) = V_0 + Σ f_i(t) V_i: the chain of scaled sides, Bézier's articulated "pantin".
      function drawVectorForm(c) {
        const { vectors, factors } = library.vectorForm(c, t);
        const chain = [vectors[0], vectors[1]];
        for (let i = 1; i < factors.length; ++i) {
          const [x, y] = chain.slice(-2);
          chain.push(x + factors[i] * vectors[2 * i], y + factors[i] * vectors[2 * i + 1]);
        }
        plot.polyline(chain, { color: '#be185d', width: 2.5 });
        plot.points(chain, { color: '#be185d', radius: 3 });
      }

      return { draw, model: curve, plot };
    },
  });
})();
