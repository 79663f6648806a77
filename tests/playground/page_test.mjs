// The playground in a real browser: node page_test.mjs PAGE_DIR CLI EXAMPLES [SHOTS_DIR]
// Debian's Chromium driven by playwright-core opens PAGE_DIR/index.html from
// file:// (as a user who double-clicks it) and checks, for every view, that it
// loads and draws with no console error; then what the page shows against
// references it did not compute: the notebook polygon's C(0.5) = (2.25, 1.5)
// (seed 004's worked value), the head's C¹ control points against the CLI's
// `casteljau interpolate`, an exported model read back by `casteljau eval`.
// Dragging and the keyboard must change the curve and the URL; a phone-sized
// window must not scroll sideways. With SHOTS_DIR, a screenshot of each view
// goes there (make demo puts them into the gallery).
import { chromium } from 'playwright-core';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import assert from 'node:assert/strict';

const [pageDir, cli, examples, shotsDir] = process.argv.slice(2);
if (!pageDir || !cli || !examples) {
  console.error('usage: node page_test.mjs PAGE_DIR CLI EXAMPLES [SHOTS_DIR]');
  process.exit(2);
}
const pageUrl = pathToFileURL(resolve(pageDir, 'index.html')).href;
const work = mkdtempSync(join(tmpdir(), 'playground-'));
const problems = [];  // console errors and uncaught exceptions, with the view they came from
let failures = 0;

async function check(name, body) {
  try {
    await body();
    console.log(`ok   ${name}`);
  } catch (error) {
    ++failures;
    console.log(`FAIL ${name}\n     ${String(error.stack || error).split('\n').slice(0, 4).join('\n     ')}`);
  }
}

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});

async function open(page, hash) {
  let where = hash;
  page.on('console', (message) => { if (message.type() === 'error') problems.push(`${where}: ${message.text()}`); });
  page.on('pageerror', (error) => problems.push(`${where}: ${error.message}`));
  await page.goto(`${pageUrl}${hash}`);
  await page.waitForFunction(() => window.Playground && window.Playground.ready);
  await page.evaluate(() => window.Playground.ready);
  where = hash;
}

/// The gallery page of the screenshots: each view's title, seed and explanation.
async function screenshotIndex(page) {
  const views = await page.evaluate(() => window.Playground.views.map(({ id, title, seed, explanation }) => ({ id, title, seed, explanation })));
  const escape = (text) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;');
  const figures = views.map((v) => `<figure id="${v.id}">\n<h2>${escape(v.title)}</h2>\n` +
    `<img src="playground_${v.id}.png" alt="${escape(v.title)} view of the playground" style="max-width:100%">\n` +
    `<figcaption>${escape(v.explanation)} <em>${escape(v.seed)}</em></figcaption>\n</figure>`).join('\n');
  return `<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>casteljau playground, view by view</title>\n` +
    `<link rel="icon" href="data:,">\n</head>\n<body style="font-family:sans-serif;max-width:1200px;margin:2em auto">\n` +
    `<h1>The web playground, view by view</h1>\n<p>Screenshots taken in Chromium by tests/playground/page_test.mjs ` +
    `(make demo). The page itself: out/playground/index.html.</p>\n${figures}\n</body>\n</html>\n`;
}

/// Loads the page afresh at a fragment (a new document, not a hash change).
async function load(page, hash) {
  await page.goto('about:blank');
  await page.goto(`${pageUrl}${hash}`);
  await page.evaluate(() => window.Playground.ready);
}

/// The status line (bad input is reported there, never thrown to the console).
const statusOf = (page) => page.evaluate(() => document.getElementById('status').textContent);

