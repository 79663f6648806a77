// View 7: surfaces in a turning 3D view on a 2D canvas. A Bézier patch or a
// B-spline patch of up to 20 x 20 control points whose net one drags up and
// down, and a Coons patch from four boundary cubics with either blending.
// Drag a point: it moves vertically (z). Drag elsewhere: the view turns.
'use strict';

(function () {
  // 48 shades of the surface's blue, from facing away from the light to facing it.
  const shades = Array.from({ length: 48 }, (_, i) => `hsl(212, 55%, ${(38 + (45 * i) / 47).toFixed(1)}%)`);
  const PATCHES = [['bezier', 'Bézier patch (4 × 4)'], ['bspline', 'B-spline patch (cubic, N × N)'], ['coons', 'Coons patch (four cubics)']];

  /// The starting heights: a smooth bump over the net, so the patch is not flat.
  function bump(rows, columns) {
    const z = [];
    for (let i = 0; i < rows; ++i) {
      for (let j = 0; j < columns; ++j) {
        const s = i / Math.max(rows - 1, 1), t = j / Math.max(columns - 1, 1);
        z.push(Number((1.6 * Math.sin(Math.PI * s) * Math.sin(Math.PI * t) + 0.6 * Math.cos(3 * s + 2 * t)).toFixed(3)));
      }
    }
    return z;
  }

  /// A net of rows x columns over [-2, 2]^2 with the given heights (flat xyz).
  function netOf(rows, columns, z) {
    const net = new Float64Array(3 * rows * columns);
    for (let i = 0; i < rows; ++i) {
      for (let j = 0; j < columns; ++j) {
        const k = i * columns + j;
        net.set([-2 + (4 * i) / (rows - 1), -2 + (4 * j) / (columns - 1), z[k]], 3 * k);
      }
    }
    return net;
  }

  // The Coons patch's 12 points: corners P00, P01, P10, P11 then two inner
  // points per boundary, in the order u0 (x = -2), u1 (x = 2), v0 (y = -2), v1 (y = 2).
  const COONS_XY = [[-2, -2], [-2, 2], [2, -2], [2, 2],
    [-2, -0.7], [-2, 0.7], [2, -0.7], [2, 0.7], [-0.7, -2], [0.7, -2], [-0.7, 2], [0.7, 2]];
  const COONS_Z = [0, 0.5, 0.5, 0, 1.5, -0.5, -0.5, 1.2, 1.0, 1.4, -0.8, 0.9];

  function coonsBoundaries(z) {
    const p = COONS_XY.map(([x, y], k) => [x, y, z[k]]);
    const cubic = (a, b, c, d) => ({ kind: 'bezier', dimension: 3, control: Float64Array.from([...p[a], ...p[b], ...p[c], ...p[d]]) });
    return { u0: cubic(0, 4, 5, 1), u1: cubic(2, 6, 7, 3), v0: cubic(0, 8, 9, 2), v1: cubic(1, 10, 11, 3) };
  }

  Playground.register({
    id: 'surfaces',
    title: 'Surfaces',
    seed: 'Seed 001 §6 and seed 003 §4 (tensor-product Bézier and B-spline patches, Coons patches with linear and cubic blending).',
    explanation: 'S(u,v) = Σ Σ N_i(u) N_j(v) P_ij: the curve construction in each direction. A Coons patch fills four boundary curves: ' +
      'the sum of the two ruled surfaces minus the bilinear one, blended linearly or with cubic Hermite functions.',
    defaults: { patch: 'bezier', N: '6', yaw: '-35', pitch: '55', blending: 'linear', z: '' },
    mount(context) {
      const { library, controls, values } = context;
      const state = Object.assign({}, values);
      const plot = context.plot({ label: 'surface patch in 3D: drag a control point up or down, drag elsewhere to turn', editable: true, height: 460 });
      plot.canAdd = false;
      plot.setBounds(-3.6, 3.6, -2.8, 3.4);
      let yaw = (Number(state.yaw) * Math.PI) / 180, pitch = (Number(state.pitch) * Math.PI) / 180;
      let points3 = [];  // the draggable 3D points (x, y, z)

      function size() { return state.patch === 'bezier' ? 4 : Math.max(4, Math.min(20, Number(state.N) || 6)); }
      function reset() {
        const z = (state.z || '').split(',').filter((s) => s !== '').map(Number);
        if (state.patch === 'coons') {
          points3 = COONS_XY.map(([x, y], k) => [x, y, z.length === COONS_XY.length && z.every(Number.isFinite) ? z[k] : COONS_Z[k]]);
        } else {
          const n = size();
          const heights = z.length === n * n && z.every(Number.isFinite) ? z : bump(n, n);
          const net = netOf(n, n, heights);
          points3 = [];
          for (let k = 0; k < n * n; ++k) points3.push([net[3 * k], net[3 * k + 1], net[3 * k + 2]]);
        }
        plot.minimumHandles = points3.length;
      }

      function project([x, y, z]) {
        const x1 = x * Math.cos(yaw) - y * Math.sin(yaw), y1 = x * Math.sin(yaw) + y * Math.cos(yaw);
        return [x1, z * Math.cos(pitch) + y1 * Math.sin(pitch), y1 * Math.cos(pitch) - z * Math.sin(pitch)];
      }
      function placeHandles() {
        plot.handles = points3.map((p) => { const [x, y] = project(p); return { x, y }; });
      }
      const save = () => context.save(() => Object.assign(state, {
        yaw: String(Math.round((yaw * 180) / Math.PI)), pitch: String(Math.round((pitch * 180) / Math.PI)),
        z: points3.map((p) => PageState.formatNumber(p[2])).join(',') }));
      plot.onchange = () => {
        // Only heights change: a handle's vertical screen motion is dz cos(pitch).
        const k = plot.dragging >= 0 ? plot.dragging : plot.selected;
        if (k >= 0) {
          const [, y] = project(points3[k]);
          points3[k][2] += (plot.handles[k].y - y) / Math.max(Math.cos(pitch), 0.2);
        }
        placeHandles();
        save();
        context.redraw();
      };
      plot.onpan = (dx, dy) => {
        yaw += dx * 0.01;
        pitch = Math.max(0.05, Math.min(Math.PI / 2, pitch + dy * 0.01));
        placeHandles();
        save();
        context.redraw();
      };

      Controls.select(controls, 'patch', PATCHES, state.patch, (v) => { state.patch = v; state.z = ''; reset(); placeHandles(); save(); context.redraw(); showOptions(); });
      const count = Controls.slider(controls, 'N', { min: 4, max: 20, step: 1, value: size() }, (v) => {
        state.N = String(v); state.z = ''; reset(); placeHandles(); save(); context.redraw();
      });
      const blending = Controls.select(controls, 'blending', [['linear', 'linear'], ['cubic', 'cubic (Hermite)']], state.blending,
        (v) => { state.blending = v; save(); context.redraw(); });
      function showOptions() {
        count.parentElement.hidden = state.patch !== 'bspline';
        blending.parentElement.hidden = state.patch !== 'coons';
      }
      showOptions();
      reset();
      placeHandles();

      /// The surface on screen, as the page describes surfaces (wasm/bind_surfaces.cpp).
      function description() {
        if (state.patch === 'coons') return { kind: 'coons', boundaries: coonsBoundaries(points3.map((p) => p[2])), blending: state.blending };
        const n = size();
        const net = Float64Array.from(points3.flat());
        if (state.patch === 'bezier') return { kind: 'bezier_surface', rows: n, columns: n, net };
        const knots = library.clampedUniformKnots(3, n);
        return { kind: 'bspline_surface', rows: n, columns: n, net, degreeU: 3, degreeV: 3, knotsU: knots, knotsV: knots };
      }

      /// The grid of surface points (flat xyz) and its size.
      function grid() {
        const surface = description();
        if (surface.kind === 'coons') {
          const samples = 33;
          return { points: library.coonsGrid(surface.boundaries, surface.blending, samples, samples), nu: samples, nv: samples };
        }
        // Three cells per span on small nets, two on large ones (a 20 x 20 net: 40 x 40 cells).
        const samples = size() <= 10 ? 3 * size() + 1 : 2 * size() + 1;
        return { points: library.surfaceGrid(surface, samples, samples), nu: samples, nv: samples };
      }

      function draw() {
        const { points, nu, nv } = grid();
        const c = plot.context;
        plot.clear();
        // Quads far to near (the painter's algorithm), shaded by their normal.
        const projected = new Float64Array(points.length);
        for (let k = 0; k < points.length; k += 3) projected.set(project([points[k], points[k + 1], points[k + 2]]), k);
        // Quads as the index of their first corner; depth = the sum of the four corners' depths.
        const cells = (nu - 1) * (nv - 1);
        const first = new Uint32Array(cells), depth = new Float64Array(cells);
        for (let a = 0, q = 0; a + 1 < nu; ++a) {
          for (let b = 0; b + 1 < nv; ++b, ++q) {
            const k = 3 * (a * nv + b);
            first[q] = k;
            depth[q] = projected[k + 2] + projected[k + 5] + projected[k + 3 * nv + 2] + projected[k + 3 * nv + 5];
          }
        }
        const order = Uint32Array.from({ length: cells }, (_, q) => q).sort((q, r) => depth[r] - depth[q]);
        c.save();
        for (const q of order) {
          const k0 = first[q], k1 = k0 + 3, k2 = k0 + 3 * nv + 3, k3 = k0 + 3 * nv;
          // The normal of the projected quad's diagonals (view space: x right, y up, z away).
          const ux = projected[k2] - projected[k0], uy = projected[k2 + 1] - projected[k0 + 1], uz = projected[k2 + 2] - projected[k0 + 2];
          const vx = projected[k3] - projected[k1], vy = projected[k3 + 1] - projected[k1 + 1], vz = projected[k3 + 2] - projected[k1 + 2];
          const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
          const light = Math.abs(0.3 * nx + 0.6 * ny - 0.74 * nz) / (Math.hypot(nx, ny, nz) || 1);
          c.fillStyle = c.strokeStyle = shades[Math.round(light * (shades.length - 1))];
          c.beginPath();
          c.moveTo(plot.ox + plot.sx * projected[k0], plot.oy - plot.sy * projected[k0 + 1]);
          c.lineTo(plot.ox + plot.sx * projected[k1], plot.oy - plot.sy * projected[k1 + 1]);
          c.lineTo(plot.ox + plot.sx * projected[k2], plot.oy - plot.sy * projected[k2 + 1]);
          c.lineTo(plot.ox + plot.sx * projected[k3], plot.oy - plot.sy * projected[k3 + 1]);
          c.closePath();
          c.fill();
        }
        c.restore();
        // The net (or the Coons boundaries' control polygons) over the surface.
        if (state.patch === 'coons') {
          for (const boundary of Object.values(coonsBoundaries(points3.map((p) => p[2])))) {
            const flat = [];
            for (let k = 0; k < boundary.control.length; k += 3) flat.push(...project([boundary.control[k], boundary.control[k + 1], boundary.control[k + 2]]).slice(0, 2));
            plot.polyline(flat, { color: '#9a3412', width: 1.2, dash: [4, 3] });
          }
        } else {
          const n = size();
          for (let i = 0; i < n; ++i) {
            const row = [], column = [];
            for (let j = 0; j < n; ++j) { row.push(plot.handles[i * n + j].x, plot.handles[i * n + j].y); column.push(plot.handles[j * n + i].x, plot.handles[j * n + i].y); }
            plot.polyline(row, { color: 'rgba(154, 52, 18, 0.7)', width: 1 });
            plot.polyline(column, { color: 'rgba(154, 52, 18, 0.7)', width: 1 });
          }
        }
        plot.drawHandles();
        const text = document.createElement('p');
        text.id = 'surface-summary';
        text.textContent = `${PATCHES.find(([id]) => id === state.patch)[1]}: ${points3.length} control points, ` +
          `${(nu - 1) * (nv - 1)} shaded cells from a ${nu} × ${nv} grid of surface points computed by casteljau` +
          (state.patch === 'coons' ? `, ${state.blending} blending` : '');
        context.readout(text);
      }

      return { draw, model: description, plot };
    },
  });
})();
