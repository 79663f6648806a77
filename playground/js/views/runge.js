// View 4: Runge's phenomenon. Lagrange interpolation of 1/(1 + 25x²) on n+1
// uniform nodes oscillates more as n grows; on Chebyshev nodes it converges;
// a natural spline of order q through the uniform nodes never oscillates so.
'use strict';

(function () {
  const SAMPLES = 801;
  const runge = (x) => 1 / (1 + 25 * x * x);

  function nodes(xs) {
    const flat = new Float64Array(2 * xs.length);
    xs.forEach((x, i) => { flat[2 * i] = x; flat[2 * i + 1] = runge(x); });
    return flat;
  }

  /// max |y - f(x)| over the sampled points of an interpolant (x, y) pairs.
  function largestError(flat) {
    let error = 0;
    for (let i = 0; i < flat.length; i += 2) error = Math.max(error, Math.abs(flat[i + 1] - runge(flat[i])));
    return error;
  }

  Playground.register({
    id: 'runge',
    title: 'Runge',
    seed: 'Seed 001 §3 (Lagrange interpolation, Runge\'s example, Chebyshev nodes; natural splines of order q).',
    explanation: 'The polynomial of degree n through n+1 equally spaced samples of 1/(1+25x²) swings wider near ±1 as n grows; ' +
      'on Chebyshev nodes (clustered at the ends) its error falls with n. The natural spline of order q (degree 2q−1) ' +
      'through the same equally spaced nodes stays close.',
    defaults: { n: '10', q: '2', uniform: '1', chebyshev: '1', spline: '1' },
    mount(context) {
      const { library, controls, values } = context;
      const state = Object.assign({}, values);
      const plot = context.plot({ label: 'Runge function and its interpolants on [-1, 1]', equalAspect: false, height: 400 });
      plot.setBounds(-1.05, 1.05, -0.6, 1.6);
      const save = () => context.save(state);
      const set = (key) => (v) => { state[key] = String(v); save(); context.redraw(); };
      Controls.slider(controls, 'n (degree)', { min: 2, max: 40, step: 1, value: Number(state.n) }, set('n'));
      Controls.slider(controls, 'spline order q', { min: 1, max: 4, step: 1, value: Number(state.q) }, set('q'));
      for (const [key, text] of [['uniform', 'Lagrange, uniform'], ['chebyshev', 'Lagrange, Chebyshev'], ['spline', 'natural spline']]) {
        Controls.checkbox(controls, text, state[key] === '1', (checked) => set(key)(checked ? '1' : '0'));
      }
      const xs = new Float64Array(SAMPLES).map((_, j) => -1 + (2 * j) / (SAMPLES - 1));
      const truth = nodes(Array.from(xs));
      let shown = null;

      function draw() {
        const n = Number(state.n), q = Number(state.q);
        const uniformX = Array.from({ length: n + 1 }, (_, i) => -1 + (2 * i) / n);
        const uniform = nodes(uniformX);
        const chebyshevX = library.chebyshevParameters(n + 1, -1, 1);
        const chebyshev = nodes(Array.from(chebyshevX));
        plot.clear();
        plot.axes();
        plot.polyline(truth, { color: '#111827', width: 3 });
        const rows = [];
        if (state.uniform === '1') {
          const curve = library.lagrangePoints(uniform, uniformX, xs);
          plot.polyline(curve, { color: '#dc2626', width: 2 });
          plot.points(uniform, { color: '#dc2626', radius: 3.5 });
          rows.push(['#dc2626', 'Lagrange on uniform nodes', largestError(curve)]);
        }
        if (state.chebyshev === '1') {
          const curve = library.lagrangePoints(chebyshev, chebyshevX, xs);
          plot.polyline(curve, { color: '#1f4e9c', width: 2 });
          plot.points(chebyshev, { color: '#1f4e9c', radius: 3.5, outline: true });
          rows.push(['#1f4e9c', 'Lagrange on Chebyshev nodes', largestError(curve)]);
        }
        if (state.spline === '1') {
          if (n + 1 >= Math.max(q, 2)) {
            const spline = library.interpolateNatural(uniform, uniformX, q);
            const curve = library.pointsAt(spline, xs);
            plot.polyline(curve, { color: '#15803d', width: 2, dash: [7, 3] });
            rows.push(['#15803d', `natural spline, order ${q} (degree ${2 * q - 1}), uniform nodes`, largestError(curve)]);
          }
        }
        const table = document.createElement('table');
        table.id = 'runge-errors';
        for (const [color, text, error] of rows) {
          const row = document.createElement('tr');
          row.innerHTML = `<td style="text-align:left"><span class="legend" style="background:${color}"></span>${text}</td>` +
            `<td data-error="${error}">max error ${error.toExponential(2)}</td>`;
          table.appendChild(row);
        }
        shown = uniform;
        context.readout(table);
      }

      return { draw, model: () => (shown ? library.interpolateNatural(shown, Array.from({ length: shown.length / 2 }, (_, i) => shown[2 * i]), Number(state.q)) : null) };
    },
  });
})();
