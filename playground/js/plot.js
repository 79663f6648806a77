// A figure on a canvas in world coordinates (y up), with draggable handles.
// Pointer events serve mouse, pen and touch alike; the canvas takes the
// keyboard focus: [ and ] (or n and p) choose a handle, the arrow keys move it
// (Shift: ten times further), Delete removes it, Insert or + adds one after it.
// Double-click (or double-tap) on empty space adds a point, on a handle removes it.
'use strict';

(function () {
  const HIT_RADIUS = { mouse: 10, pen: 14, touch: 22 };  // CSS pixels around a handle that grab it

  class Plot {
    /// options: {label, height (CSS px), equalAspect (default true), editable, wide (the figures' whole width)}
    constructor(container, options = {}) {
      this.options = Object.assign({ height: 360, equalAspect: true, editable: false, label: 'figure' }, options);
      this.canvas = document.createElement('canvas');
      this.canvas.className = 'plot';
      this.canvas.setAttribute('role', 'img');
      this.canvas.setAttribute('aria-label', this.options.label);
      this.canvas.style.height = `${this.options.height}px`;
      if (this.options.wide) this.canvas.style.gridColumn = '1 / -1';  // the whole width of the figures
      if (this.options.editable) {
        this.canvas.tabIndex = 0;
        this.canvas.setAttribute('aria-roledescription', 'editable figure');
      }
      container.appendChild(this.canvas);
      this.context = this.canvas.getContext('2d');
      this.bounds = { xmin: -1, xmax: 1, ymin: -1, ymax: 1 };
      this.handles = [];       // [{x, y}] the points one can drag
      this.selected = -1;      // handle chosen by the keyboard or the last drag
      this.dragging = -1;
      this.panning = null;     // [px, py] of the last pointer position while panning
      this.onchange = null;    // (handles) after a drag, a key, an add or a delete
      this.ondraw = null;      // () redraws the figure
      this.onpointer = null;   // (x, y) the pointer's world position (hover), or null when it leaves
      this.onpan = null;       // (dx, dy) in CSS pixels, while dragging where there is no handle (3D views turn)
      this.canAdd = true;
      this.minimumHandles = 1;
      this.bindEvents();
      this.resize();
    }

    resize() {
      const ratio = window.devicePixelRatio || 1;
      const width = this.canvas.clientWidth || 600;
      const height = this.canvas.clientHeight || this.options.height;
      this.canvas.width = Math.round(width * ratio);
      this.canvas.height = Math.round(height * ratio);
      this.width = width;
      this.height = height;
      this.context.setTransform(ratio, 0, 0, ratio, 0, 0);
      this.updateScale();
    }

    /// Shows the box [xmin, xmax] x [ymin, ymax] (with equal units when equalAspect).
    setBounds(xmin, xmax, ymin, ymax) {
      this.bounds = { xmin, xmax, ymin, ymax };
      this.updateScale();
    }

    /// {xmin, xmax, ymin, ymax} of the finite points of flat [x0, y0, ...] arrays
    /// (xmin > xmax when there are none).
    static boundsOf(arrays) {
      let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
      for (const flat of arrays) {
        for (let i = 0; i + 1 < flat.length; i += 2) {
          if (!Number.isFinite(flat[i]) || !Number.isFinite(flat[i + 1])) continue;
          xmin = Math.min(xmin, flat[i]); xmax = Math.max(xmax, flat[i]);
          ymin = Math.min(ymin, flat[i + 1]); ymax = Math.max(ymax, flat[i + 1]);
        }
      }
      return { xmin, xmax, ymin, ymax };
    }

    /// Shows every point of the flat arrays, with a margin (a fraction of the size).
    fit(arrays, margin = 0.08) {
      let { xmin, xmax, ymin, ymax } = Plot.boundsOf(arrays);
      if (!(xmin <= xmax)) { xmin = -1; xmax = 1; ymin = -1; ymax = 1; }
      const size = Math.max(xmax - xmin, ymax - ymin, 1e-9);
      const pad = size * margin;
      this.setBounds(xmin - pad, xmax + pad, ymin - pad, ymax + pad);
    }

    updateScale() {
      const { xmin, xmax, ymin, ymax } = this.bounds;
      let sx = this.width / (xmax - xmin), sy = this.height / (ymax - ymin);
      if (this.options.equalAspect) sx = sy = Math.min(sx, sy);
      this.sx = sx; this.sy = sy;
      // Centre the box in the canvas.
      this.ox = (this.width - sx * (xmax - xmin)) / 2 - sx * xmin;
      this.oy = (this.height + sy * (ymax - ymin)) / 2 + sy * ymin;
    }

    toScreen(x, y) { return [this.ox + this.sx * x, this.oy - this.sy * y]; }
    toWorld(px, py) { return [(px - this.ox) / this.sx, (this.oy - py) / this.sy]; }
    /// One CSS pixel in world units: the drawing tolerance of a curve.
    pixel() { return 1 / Math.max(this.sx, this.sy); }

    clear() {
      this.context.clearRect(0, 0, this.width, this.height);
    }

    /// Axes through the origin, when it is in view.
    axes() {
      const c = this.context;
      c.save();
      c.strokeStyle = '#d0d4da';
      c.lineWidth = 1;
      const [x0, y0] = this.toScreen(0, 0);
      c.beginPath();
      if (x0 >= 0 && x0 <= this.width) { c.moveTo(x0, 0); c.lineTo(x0, this.height); }
      if (y0 >= 0 && y0 <= this.height) { c.moveTo(0, y0); c.lineTo(this.width, y0); }
      c.stroke();
      c.restore();
    }

    /// A polyline through the flat points; style: {color, width, dash, fill, close}.
    polyline(flat, style = {}) {
      const c = this.context;
      if (flat.length < 4 && !style.fill) return;
      c.save();
      c.beginPath();
      let pen = false;
      for (let i = 0; i + 1 < flat.length; i += 2) {
        if (!Number.isFinite(flat[i]) || !Number.isFinite(flat[i + 1])) { pen = false; continue; }
        const [px, py] = this.toScreen(flat[i], flat[i + 1]);
        if (pen) c.lineTo(px, py); else c.moveTo(px, py);
        pen = true;
      }
      if (style.close) c.closePath();
      if (style.fill) { c.fillStyle = style.fill; c.fill(); }
      if (style.color !== null) {
        c.strokeStyle = style.color || '#1f4e9c';
        c.lineWidth = style.width || 2;
        c.lineJoin = 'round';
        if (style.dash) c.setLineDash(style.dash);
        c.stroke();
      }
      c.restore();
    }

    /// Dots at the flat points; style: {color, radius, outline}.
    points(flat, style = {}) {
      const c = this.context;
      c.save();
      c.fillStyle = style.color || '#1f4e9c';
      for (let i = 0; i + 1 < flat.length; i += 2) {
        const [px, py] = this.toScreen(flat[i], flat[i + 1]);
        c.beginPath();
        c.arc(px, py, style.radius || 3, 0, 2 * Math.PI);
        if (style.outline) { c.strokeStyle = c.fillStyle; c.lineWidth = 1.5; c.stroke(); } else c.fill();
      }
      c.restore();
    }

    /// Text at a world position, offset in pixels.
    label(text, x, y, style = {}) {
      const c = this.context;
      const [px, py] = this.toScreen(x, y);
      c.save();
      c.font = style.font || '12px system-ui, sans-serif';
      c.fillStyle = style.color || '#333';
      c.textAlign = style.align || 'left';
      c.fillText(text, px + (style.dx ?? 6), py + (style.dy ?? -6));
      c.restore();
    }

    /// The draggable handles (one path: thousands stay cheap), the selected one ringed.
    drawHandles(color = '#c2410c') {
      const c = this.context;
      const radius = this.handles.length > 200 ? 3 : 5;
      c.save();
      c.beginPath();
      for (const handle of this.handles) {
        const [px, py] = this.toScreen(handle.x, handle.y);
        c.moveTo(px + radius, py);
        c.arc(px, py, radius, 0, 2 * Math.PI);
      }
      c.fillStyle = color;
      c.fill();
      const chosen = this.handles[this.selected];
      if (chosen) {
        const [px, py] = this.toScreen(chosen.x, chosen.y);
        c.beginPath();
        c.arc(px, py, radius + 4, 0, 2 * Math.PI);
        c.strokeStyle = document.activeElement === this.canvas ? '#111' : color;
        c.lineWidth = 2;
        c.stroke();
      }
      c.restore();
    }

    /// "P0", "P1", ... beside the handles, when there are few enough to read.
    labelHandles(name = (i) => `P${i}`, color = '#9a3412') {
      if (this.handles.length > 40) return;
      this.handles.forEach((h, i) => this.label(name(i), h.x, h.y, { color }));
    }

    handleAt(px, py, pointerType) {
      const radius = HIT_RADIUS[pointerType] || HIT_RADIUS.mouse;
      let best = -1, bestDistance = radius * radius;
      this.handles.forEach((handle, i) => {
        const [hx, hy] = this.toScreen(handle.x, handle.y);
        const d = (hx - px) ** 2 + (hy - py) ** 2;
        if (d <= bestDistance) { best = i; bestDistance = d; }
      });
      return best;
    }

    changed() {
      if (this.onchange) this.onchange(this.handles);
    }

    eventPosition(event) {
      const rect = this.canvas.getBoundingClientRect();
      return [event.clientX - rect.left, event.clientY - rect.top];
    }

    bindEvents() {
      const canvas = this.canvas;
      canvas.addEventListener('pointerdown', (event) => {
        if (!this.options.editable) return;
        const [px, py] = this.eventPosition(event);
        const hit = this.handleAt(px, py, event.pointerType);
        if (hit < 0) {
          if (!this.onpan) return;
          this.panning = [px, py];
        } else {
          this.dragging = this.selected = hit;
        }
        canvas.setPointerCapture(event.pointerId);
        event.preventDefault();
      });
      canvas.addEventListener('pointermove', (event) => {
        const [px, py] = this.eventPosition(event);
        const [x, y] = this.toWorld(px, py);
        if (this.panning) {
          const [qx, qy] = this.panning;
          this.panning = [px, py];
          this.onpan(px - qx, py - qy);
        } else if (this.dragging >= 0) {
          this.handles[this.dragging].x = x;
          this.handles[this.dragging].y = y;
          this.changed();
        } else if (this.onpointer) {
          this.onpointer(x, y);
        }
      });
      const release = (event) => {
        if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
        this.dragging = -1;
        this.panning = null;
      };
      canvas.addEventListener('pointerup', release);
      canvas.addEventListener('pointercancel', release);
      canvas.addEventListener('pointerleave', () => { if (this.onpointer && this.dragging < 0) this.onpointer(null, null); });
      canvas.addEventListener('dblclick', (event) => {
        if (!this.options.editable) return;
        const [px, py] = this.eventPosition(event);
        const hit = this.handleAt(px, py, 'mouse');
        if (hit >= 0) this.remove(hit);
        else if (this.canAdd) this.insertNear(...this.toWorld(px, py));
      });
      canvas.addEventListener('keydown', (event) => this.key(event));
      canvas.addEventListener('focus', () => { if (this.selected < 0 && this.handles.length) this.selected = 0; if (this.ondraw) this.ondraw(); });
      canvas.addEventListener('blur', () => { if (this.ondraw) this.ondraw(); });
      if (window.ResizeObserver) {
        new ResizeObserver(() => { this.resize(); if (this.ondraw) this.ondraw(); }).observe(canvas);
      }
    }

    remove(index) {
      if (this.handles.length <= this.minimumHandles) return;
      this.handles.splice(index, 1);
      this.selected = Math.min(index, this.handles.length - 1);
      this.changed();
    }

    /// Adds a point at (x, y) between the two consecutive handles it is nearest to.
    insertNear(x, y) {
      let where = this.handles.length;
      let best = Infinity;
      for (let i = 0; i + 1 < this.handles.length; ++i) {
        const a = this.handles[i], b = this.handles[i + 1];
        const d = Math.hypot(x - a.x, y - a.y) + Math.hypot(x - b.x, y - b.y) - Math.hypot(b.x - a.x, b.y - a.y);
        if (d < best) { best = d; where = i + 1; }
      }
      const dEnd = this.handles.length ? Math.hypot(x - this.handles[this.handles.length - 1].x, y - this.handles[this.handles.length - 1].y) : 0;
      if (this.handles.length && dEnd < best) where = this.handles.length;
      this.handles.splice(where, 0, { x, y });
      this.selected = where;
      this.changed();
    }

    key(event) {
      if (!this.options.editable || !this.handles.length) return;
      const step = (event.shiftKey ? 10 : 1) * 0.01 * Math.max(this.bounds.xmax - this.bounds.xmin, this.bounds.ymax - this.bounds.ymin);
      const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] };
      const h = this.handles;
      if (this.selected < 0) this.selected = 0;
      if (event.key in moves) {
        h[this.selected].x += moves[event.key][0];
        h[this.selected].y += moves[event.key][1];
        this.changed();
      } else if (event.key === ']' || event.key === 'n') {
        this.selected = (this.selected + 1) % h.length;
        if (this.ondraw) this.ondraw();
      } else if (event.key === '[' || event.key === 'p') {
        this.selected = (this.selected + h.length - 1) % h.length;
        if (this.ondraw) this.ondraw();
      } else if (event.key === 'Delete' || event.key === 'Backspace') {
        this.remove(this.selected);
      } else if ((event.key === 'Insert' || event.key === '+') && this.canAdd) {
        const a = h[this.selected], b = h[Math.min(this.selected + 1, h.length - 1)];
        const offset = this.selected + 1 < h.length ? 0 : step * 5;
        h.splice(this.selected + 1, 0, { x: (a.x + b.x) / 2 + offset, y: (a.y + b.y) / 2 });
        this.selected += 1;
        this.changed();
      } else {
        return;
      }
      event.preventDefault();
    }
  }

  window.Plot = Plot;
})();
