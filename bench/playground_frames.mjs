// The playground's redraw time while dragging, measured in the browser:
// node bench/playground_frames.mjs PAGE_DIR [OUT.md]   (make bench-playground)
// Debian's Chromium (headless, software canvas) opens the page from file://;
// for each workload the mouse drags one control point in 120 steps, and each
// pointer move redraws the view synchronously. Timed: each move's whole
// handling (the view's state, the library's WebAssembly calls, the canvas
// commands); the browser's rasterizing of the canvas afterwards is not in it.
// Prints the median, 95th percentile
// and largest redraw time of each workload as a Markdown table.
import { createRequire } from 'node:module';
import { writeFileSync } from 'node:fs';
import { resolve, dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { cpus, loadavg } from 'node:os';

// playwright-core is installed for the tests (make deps): tests/playground/node_modules.
const here = dirname(fileURLToPath(import.meta.url));
const { chromium } = createRequire(join(here, '..', 'tests', 'playground', 'package.json'))('playwright-core');

const [pageDir, outPath] = process.argv.slice(2);
if (!pageDir) {
  console.error('usage: node bench/playground_frames.mjs PAGE_DIR [OUT.md]');
  process.exit(2);
}
const pageUrl = pathToFileURL(resolve(pageDir, 'index.html')).href;
const STEPS = 120;

/// n points along a wave, "x,y;x,y" for the URL.
function wave(n, width, height) {
  return Array.from({ length: n }, (_, i) => {
    const x = (width * i) / (n - 1) - width / 2;
    return `${x.toFixed(4)},${(height * Math.sin((i * 2 * Math.PI * 7) / n)).toFixed(4)}`;
  }).join(';');
}

const workloads = [
  { name: 'Bézier curve of degree 20 (construction shown)', hash: `#view=bezier&levels=1&points=${wave(21, 10, 3)}`, handle: 10 },
  { name: "the car's C² cubic spline (26 points, not-a-knot)", hash: '#view=interpolation&data=car&method=cubic&end=not-a-knot', handle: 12 },
  { name: 'cubic B-spline of 1,000 control points', hash: `#view=bspline&deboor=1&points=${wave(1000, 100, 3)}`, handle: 500 },
  { name: 'B-spline surface, 20 × 20 net (40 × 40 shaded cells)', hash: '#view=surfaces&patch=bspline&N=20', handle: 210 },
];

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});
const rows = [];
try {
  const page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
  for (const workload of workloads) {
    await page.goto('about:blank');
    await page.goto(`${pageUrl}${workload.hash}`);
    await page.evaluate(() => window.Playground.ready);
    const [x, y] = await page.evaluate((k) => {
      const plot = window.Playground.current().instance.plot;
      const rect = plot.canvas.getBoundingClientRect();
      const [px, py] = plot.toScreen(plot.handles[k].x, plot.handles[k].y);
      return [rect.left + px, rect.top + py];
    }, workload.handle);
    const problem = await page.evaluate(() => document.getElementById('status').textContent);
    if (problem) throw new Error(`${workload.name}: ${problem}`);
    await page.mouse.move(x, y);
    await page.mouse.down();
    // Each pointer move's whole handling: from a capturing listener on the
    // window (first) to a bubbling one (last): the view's state, its redraw.
    await page.evaluate(() => {
      window.moveTimes = [];
      let started = 0;
      window.addEventListener('pointermove', () => { started = performance.now(); }, true);
      window.addEventListener('pointermove', () => { window.moveTimes.push(performance.now() - started); });
    });
    for (let step = 1; step <= STEPS; ++step) {
      await page.mouse.move(x + 40 * Math.sin((step * Math.PI) / 30), y - 30 * Math.sin((step * Math.PI) / 45));
    }
    await page.mouse.up();
    const times = (await page.evaluate(() => window.moveTimes)).sort((a, b) => a - b);
    const at = (q) => times[Math.min(times.length - 1, Math.floor(q * times.length))];
    rows.push([workload.name, times.length, at(0.5), at(0.95), times[times.length - 1]]);
  }
} finally {
  await browser.close();
}
const lines = [
  `Playground redraw while dragging (Chromium headless, software canvas; ` +
    `${new Date().toISOString().slice(0, 10)}, ${cpus().length} cores, load ${loadavg()[0].toFixed(2)}):`,
  '',
  '| workload | redraws | median ms | 95th percentile ms | largest ms |',
  '|---|---:|---:|---:|---:|',
  ...rows.map(([name, count, median, p95, largest]) => `| ${name} | ${count} | ${median.toFixed(2)} | ${p95.toFixed(2)} | ${largest.toFixed(2)} |`),
  '',
];
process.stdout.write(lines.join('\n'));
if (outPath) writeFileSync(outPath, lines.join('\n'));
