// View 5: a B-spline under the hand. Its degree, its knots dragged on a ruler
// (a knot dropped on another stacks: multiplicity), the basis functions drawn
// under the curve, the stretch of curve a control point moves, knot insertion
// and de Boor's construction at u.
'use strict';

(function () {
  const SAMPLES = 301;
  const SNAP_PIXELS = 6;  // a knot dragged this close to another joins it (multiplicity + 1)
  const BASIS_DRAWN_AROUND = 8;  // with many control points, the basis functions drawn beside the chosen one

  function hue(i, n) { return `hsl(${Math.round((300 * i) / Math.max(n, 1)) % 360}, 65%, 42%)`; }

  const DEFAULT_POINTS = [[-4, -1], [-3, 2], [-1, 3], [0, 0], [2, -1], [3, 2], [5, 2.5]];

  /// The interior knots of a clamped knot vector: all but the p+1 at each end.
  function interior(knots, degree) { return knots.slice(degree + 1, knots.length - degree - 1); }

  Playground.register({
    id: 'bspline',
    title: 'B-spline',
    seed: 'Seed 001 §4 and seed 004 (B-spline basis by Cox–de Boor, local control, knot insertion); The NURBS Book ch. 2, 5.',
    explanation: 'C(u) = Σ N_{i,p}(u) P_i. Each basis function N_{i,p} lives on [t_i, t_{i+p+1}]: moving P_i changes ' +
      'only that stretch of curve (local control). A knot of multiplicity k lowers the continuity there to C^{p−k}. ' +
      'Inserting a knot adds a control point without changing the curve.',
    defaults: { points: PageState.formatPoints(DEFAULT_POINTS.map(([x, y]) => ({ x, y }))), degree: '3', knots: '', u: '0.4', deboor: '1' },
    mount(context) {
      const { library, controls, values } = context;
      const state = Object.assign({}, values);
      const plot = context.plot({ label: 'B-spline curve with draggable control points', editable: true, height: 380, wide: true });
      const ruler = context.plot({ label: 'knot ruler: drag a knot; drop it on another to stack them', editable: true, equalAspect: false, height: 64, wide: true });
      const basisPlot = context.plot({ label: 'the basis functions N_i,p on the parameter axis', equalAspect: false, height: 170, wide: true });
      plot.handles = PageState.parsePoints(state.points) || DEFAULT_POINTS.map(([x, y]) => ({ x, y }));
      plot.minimumHandles = 2;
      ruler.canAdd = false;
      ruler.minimumHandles = 0;
      let degree = Math.max(1, Math.min(Number(state.degree) || 3, 7));
      let knots = parseKnots(state.knots);
      let u = Number(state.u);
      if (!(u >= 0 && u <= 1)) u = 0.4;

      function parseKnots(text) {
        const list = (text || '').split(',').filter((s) => s !== '').map(Number);
        return list.every(Number.isFinite) ? list : [];
      }
      /// Clamped knots for the current control points: the stored ones when they fit, else uniform.
      function currentKnots() {
        const count = plot.handles.length;
        const inner = count - degree - 1;
        if (inner >= 0 && knots.length === inner && knots.every((k, i) => k > 0 && k < 1 && (i === 0 || k >= knots[i - 1]))) {
          return [...Array(degree + 1).fill(0), ...knots, ...Array(degree + 1).fill(1)];
        }
        const uniform = Array.from(library.clampedUniformKnots(degree, count));
        knots = interior(uniform, degree);
        return uniform;
      }
      const curve = () => {
        if (plot.handles.length < degree + 1) throw new Error(`degree ${degree} needs at least ${degree + 1} control points`);
        return { kind: 'bspline', degree, knots: currentKnots(), control: PageState.flat(plot.handles) };
      };
      const save = () => context.save(() => Object.assign(state, {
        points: PageState.formatPoints(plot.handles), degree: String(degree), knots: knots.map(PageState.formatNumber).join(','), u: String(u) }));

      /// The ruler's handles: one per interior knot, stacked by multiplicity.
      function rulerHandles() {
        const level = new Map();
        ruler.handles = knots.map((k) => {
          const y = level.get(k) || 0;
          level.set(k, y + 1);
          return { x: k, y: 0.35 + 0.55 * y };
        });
      }
      ruler.setBounds(-0.03, 1.03, -0.5, 2);
      plot.fit([PageState.flat(plot.handles)], 0.1);
      plot.onchange = () => {
        // A control point added or removed changes how many knots there are: start from uniform ones.
        if (plot.handles.length - degree - 1 !== knots.length) knots = [];
        save();
        context.redraw();
      };
      ruler.onchange = () => {
        const snap = SNAP_PIXELS / ruler.sx;
        const moving = ruler.dragging >= 0 ? ruler.dragging : ruler.selected;
        const all = ruler.handles.map((h) => Math.min(Math.max(h.x, 1e-6), 1 - 1e-6));
        if (moving >= 0) {
          for (let i = 0; i < all.length; ++i) {
            if (i !== moving && Math.abs(all[i] - all[moving]) < snap) all[moving] = all[i];
          }
          const multiplicity = all.filter((k) => k === all[moving]).length;
          if (multiplicity > degree + 1) all[moving] += snap;  // at most p+1 equal knots
        }
        knots = all.slice().sort((a, b) => a - b);
        // Keep hold of the knot under the pointer when it passes another.
        if (moving >= 0) {
          const at = knots.indexOf(all[moving]);
          ruler.selected = at;
          if (ruler.dragging >= 0) ruler.dragging = at;
        }
        save();
        context.redraw();
      };
      plot.ondraw = ruler.ondraw = basisPlot.ondraw = context.redraw;

      Controls.slider(controls, 'degree p', { min: 1, max: 7, step: 1, value: degree }, (v) => { degree = v; knots = []; save(); context.redraw(); });
      Controls.slider(controls, 'u', { min: 0, max: 1, step: 0.005, value: u }, (v) => { u = v; save(); context.redraw(); });
      Controls.checkbox(controls, 'de Boor construction', state.deboor === '1', (checked) => { state.deboor = checked ? '1' : '0'; save(); context.redraw(); });
      Controls.button(controls, 'Insert knot at u', () => {
        const refined = library.insertKnot(curve(), u, 1);
        plot.handles = PageState.handles(refined.control);
        knots = interior(Array.from(refined.knots), degree);
        save();
        context.redraw();
      });
      Controls.button(controls, 'Uniform knots', () => { knots = []; save(); context.redraw(); });

      function draw() {
        const c = curve();
        const count = plot.handles.length;
        const chosen = plot.selected >= 0 && plot.selected < count ? plot.selected : Math.min(1, count - 1);
        plot.clear();
        plot.axes();
        plot.polyline(c.control, { color: '#9ca3af', width: 1.5, dash: [5, 4] });
        const line = library.polyline(c, 0.25 * plot.pixel());
        plot.polyline(line.points, { color: '#1f4e9c', width: 2.5 });
        // The stretch of curve P_chosen moves: u in [t_i, t_{i+p+1}].
        const low = c.knots[chosen], high = c.knots[chosen + degree + 1];
        const stretch = [];
        for (let j = 0; j < line.parameters.length; ++j) {
          if (line.parameters[j] >= low && line.parameters[j] <= high) stretch.push(line.points[2 * j], line.points[2 * j + 1]);
        }
        plot.polyline(stretch, { color: hue(chosen, count - 1), width: 6 });
        if (state.deboor === '1') {
          const net = library.deBoorConstruction(c, u);
          net.levels.slice(1).forEach((level, r) => {
            plot.polyline(level, { color: '#7c3aed', width: 1.2 });
            plot.points(level, { color: r + 2 === net.levels.length ? '#111827' : '#7c3aed', radius: r + 2 === net.levels.length ? 6 : 3 });
          });
        }
        plot.drawHandles();
        plot.labelHandles();

        rulerHandles();
        ruler.clear();
        ruler.polyline([0, 0.2, 1, 0.2], { color: '#6b7280', width: 1.5 });
        for (let k = 0; k <= 10; ++k) ruler.label(String(k / 10), k / 10, 0.2, { dx: -6, dy: 14, color: '#6b7280', font: '10px system-ui' });
        ruler.polyline([u, -0.5, u, 2], { color: '#7c3aed', width: 1, dash: [3, 3] });
        ruler.drawHandles('#0f766e');

        const us = new Float64Array(SAMPLES).map((_, j) => j / (SAMPLES - 1));
        const first = count > 2 * BASIS_DRAWN_AROUND + 1 ? Math.max(0, chosen - BASIS_DRAWN_AROUND) : 0;
        const last = count > 2 * BASIS_DRAWN_AROUND + 1 ? Math.min(count - 1, chosen + BASIS_DRAWN_AROUND) : count - 1;
        const basis = library.bsplineBasis(degree, c.knots, count, first, last, us);
        basisPlot.setBounds(-0.02, 1.02, -0.08, 1.08);
        basisPlot.clear();
        basisPlot.polyline([0, 0, 1, 0], { color: '#e5e7eb', width: 1 });
        const graph = new Float64Array(2 * SAMPLES);
        for (let i = first; i <= last; ++i) {
          for (let j = 0; j < SAMPLES; ++j) { graph[2 * j] = us[j]; graph[2 * j + 1] = basis[(i - first) * SAMPLES + j]; }
          basisPlot.polyline(graph, { color: hue(i, count - 1), width: i === chosen ? 4 : 1.5 });
        }
        basisPlot.polyline([u, -0.08, u, 1.08], { color: '#7c3aed', width: 1, dash: [3, 3] });

        const text = document.createElement('p');
        text.id = 'bspline-summary';
        text.textContent = `degree ${degree}, ${count} control points, knots ${c.knots.map(PageState.formatNumber).join(' ')} · ` +
          `P${chosen} moves u ∈ [${PageState.formatNumber(low)}, ${PageState.formatNumber(high)}]` +
          (first > 0 || last < count - 1 ? ` · basis drawn for P${first}…P${last}` : '');
        context.readout(text);
      }

      return { draw, model: curve, plot, ruler };
    },
  });
})();