try {
  const context = await browser.newContext({ viewport: { width: 1200, height: 900 }, acceptDownloads: true });
  const page = await context.newPage();
  await open(page, '');
  const views = await page.evaluate(() => window.Playground.views.map((view) => view.id));

  await check(`every view loads and draws from file:// (${views.join(', ')})`, async () => {
    for (const id of views) {
      await page.click(`#views button[data-view="${id}"]`);
      await page.waitForFunction((v) => document.body.dataset.view === v, id);
      assert.equal(await statusOf(page), '', `${id}: the status line reports an error`);
      const drawn = await page.evaluate(() => [...document.querySelectorAll('#figures canvas')].map((canvas) => {
        const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        let inked = 0;
        for (let i = 3; i < data.length; i += 4) if (data[i] > 0) ++inked;
        return inked;
      }));
      assert.ok(drawn.length > 0 && drawn.every((inked) => inked > 500), `${id}: a figure is blank (${drawn})`);
      assert.ok(page.url().includes(`view=${id}`), `${id}: the URL does not name the view`);
      if (shotsDir) await page.screenshot({ path: join(shotsDir, `playground_${id}.png`), fullPage: true });
    }
    if (shotsDir) writeFileSync(join(shotsDir, 'index.html'), await screenshotIndex(page));
  });

  await check('the notebook polygon shows C(0.5) = (2.25, 1.5) (seed 004)', async () => {
    await load(page, '#view=bezier&t=0.5');
    await page.waitForFunction(() => document.getElementById('point-at-t'));
    const shown = await page.evaluate(() => {
      const span = document.getElementById('point-at-t');
      return [Number(span.dataset.x), Number(span.dataset.y), span.textContent];
    });
    assert.deepEqual(shown.slice(0, 2), [2.25, 1.5]);
    assert.match(shown[2], /\(2\.25, 1\.5\)/);
  });

  await check('dragging a control point changes the curve, the picture and the URL', async () => {
    const before = await page.evaluate(() => ({
      curve: Array.from(window.Playground.current().instance.model().control),
      picture: document.querySelector('#figures canvas').toDataURL(),
    }));
    const handle = await page.evaluate(() => {
      const plot = window.Playground.current().instance.plot;
      const rect = plot.canvas.getBoundingClientRect();
      const [px, py] = plot.toScreen(plot.handles[2].x, plot.handles[2].y);
      return [rect.left + px, rect.top + py];
    });
    await page.mouse.move(handle[0], handle[1]);
    await page.mouse.down();
    await page.mouse.move(handle[0] + 30, handle[1] + 40, { steps: 5 });
    await page.mouse.up();
    const after = await page.evaluate(() => ({
      curve: Array.from(window.Playground.current().instance.model().control),
      picture: document.querySelector('#figures canvas').toDataURL(),
    }));
    assert.notDeepEqual(after.curve.slice(4, 6), before.curve.slice(4, 6), 'P2 did not move');
    assert.deepEqual(after.curve.slice(0, 4), before.curve.slice(0, 4), 'other points moved');
    assert.notEqual(after.picture, before.picture, 'the figure was not redrawn');
    assert.ok(!page.url().includes('points=0,0;1,2;2,2;4,1;4,0'), 'the URL still holds the old points');
  });

  await check('the keyboard selects and moves a point', async () => {
    await load(page, '#view=bezier');
    const before = await page.evaluate(() => Array.from(window.Playground.current().instance.model().control));
    await page.focus('#figures canvas');
    await page.keyboard.press(']');
    await page.keyboard.press('ArrowUp');
    const after = await page.evaluate(() => Array.from(window.Playground.current().instance.model().control));
    assert.equal(after[2], before[2]);
    assert.ok(after[3] > before[3], 'ArrowUp did not raise P1');
  });

  await check('the head\'s C¹ control points equal casteljau interpolate\'s', async () => {
    const expected = JSON.parse(execFileSync(cli, ['interpolate', join(examples, 'head.csv'), '--method', 'c1-bezier', '--alpha', '1.5']));
    await load(page, '#view=interpolation&data=head&method=c1-bezier&alpha=1.5');
    const shown = await page.evaluate(() => [...document.querySelectorAll('#control-points tr')].slice(1).map((row) =>
      [...row.querySelectorAll('td[data-x]')].map((cell) => [Number(cell.dataset.x), Number(cell.dataset.y)])));
    assert.equal(shown.length, expected.pieces.length);
    assert.ok(await page.isVisible('label:text-is("α")') && !(await page.isVisible('label:text-is("ends")')),
      'C¹ Bézier shows α and hides the end conditions');
    shown.forEach((piece, i) => piece.forEach((point, k) => point.forEach((value, d) => {
      const reference = expected.pieces[i][k][d];
      assert.ok(Math.abs(value - reference) <= 1e-13 * 20, `piece ${i} point ${k}: ${value} vs ${reference}`);
    })));
  });

  await check('an exported model reads back in the CLI (casteljau eval)', async () => {
    await load(page, '#view=bezier');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-json')]);
    const saved = join(work, 'exported.json');
    await download.saveAs(saved);
    const csv = execFileSync(cli, ['eval', saved, '--at', '0.5']).toString().trim();
    assert.equal(csv, '2.25,1.5');
    const [svg] = await Promise.all([page.waitForEvent('download'), page.click('#export-svg')]);
    const svgPath = join(work, 'exported.svg');
    await svg.saveAs(svgPath);
    assert.match(readFileSync(svgPath, 'utf8'), /^<svg [^>]*viewBox=/);
  });

  await check('the state in the URL comes back: alpha, method and points', async () => {
    await load(page, '#view=interpolation&data=car&method=cubic&end=natural&param=centripetal');
    const curve = await page.evaluate(() => window.Playground.current().instance.model());
    assert.equal(curve.kind, 'bspline');
    assert.equal(await page.evaluate(() => document.querySelectorAll('#figures canvas').length), 1);
    assert.equal(await statusOf(page), '');
  });

  await check('bad input is reported on the status line, not thrown', async () => {
    await load(page, '#view=bezier&points=0,0;1,1;2,0');
    await page.evaluate(() => { window.Playground.current().instance.plot.handles[1].x = NaN; window.Playground.redraw(); });
    assert.match(await statusOf(page), /NaN/);
  });

  await check('a phone-sized window: no sideways scrolling, and a touch drag moves a point', async () => {
    const phone = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
    const small = await phone.newPage();
    await open(small, '#view=bezier');
    const overflow = await small.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 0, `the page is ${overflow}px wider than the phone`);
    const before = await small.evaluate(() => Array.from(window.Playground.current().instance.model().control));
    // A real touch drag (Chromium's input pipeline turns it into pointer events).
    const [x, y] = await small.evaluate(() => {
      const plot = window.Playground.current().instance.plot;
      const rect = plot.canvas.getBoundingClientRect();
      const [px, py] = plot.toScreen(plot.handles[1].x, plot.handles[1].y);
      return [rect.left + px + 4, rect.top + py + 8];
    });
    const cdp = await phone.newCDPSession(small);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x, y }] });
    for (let step = 1; step <= 4; ++step) {
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: x + 6 * step, y: y + 5 * step }] });
    }
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    const after = await small.evaluate(() => Array.from(window.Playground.current().instance.model().control));
    assert.notDeepEqual(after.slice(2, 4), before.slice(2, 4));
    await phone.close();
  });

  await check('B-spline: inserting a knot adds a control point and keeps the curve; a knot dropped on another stacks', async () => {
    await load(page, '#view=bspline');
    const sample = () => page.evaluate(() => {
      const model = window.Playground.current().instance.model();
      const us = Array.from({ length: 41 }, (_, j) => j / 40);
      return { model: { control: Array.from(model.control), knots: Array.from(model.knots) },
               points: Array.from(window.Playground.library().pointsAt(model, us)) };
    });
    const before = await sample();
    await page.click('button:text("Insert knot at u")');
    const after = await sample();
    assert.equal(after.model.control.length, before.model.control.length + 2);
    assert.equal(after.model.knots.length, before.model.knots.length + 1);
    after.points.forEach((value, i) => assert.ok(Math.abs(value - before.points[i]) <= 1e-13 * 10, `point ${i >> 1} moved`));
    // Drag the first interior knot of the ruler onto the second.
    const [from, to] = await page.evaluate(() => {
      const ruler = window.Playground.current().instance.ruler;
      const rect = ruler.canvas.getBoundingClientRect();
      const at = (h) => { const [px, py] = ruler.toScreen(h.x, h.y); return [rect.left + px, rect.top + py]; };
      return [at(ruler.handles[0]), at(ruler.handles[1])];
    });
    await page.mouse.move(...from);
    await page.mouse.down();
    await page.mouse.move(to[0] + 1, from[1], { steps: 6 });
    await page.mouse.up();
    const knots = await page.evaluate(() => Array.from(window.Playground.current().instance.model().knots));
    const interior = knots.slice(4, -4);
    assert.equal(interior[0], interior[1], `the knots did not stack: ${interior}`);
    assert.equal(await statusOf(page), '');
  });

  await check('NURBS: the circle is exact to rounding; the seed\'s cubic semicircle is off by 1.8 % of the radius', async () => {
    await load(page, '#view=nurbs');
    const [circle, cubic] = await page.evaluate(() => {
      const line = document.getElementById('nurbs-errors');
      return [Number(line.dataset.circle), Number(line.dataset.cubic)];
    });
    assert.ok(circle <= 1e-14 * 2, `circle off by ${circle}`);
    // The cubic (-3,0) (-3,4) (3,4) (3,0) in closed form, x = -3(1-t)³ - 9t(1-t)² + 9t²(1-t) + 3t³,
    // y = 12t(1-t): its largest | |C| - 3 | is 0.0550505 at t(1-t) = 1/6 (numpy, 2,000,001 samples);
    // the page samples 721 parameters.
    assert.ok(Math.abs(cubic - 0.0550505) <= 1e-6, `cubic off by ${cubic}`);
  });

  await check('surfaces: dragging a net point moves its height; dragging elsewhere turns the view; the export reads back', async () => {
    await load(page, '#view=surfaces&patch=bezier');
    const before = await page.evaluate(() => ({ net: Array.from(window.Playground.current().instance.model().net), url: location.hash }));
    const [x, y] = await page.evaluate(() => {
      const plot = window.Playground.current().instance.plot;
      const rect = plot.canvas.getBoundingClientRect();
      const [px, py] = plot.toScreen(plot.handles[5].x, plot.handles[5].y);
      return [rect.left + px, rect.top + py];
    });
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x, y - 40, { steps: 4 });
    await page.mouse.up();
    const after = await page.evaluate(() => Array.from(window.Playground.current().instance.model().net));
    assert.deepEqual(after.slice(15, 17), before.net.slice(15, 17), 'the point moved sideways');
    assert.ok(after[17] > before.net[17], 'the point did not rise');
    await page.mouse.move(x + 300, y + 150);
    await page.mouse.down();
    await page.mouse.move(x + 360, y + 150, { steps: 4 });
    await page.mouse.up();
    assert.notEqual(await page.evaluate(() => new URLSearchParams(location.hash.slice(1)).get('yaw')),
      new URLSearchParams(before.url.slice(1)).get('yaw'), 'the view did not turn');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-json')]);
    const saved = join(work, 'surface.json');
    await download.saveAs(saved);
    const corner = execFileSync(cli, ['eval', saved, '--at', '0,0']).toString().trim().split(',').map(Number);
    assert.deepEqual(corner, after.slice(0, 3), 'S(0,0) is not the corner of the net');
    for (const patch of ['bspline', 'coons']) {
      await page.selectOption('#controls select', patch);
      assert.equal(await statusOf(page), '', `${patch}: the status line reports an error`);
    }
  });

  await check('queries: the nearest point follows the pointer; crossings agree with casteljau intersect', async () => {
    await load(page, '#view=queries&arcs=1');
    const box = await page.evaluate(() => {
      const rect = window.Playground.current().instance.plot.canvas.getBoundingClientRect();
      return [rect.left, rect.top, rect.width, rect.height];
    });
    await page.mouse.move(box[0] + box[2] * 0.3, box[1] + box[3] * 0.8);
    const summary = await page.evaluate(() => document.getElementById('query-summary').textContent);
    assert.match(summary, /nearest point C\(/);
    const counts = summary.match(/(\d+) crossings? with the segment, (\d+) of the curve with itself/).slice(1).map(Number);
    const model = await page.evaluate(() => {
      const curve = window.Playground.current().instance.model();
      return { degree: curve.degree, knots: Array.from(curve.knots), control: Array.from(curve.control) };
    });
    const segment = await page.evaluate(() => {
      const h = window.Playground.current().instance.plot.handles.slice(-2);
      return { type: 'bezier', control_points: h.map((p) => [p.x, p.y]) };
    });
    const curvePath = join(work, 'query_curve.json'), segmentPath = join(work, 'query_segment.json');
    const rows = model.control.reduce((out, v, i) => { if (i % 2) out[out.length - 1].push(v); else out.push([v]); return out; }, []);
    writeFileSync(curvePath, JSON.stringify({ type: 'bspline', degree: model.degree, knots: model.knots, control_points: rows }));
    writeFileSync(segmentPath, JSON.stringify(segment));
    const crossings = JSON.parse(execFileSync(cli, ['intersect', curvePath, segmentPath])).intersections;
    const own = JSON.parse(execFileSync(cli, ['intersect', curvePath])).intersections;
    assert.deepEqual(counts, [crossings.length, own.length]);
    assert.deepEqual(counts, [3, 1]);
  });

  await check('no console errors anywhere', async () => {
    assert.deepEqual(problems, []);
  });
} finally {
  await browser.close();
  rmSync(work, { recursive: true, force: true });
}
process.exit(failures ? 1 : 0);
