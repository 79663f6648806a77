// What the page exports: the curve or surface on screen as casteljau's model
// JSON (docs/formats.md; the CLI and the Python module read it back), and a
// plane curve as SVG: its certified polyline within 1e-4 of the curve's size
// (the library's flatten), so any curve kind and degree exports the same way.
'use strict';

(function () {
  function rows(flat, dimension) {
    const out = [];
    for (let i = 0; i < flat.length; i += dimension) out.push(Array.from(flat.slice(i, i + dimension)));
    return out;
  }

  /// rows x columns points (flat, d each) as the nested control_points[i][j] of a net.
  function net(flat, rowCount, columns, dimension) {
    const points = rows(flat, dimension);
    return Array.from({ length: rowCount }, (_, i) => points.slice(i * columns, (i + 1) * columns));
  }

  function withWeights(out, weights, shape) {
    if (weights && weights.length) out.weights = shape ? shape(Array.from(weights)) : Array.from(weights);
    return out;
  }

  /// The model JSON object of a page description (wasm/curve_values.hpp, wasm/bind_surfaces.cpp).
  function model(shape) {
    const d = shape.dimension || 2;
    switch (shape.kind) {
      case 'bezier':
        return withWeights({ type: 'bezier', control_points: rows(shape.control, d) }, shape.weights);
      case 'piecewise':
        if (shape.pieces.some((piece) => piece.weights && piece.weights.length)) {
          return { type: 'piecewise_bezier', pieces: shape.pieces.map((piece) => model(Object.assign({ dimension: d }, piece))) };
        }
        return { type: 'piecewise_bezier', pieces: shape.pieces.map((piece) => rows(piece.control, d)) };
      case 'bspline':
        return withWeights({ type: 'bspline', degree: shape.degree, knots: Array.from(shape.knots), control_points: rows(shape.control, d) }, shape.weights);
      case 'bezier_surface':
        return withWeights({ type: 'bezier_surface', control_points: net(shape.net, shape.rows, shape.columns, 3) }, shape.weights,
          (w) => net(w, shape.rows, shape.columns, 1).map((row) => row.map(([x]) => x)));
      case 'bspline_surface':
        return withWeights({ type: 'bspline_surface', degree: [shape.degreeU, shape.degreeV], knots: [Array.from(shape.knotsU), Array.from(shape.knotsV)],
          control_points: net(shape.net, shape.rows, shape.columns, 3) }, shape.weights,
          (w) => net(w, shape.rows, shape.columns, 1).map((row) => row.map(([x]) => x)));
      case 'coons': {
        const boundaries = {};
        for (const name of ['u0', 'u1', 'v0', 'v1']) boundaries[name] = model(shape.boundaries[name]);
        return { type: 'coons', boundaries, blending: shape.blending };
      }
      default:
        throw new Error(`cannot export a shape of kind ${shape.kind}`);
    }
  }

  function svg(library, curve) {
    if (!['bezier', 'piecewise', 'bspline'].includes(curve.kind) || (curve.dimension || 2) !== 2) {
      throw new Error('SVG export takes a plane curve; export this view as model JSON');
    }
    // The control points bound the curve (convex hull): their box sets the tolerance.
    const controls = curve.kind === 'piecewise' ? curve.pieces.map((piece) => piece.control) : [curve.control];
    const hull = Plot.boundsOf(controls);
    const points = library.polyline(curve, 1e-4 * Math.max(hull.xmax - hull.xmin, hull.ymax - hull.ymin, 1e-9)).points;
    const { xmin, xmax, ymin, ymax } = Plot.boundsOf([points]);
    const size = Math.max(xmax - xmin, ymax - ymin, 1e-9);
    const margin = 0.05 * size;
    const commands = [];
    // y up in the model, y down in SVG: negate y.
    for (let i = 0; i < points.length; i += 2) commands.push(`${i ? 'L' : 'M'}${points[i]} ${-points[i + 1]}`);
    const viewBox = [xmin - margin, -ymax - margin, xmax - xmin + 2 * margin, ymax - ymin + 2 * margin];
    return `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${viewBox.join(' ')}">\n` +
      `<path d="${commands.join(' ')}" fill="none" stroke="black" stroke-width="${size / 300}"/>\n</svg>\n`;
  }

  window.ModelExport = {
    /// The model JSON text of a curve or surface description.
    modelJson: (shape) => JSON.stringify(model(shape)) + '\n',
    model,
    svg,
  };
})();
