// How Chromium draws each SVG file of a folder: node chromium_drawings.mjs DIR OUT.json
// Every file is opened as an SVG document (file://, parsed as XML). For each
// geometry element (path, rect, circle, ellipse, line, polyline, polygon) in
// document order, the browser reports getTotalLength() and
// getPointAtLength() at 65 equally spaced lengths, mapped to the root's user
// space (the element's screen CTM, then the inverse of the root's: every
// transform and nested viewport applied, the root's viewBox map not).
// chromium_check.cpp compares them with casteljau's reading.
import { chromium } from 'playwright-core';
import { readdir, writeFile } from 'node:fs/promises';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [folder, outPath] = process.argv.slice(2);
if (!folder || !outPath) {
  console.error('usage: node chromium_drawings.mjs DIR OUT.json');
  process.exit(2);
}
const files = (await readdir(folder)).filter((name) => name.endsWith('.svg')).sort();
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--allow-file-access-from-files'],
});
try {
  const page = await browser.newPage();
  const readings = {};
  for (const name of files) {
    await page.goto(pathToFileURL(resolve(join(folder, name))).href);
    readings[name] = await page.evaluate(() => {
      const root = document.documentElement;
      const toRoot = root.getScreenCTM().inverse();
      const elements = [];
      for (const element of root.querySelectorAll('path, rect, circle, ellipse, line, polyline, polygon')) {
        const m = toRoot.multiply(element.getScreenCTM());
        const total = element.getTotalLength();
        const points = [];
        if (total > 0) {
          for (let k = 0; k <= 64; ++k) {
            const p = element.getPointAtLength((total * k) / 64);
            points.push([m.a * p.x + m.c * p.y + m.e, m.b * p.x + m.d * p.y + m.f]);
          }
        }
        // The length in root units: the element's own scaled by the map, when
        // the map is a similarity (rotation, reflection, uniform scale);
        // under skews and uneven scales it is not known here (null).
        const scale = Math.sqrt(Math.abs(m.a * m.d - m.b * m.c));
        const near = (x, y) => Math.abs(x - y) <= 1e-6 * scale;
        const similar = (near(m.a, m.d) && near(m.b, -m.c)) || (near(m.a, -m.d) && near(m.b, m.c));
        elements.push({ tag: element.tagName, id: element.id, total: similar ? total * scale : null, points });
      }
      return elements;
    });
  }
  await writeFile(outPath, JSON.stringify({ browser: `Chromium ${browser.version()}`, readings }));
} finally {
  await browser.close();
}
