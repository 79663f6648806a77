// The playground's frame: the list of views, the one on screen, its state in
// the URL, the export buttons and the status line. Views register themselves
// (js/views/*.js) with Playground.register({id, title, seed, explanation,
// defaults, mount}); mount(context) builds the view's controls and figures and
// returns {draw(), model()} (model: the curve or surface to export, or null).
'use strict';

(function () {
  const views = [];
  const frameTimes = [];  // milliseconds per redraw of the current view (the benchmark reads them)
  let library = null;
  let current = null;     // {view, instance, values}

  let pendingChanges = [];  // the current view's changes not yet in the URL
  let pendingTimer = 0;

  function register(view) { views.push(view); }

  /// Writes the pending changes of the current view into the URL.
  function writeState() {
    clearTimeout(pendingTimer);
    pendingTimer = 0;
    if (!current || !pendingChanges.length) return;
    for (const changes of pendingChanges) Object.assign(current.values, typeof changes === 'function' ? changes() : changes);
    pendingChanges = [];
    PageState.write(current.view.id, current.values);
  }

  function status(message, isError = false) {
    const line = document.getElementById('status');
    line.textContent = message || '';
    line.classList.toggle('error', Boolean(isError));
  }

  /// Runs the view's draw, timing it; an exception (bad input) goes to the status line.
  function redraw() {
    if (!current) return;
    const started = performance.now();
    try {
      current.instance.draw();
      if (current.failed) { status(''); current.failed = false; }
    } catch (error) {
      status(error.message, true);
      current.failed = true;
    }
    frameTimes.push(performance.now() - started);
    if (frameTimes.length > 1000) frameTimes.shift();
  }

  function show(id, values) {
    // A new view, or a link followed: what was not yet written is dropped.
    pendingChanges = [];
    clearTimeout(pendingTimer);
    pendingTimer = 0;
    const view = views.find((v) => v.id === id) || views[0];
    const merged = Object.assign({}, view.defaults, values || {});
    for (const button of document.querySelectorAll('#views button')) {
      button.setAttribute('aria-selected', String(button.dataset.view === view.id));
      button.tabIndex = button.dataset.view === view.id ? 0 : -1;
    }
    document.getElementById('view-title').textContent = view.title;
    document.getElementById('view-explanation').textContent = view.explanation;
    document.getElementById('view-seed').textContent = view.seed;
    const controls = document.getElementById('controls');
    const figures = document.getElementById('figures');
    const readout = document.getElementById('readout');
    controls.replaceChildren();
    figures.replaceChildren();
    readout.replaceChildren();
    status('');
    frameTimes.length = 0;
    const context = {
      library,
      values: merged,
      controls,
      figures,
      /// Stores the view's values in the URL: `changes` is an object, or a
      /// function giving one (called once when the URL is written, at most every
      /// 150 ms and at the end of a drag: formatting 1,000 points on every
      /// pointer move would cost more than drawing them).
      save(changes) {
        pendingChanges.push(changes);
        if (!pendingTimer) pendingTimer = setTimeout(writeState, 150);
      },
      /// A new figure under the controls.
      plot(options) {
        const plot = new Plot(figures, options);
        plot.ondraw = redraw;
        return plot;
      },
      /// Replaces the read-out under the figures with the given nodes or text.
      readout(...nodes) { readout.replaceChildren(...nodes); },
      redraw,
    };
    current = { view, values: merged, instance: null, failed: false };
    try {
      current.instance = view.mount(context);
    } catch (error) {
      status(error.message, true);
      current.instance = { draw() {}, model: () => null };
    }
    PageState.write(view.id, merged);
    document.body.dataset.view = view.id;
    redraw();
  }

  function download(name, type, text) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([text], { type }));
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 0);
  }

  function exportModel(format) {
    try {
      const shape = current && current.instance.model ? current.instance.model() : null;
      if (!shape) { status('this view has nothing to export'); return; }
      if (format === 'json') download(`${current.view.id}.json`, 'application/json', ModelExport.modelJson(shape));
      else download(`${current.view.id}.svg`, 'image/svg+xml', ModelExport.svg(library, shape));
    } catch (error) {
      status(error.message, true);
    }
  }

  function buildNavigation() {
    const nav = document.getElementById('views');
    nav.setAttribute('role', 'tablist');
    for (const view of views) {
      const button = document.createElement('button');
      button.type = 'button';
      button.setAttribute('role', 'tab');
      button.dataset.view = view.id;
      button.textContent = view.title;
      button.addEventListener('click', () => show(view.id));
      nav.appendChild(button);
    }
    // Arrow keys move between the tabs (the WAI-ARIA tabs pattern).
    nav.addEventListener('keydown', (event) => {
      const buttons = [...nav.querySelectorAll('button')];
      const at = buttons.indexOf(document.activeElement);
      if (at < 0 || (event.key !== 'ArrowRight' && event.key !== 'ArrowLeft')) return;
      const next = buttons[(at + (event.key === 'ArrowRight' ? 1 : buttons.length - 1)) % buttons.length];
      next.focus();
      next.click();
      event.preventDefault();
    });
  }

  async function start() {
    try {
      library = await loadLibrary();
    } catch (error) {
      status(`the WebAssembly module did not load: ${error.message}`, true);
      throw error;
    }
    buildNavigation();
    window.addEventListener('pointerup', writeState);
    document.getElementById('export-json').addEventListener('click', () => exportModel('json'));
    document.getElementById('export-svg').addEventListener('click', () => exportModel('svg'));
    const { view, values } = PageState.read();
    show(view, values);
    // The page writes its own state with replaceState (no event): a hashchange
    // is a link followed or an address edited, so show what it says.
    window.addEventListener('hashchange', () => {
      const state = PageState.read();
      show(state.view, state.values);
    });
  }

  window.Playground = {
    register,
    show,
    redraw,
    frameTimes,
    views,
    /// The view on screen: {id, instance} (tests and the benchmark read it).
    current: () => current && { id: current.view.id, instance: current.instance, values: current.values },
    /// The loaded library (js/library.js), once ready.
    library: () => library,
    ready: null,
  };
  window.addEventListener('DOMContentLoaded', () => { window.Playground.ready = start(); });
})();
