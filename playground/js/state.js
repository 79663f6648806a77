// The page's state in the URL's fragment, so that a link shares exactly what
// is on screen: #view=bezier&points=0,0;1,2;2,2;4,1;4,0&t=0.5
// Points are written "x,y;x,y;..." with at most 6 significant digits.
'use strict';

(function () {
  function formatNumber(value) {
    return String(Number(value.toPrecision(6)));
  }

  const PageState = {
    /// {view, values: {key: string}} read from the fragment.
    read() {
      const params = new URLSearchParams(window.location.hash.replace(/^#/, ''));
      const values = {};
      for (const [key, value] of params) if (key !== 'view') values[key] = value;
      return { view: params.get('view'), values };
    },

    /// Writes the view and its values into the fragment (no new history entry).
    write(view, values) {
      const params = new URLSearchParams();
      params.set('view', view);
      for (const [key, value] of Object.entries(values)) params.set(key, value);
      const hash = '#' + params.toString().replace(/%2C/g, ',').replace(/%3B/g, ';');
      if (hash !== window.location.hash) history.replaceState(null, '', hash);
    },

    formatNumber,

    /// "x,y;x,y" from handles [{x, y}].
    formatPoints(handles) {
      return handles.map((h) => `${formatNumber(h.x)},${formatNumber(h.y)}`).join(';');
    },

    /// Handles [{x, y}] from "x,y;x,y"; null when the text is not such a list.
    parsePoints(text) {
      if (typeof text !== 'string' || !text) return null;
      const handles = [];
      for (const pair of text.split(';')) {
        const [x, y] = pair.split(',').map(Number);
        if (!Number.isFinite(x) || !Number.isFinite(y)) return null;
        handles.push({ x, y });
      }
      return handles;
    },

    /// Handles [{x, y}] from a flat [x0, y0, x1, y1, ...].
    handles(flat) {
      const out = [];
      for (let i = 0; i + 1 < flat.length; i += 2) out.push({ x: flat[i], y: flat[i + 1] });
      return out;
    },

    /// Flat [x0, y0, x1, y1, ...] from handles.
    flat(handles) {
      const out = new Float64Array(handles.length * 2);
      handles.forEach((h, i) => { out[2 * i] = h.x; out[2 * i + 1] = h.y; });
      return out;
    },
  };

  window.PageState = PageState;
})();
