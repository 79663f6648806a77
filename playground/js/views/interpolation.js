// View 3: the head and the car of seed 000. C¹ Bézier interpolation with its
// α (one cubic P_i Q_i R_i P_{i+1} per step), Catmull–Rom, and the C² cubic
// spline with each end condition and parameterization; the data points drag.
'use strict';

(function () {
  const METHODS = [['c1-bezier', 'C¹ Bézier (seed 000)'], ['catmull-rom', 'Catmull–Rom'], ['cubic', 'C² cubic spline']];
  const PARAMETERIZATIONS = [['uniform', 'uniform'], ['chord', 'chord length'], ['centripetal', 'centripetal']];
  const ENDS = [['not-a-knot', 'not-a-knot'], ['natural', 'natural'], ['clamped', 'clamped (end chords)'], ['periodic', 'periodic (closed)']];

  function cell(text, x, y) {
    const td = document.createElement('td');
    td.textContent = text;
    if (x !== undefined) { td.dataset.x = String(x); td.dataset.y = String(y); }
    return td;
  }

  function pointCell(flat, i) {
    return cell(`(${PageState.formatNumber(flat[i])}, ${PageState.formatNumber(flat[i + 1])})`, flat[i], flat[i + 1]);
  }

  /// The table of seed 000's inner control points: piece i is P_i Q_i R_i P_{i+1}.
  function c1Table(curve) {
    const table = document.createElement('table');
    table.id = 'control-points';
    const head = document.createElement('tr');
    for (const text of ['piece i', 'P_i', 'Q_i', 'R_i', 'P_i+1']) { const th = document.createElement('th'); th.textContent = text; head.appendChild(th); }
    table.appendChild(head);
    curve.pieces.forEach((piece, i) => {
      const row = document.createElement('tr');
      row.append(cell(String(i)), pointCell(piece.control, 0), pointCell(piece.control, 2), pointCell(piece.control, 4), pointCell(piece.control, 6));
      table.appendChild(row);
    });
    const details = document.createElement('details');
    const summary = document.createElement('summary');
    summary.textContent = `The ${curve.pieces.length} cubics' control points (casteljau interpolate --method c1-bezier gives the same)`;
    details.append(summary, table);
    return details;
  }

  Playground.register({
    id: 'interpolation',
    title: 'Head and car',
    seed: 'Seed 000 (C¹ interpolation by Bézier cubics, Figure 3\'s head and car); Catmull–Rom and C² cubic splines (seed 001 §3).',
    explanation: 'Through every data point, one cubic per step: Q_i = P_i + (P_{i+1} − P_{i−1})/(3α), R_i = P_{i+1} − (P_{i+2} − P_i)/(3α), ' +
      'so R_i, P_{i+1}, Q_{i+1} are aligned and the curve is C¹. α = 2 is Catmull–Rom; the C² spline solves for its tangents instead.',
    defaults: { data: 'head', method: 'c1-bezier', alpha: '1', param: 'uniform', end: 'not-a-knot', closed: '0' },
    mount(context) {
      const { library, controls, values } = context;
      const plot = context.plot({ label: 'interpolating curve through draggable data points', editable: true, height: 440 });
      plot.minimumHandles = 3;
      const state = Object.assign({}, values);
      const initial = () => PageState.handles(window.PlaygroundData[state.data] || window.PlaygroundData.head);
      plot.handles = PageState.parsePoints(values.points) || initial();
      const save = () => context.save(() => Object.assign(state, { points: PageState.formatPoints(plot.handles) }));
      plot.onchange = () => { save(); context.redraw(); };
      /// Shows the data points and the curve's control points (the curve lies in their hull).
      const fitView = () => {
        let extra = [];
        try {
          const c = curve();
          extra = c.kind === 'piecewise' ? c.pieces.map((piece) => piece.control) : [c.control];
        } catch (error) { /* drawn (and reported) by draw() */ }
        plot.fit([PageState.flat(plot.handles), ...extra], 0.05);
      };

      const update = (key) => (value) => { state[key] = String(value); save(); showOptions(); context.redraw(); };
      Controls.select(controls, 'data', [['head', 'head (19 points)'], ['car', 'car (26 points)']], state.data, (value) => {
        state.data = value;
        plot.handles = initial();
        fitView();
        save();
        context.redraw();
      });
      Controls.select(controls, 'method', METHODS, state.method, update('method'));
      const alpha = Controls.slider(controls, 'α', { min: 0.25, max: 4, step: 0.05, value: Number(state.alpha) }, update('alpha'));
      const param = Controls.select(controls, 'parameters', PARAMETERIZATIONS, state.param, update('param'));
      const end = Controls.select(controls, 'ends', ENDS, state.end, update('end'));
      const closed = Controls.checkbox(controls, 'closed', state.closed === '1', (checked) => update('closed')(checked ? '1' : '0'));
      function showOptions() {
        const method = state.method;
        alpha.parentElement.hidden = method !== 'c1-bezier';
        param.parentElement.hidden = method === 'c1-bezier';
        end.parentElement.hidden = method !== 'cubic';
        closed.parentElement.hidden = method === 'cubic';
      }
      showOptions();
      fitView();

      function curve() {
        const points = PageState.flat(plot.handles);
        const isClosed = state.closed === '1';
        if (state.method === 'c1-bezier') return library.interpolateC1Bezier(points, Number(state.alpha), isClosed);
        if (state.method === 'catmull-rom') return library.interpolateCatmullRom(points, state.param, isClosed);
        return library.interpolateCubic(points, state.end, state.param);
      }

      function draw() {
        plot.clear();
        plot.axes();
        const c = curve();
        if (c.kind === 'piecewise') {
          // The tangent segments R_{i-1} P_i Q_i through each joint, and the inner points.
          for (const piece of c.pieces) {
            plot.polyline(piece.control.slice(0, 4), { color: '#0f766e', width: 1 });
            plot.polyline(piece.control.slice(4, 8), { color: '#7c3aed', width: 1 });
            plot.points(piece.control.slice(2, 4), { color: '#0f766e', radius: 3 });
            plot.points(piece.control.slice(4, 6), { color: '#7c3aed', radius: 3 });
          }
        } else {
          plot.polyline(c.control, { color: '#9ca3af', width: 1, dash: [4, 4] });
          plot.points(c.control, { color: '#9ca3af', radius: 2.5 });
        }
        plot.polyline(library.polyline(c, 0.25 * plot.pixel()).points, { color: '#1f4e9c', width: 2.5 });
        plot.drawHandles();
        const summary = document.createElement('p');
        if (c.kind === 'piecewise') {
          summary.innerHTML = `${c.pieces.length} cubics · <span class="legend" style="background:#0f766e"></span>Q_i ` +
            '<span class="legend" style="background:#7c3aed"></span>R_i';
          context.readout(summary, c1Table(c));
        } else {
          summary.textContent = `cubic B-spline with ${c.control.length / 2} control points and ${c.knots.length} knots (dashed: its control polygon)`;
          context.readout(summary);
        }
      }

      return { draw, model: curve, plot };
    },
  });
})();
