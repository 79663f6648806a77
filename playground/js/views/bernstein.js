// View 1: the Bernstein basis (seed 004's first figures) and the seed
// notebook's direct sum against de Casteljau at high degree.
'use strict';

(function () {
  const SAMPLES = 241;

  function hue(k, n) { return `hsl(${Math.round((300 * k) / Math.max(n, 1))}, 70%, 42%)`; }

  /// Seed 004's cycle(n): P_k = (cos t_k, sin t_k)/(k+1), t_k = -pi/2 + 2 k pi / n.
  function cycle(n) {
    const points = new Float64Array(2 * (n + 1));
    for (let k = 0; k <= n; ++k) {
      const t = -Math.PI / 2 + (2 * k * Math.PI) / n;
      points[2 * k] = Math.cos(t) / (k + 1);
      points[2 * k + 1] = Math.sin(t) / (k + 1);
    }
    return points;
  }

  Playground.register({
    id: 'bernstein',
    title: 'Bernstein basis',
    seed: 'Seed 004 §1–3 (Bernstein polynomials, naive evaluation vs de Casteljau); seed 001 §2.',
    explanation: 'B_{k,n}(t) = C(n,k) t^k (1−t)^(n−k): n+1 polynomials, positive on ]0,1[, summing to 1. ' +
      'Below, seed 004\'s spiral cycle(N) evaluated by the notebook\'s direct sum (float binomials and powers) and by ' +
      'de Casteljau: they agree to rounding until the binomials overflow near N = 1030.',
    defaults: { n: '4', N: '20' },
    mount(context) {
      const { library, controls } = context;
      let n = Number(context.values.n) || 4;
      let N = Number(context.values.N) || 20;
      const ts = new Float64Array(SAMPLES).map((_, j) => j / (SAMPLES - 1));

      const basisPlot = context.plot({ label: 'Bernstein basis functions of degree n on [0, 1]', equalAspect: false, height: 300 });
      basisPlot.setBounds(-0.04, 1.04, -0.05, 1.12);
      const spiralPlot = context.plot({ label: 'seed 004 spiral cycle(N): direct sum and de Casteljau', height: 300 });

      Controls.slider(controls, 'degree n', { min: 0, max: 20, step: 1, value: n }, (v) => { n = v; context.save({ n: String(v) }); context.redraw(); });
      Controls.slider(controls, 'spiral degree N', { min: 5, max: 1100, step: 1, value: N }, (v) => { N = v; context.save({ N: String(v) }); context.redraw(); });

      function drawBasis() {
        const values = library.bernsteinBasis(n, ts);
        basisPlot.clear();
        basisPlot.polyline([0, 0, 1, 0, 1, 1, 0, 1], { color: '#e5e7eb', width: 1, close: true });
        const line = new Float64Array(2 * SAMPLES);
        for (let k = 0; k <= n; ++k) {
          for (let j = 0; j < SAMPLES; ++j) { line[2 * j] = ts[j]; line[2 * j + 1] = values[k * SAMPLES + j]; }
          basisPlot.polyline(line, { color: hue(k, n), width: 2 });
          const peak = n === 0 ? 0.5 : k / n;  // B_{k,n} peaks at t = k/n
          basisPlot.label(`B${k},${n}`, peak, values[k * SAMPLES + Math.round(peak * (SAMPLES - 1))], { color: hue(k, n), dx: -10 });
        }
      }

      function drawSpiral() {
        const curve = { kind: 'bezier', control: cycle(N) };
        const started = performance.now();
        const casteljau = library.pointsAt(curve, ts);
        const casteljauTime = performance.now() - started;
        const sumStarted = performance.now();
        const sum = library.bernsteinSumPoints(curve, ts);
        const sumTime = performance.now() - sumStarted;
        let difference = 0, finite = true;
        for (let i = 0; i < sum.length; ++i) {
          if (!Number.isFinite(sum[i])) { finite = false; continue; }
          difference = Math.max(difference, Math.abs(sum[i] - casteljau[i]));
        }
        spiralPlot.fit([curve.control]);
        spiralPlot.clear();
        spiralPlot.axes();
        spiralPlot.polyline(curve.control, { color: '#9ca3af', width: 1 });
        spiralPlot.polyline(casteljau, { color: '#1f4e9c', width: 3 });
        spiralPlot.polyline(sum, { color: '#dc2626', width: 1.5, dash: [6, 4] });
        const text = document.createElement('p');
        text.id = 'spiral-comparison';
        text.dataset.difference = String(difference);
        text.dataset.finite = String(finite);
        text.innerHTML = `N = ${N}: <span class="legend" style="background:#1f4e9c"></span>de Casteljau ` +
          `(${casteljauTime.toFixed(2)} ms for ${SAMPLES} points) <span class="legend" style="background:#dc2626"></span>direct sum ` +
          `(${sumTime.toFixed(2)} ms): ` + (finite
          ? `largest difference ${difference.toExponential(2)} (the control points lie within 1 of the origin)`
          : 'the direct sum is no longer finite: C(N, k) overflows double beyond N ≈ 1030, de Casteljau never forms it.');
        context.readout(text);
      }

      return {
        draw() { drawBasis(); drawSpiral(); },
        model: () => ({ kind: 'bezier', control: cycle(N) }),
      };
    },
  });
})();
