// How Chromium reads each path of a corpus: node chromium_paths.mjs CORPUS OUT.json
// For every case ("name | d" lines of the corpus) the browser builds a <path>
// with that d, and reports its getTotalLength() and getPointAtLength() at 65
// equally spaced lengths (float32 in the browser). chromium_check.cpp
// compares them with casteljau's reading. Debian's chromium, headless, no
// network, a new empty profile (toolchain.md).
import { chromium } from 'playwright-core';
import { readFile, writeFile } from 'node:fs/promises';

const [corpusPath, outPath] = process.argv.slice(2);
if (!corpusPath || !outPath) {
  console.error('usage: node chromium_paths.mjs CORPUS OUT.json');
  process.exit(2);
}

const unescape = (text) =>
  text.replace(/\\([tnrf])/g, (_, c) => ({ t: '\t', n: '\n', r: '\r', f: '\f' })[c]);
const cases = (await readFile(corpusPath, 'utf8'))
  .split('\n')
  .filter((line) => line.trim() !== '' && !line.startsWith('#'))
  .map((line) => {
    const bar = line.indexOf('|');
    return { name: line.slice(0, bar).trim(), d: unescape(line.slice(bar + 1).replace(/^ /, '').replace(/ $/, '')) };
  });

// launch() gives the browser a new empty profile of its own, removed on close.
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});
try {
  const page = await browser.newPage();
  await page.setContent('<!doctype html><html><head><link rel="icon" href="data:,"></head>' +
                        '<body><svg xmlns="http://www.w3.org/2000/svg" id="drawing"></svg></body></html>');
  const readings = await page.evaluate((cases) => {
    const svg = document.getElementById('drawing');
    const result = {};
    for (const { name, d } of cases) {
      const path = document.createElementNS('http://www.w3.org/2000/svg', 'path');
      path.setAttribute('d', d);
      svg.appendChild(path);
      const total = path.getTotalLength();
      const points = [];
      const samples = 64;
      if (total > 0) {
        for (let k = 0; k <= samples; ++k) {
          const p = path.getPointAtLength((total * k) / samples);
          points.push([p.x, p.y]);
        }
      }
      result[name] = { total, points };
    }
    return result;
  }, cases);
  await writeFile(outPath, JSON.stringify({ browser: `Chromium ${browser.version()}`, readings }));
} finally {
  await browser.close();
}
