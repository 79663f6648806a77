// View 8: the questions one asks of a curve, and what a machine needs of it.
// The nearest point to the pointer, intersections with a segment and the
// curve's own crossings, points equally spaced along it, and its arc spline
// (the G¹ biarcs a CNC controller cuts as G2/G3) within a tolerance.
'use strict';

(function () {
  const CURVE_POINTS = [[-5, -1], [-2, 3.5], [2.5, 3], [2, -2], [-1.5, -1], [-0.5, 3], [4.5, 1.5]];
  const SEGMENT_POINTS = [[-5, 2.5], [5, -1.5]];
  const ARC_COLORS = ['#0f766e', '#b45309'];

  Playground.register({
    id: 'queries',
    title: 'Queries and CNC',
    seed: 'Seed 003 §5 and seed 004 (CAD/CAM: the curve a machine follows); casteljau\'s curve concept (closest point, intersections, arc length, arc splines).',
    explanation: 'Move the pointer: the nearest point of the curve follows (global minimum of the distance, ends included). ' +
      'Crossings with the segment and with itself are marked; points are spaced equally along the arc; the arc spline ' +
      'replaces the curve by circular arcs within the tolerance, as G2/G3 moves.',
    defaults: { points: PageState.formatPoints(CURVE_POINTS.concat(SEGMENT_POINTS).map(([x, y]) => ({ x, y }))), spacing: '12', tolerance: '-1.5', arcs: '1' },
    mount(context) {
      const { library, controls, values } = context;
      const state = Object.assign({}, values);
      const plot = context.plot({ label: 'a cubic B-spline and a segment: nearest point under the pointer, intersections, spacing, arcs', editable: true, height: 440 });
      const count = CURVE_POINTS.length + SEGMENT_POINTS.length;
      const parsed = PageState.parsePoints(state.points);
      plot.handles = parsed && parsed.length === count ? parsed : CURVE_POINTS.concat(SEGMENT_POINTS).map(([x, y]) => ({ x, y }));
      plot.canAdd = false;
      plot.minimumHandles = count;  // a fixed set: the curve's points, then the segment's two ends
      plot.fit([PageState.flat(plot.handles)], 0.08);
      let pointer = null;
      const save = () => context.save(() => Object.assign(state, { points: PageState.formatPoints(plot.handles) }));
      plot.onchange = () => { save(); context.redraw(); };
      plot.onpointer = (x, y) => { pointer = x === null ? null : [x, y]; context.redraw(); };

      Controls.slider(controls, 'points along the arc', { min: 0, max: 60, step: 1, value: Number(state.spacing) },
        (v) => { state.spacing = String(v); save(); context.redraw(); });
      Controls.slider(controls, 'arc tolerance', { min: -4, max: 0, step: 0.1, value: Number(state.tolerance),
        format: (v) => `${(10 ** v).toPrecision(2)}` }, (v) => { state.tolerance = String(v); save(); context.redraw(); });
      Controls.checkbox(controls, 'arc spline', state.arcs === '1', (checked) => { state.arcs = checked ? '1' : '0'; save(); context.redraw(); });

      const curve = () => {
        const control = PageState.flat(plot.handles.slice(0, CURVE_POINTS.length));
        return { kind: 'bspline', degree: 3, knots: library.clampedUniformKnots(3, CURVE_POINTS.length), control };
      };
      const segment = () => ({ kind: 'bezier', control: PageState.flat(plot.handles.slice(CURVE_POINTS.length)) });

      function draw() {
        const c = curve(), s = segment();
        plot.clear();
        plot.axes();
        plot.polyline(c.control, { color: '#d1d5db', width: 1, dash: [4, 4] });
        const lines = [];
        if (state.arcs === '1') {
          const tolerance = 10 ** Number(state.tolerance);
          const arcs = library.fitArcs(c, tolerance, 12);
          const perArc = 13 * 2;
          for (let k = 0; k * perArc < arcs.points.length; ++k) {
            plot.polyline(arcs.points.subarray(k * perArc, (k + 1) * perArc), { color: ARC_COLORS[k % 2], width: 5 });
          }
          lines.push(`arc spline: ${arcs.segments.length / 5} arcs and segments, certified within ${arcs.deviationBound.toExponential(2)} ` +
            `(tolerance ${tolerance.toPrecision(2)})`);
        }
        plot.polyline(library.polyline(c, 0.25 * plot.pixel()).points, { color: '#1f4e9c', width: 2 });
        plot.polyline(s.control, { color: '#6b7280', width: 1.5 });

        const spacing = Number(state.spacing);
        if (spacing >= 2) {
          const along = library.pointsAt(c, library.equalArcLengthParameters(c, spacing));
          plot.points(along, { color: '#7c3aed', radius: 3.5 });
        }
        const length = library.arcLength(c);
        lines.push(`length ${PageState.formatNumber(length)}` + (spacing >= 2 ? `, ${spacing} points every ${PageState.formatNumber(length / (spacing - 1))}` : ''));

        const crossings = library.intersections(c, s);
        const own = library.intersections(c, null);
        for (const meeting of crossings) plot.points(meeting.point, { color: '#dc2626', radius: 6, outline: true });
        for (const meeting of own) plot.points(meeting.point, { color: '#be185d', radius: 7, outline: true });
        lines.push(`${crossings.length} crossing${crossings.length === 1 ? '' : 's'} with the segment, ${own.length} of the curve with itself`);

        if (pointer) {
          const nearest = library.closestPoint(c, pointer[0], pointer[1]);
          plot.polyline([pointer[0], pointer[1], nearest.point[0], nearest.point[1]], { color: '#111827', width: 1, dash: [3, 3] });
          plot.points(nearest.point, { color: '#111827', radius: 5 });
          lines.push(`nearest point C(${nearest.parameter.toFixed(4)}) at distance ${PageState.formatNumber(nearest.distance)}`);
        }
        plot.drawHandles();
        const text = document.createElement('p');
        text.id = 'query-summary';
        text.textContent = lines.join(' · ');
        context.readout(text);
      }

      return { draw, model: curve, plot };
    },
  });
})();
