// How cncjs's interpreter reads a G-code program: node interpret.mjs IN.nc OUT.json
// npm's gcode-toolpath 3.0.0 (on gcode-interpreter and gcode-parser, what
// cncjs runs to draw and send a program) interprets the file and reports its
// motion: every G0/G1 move with its two end points and every G2/G3 arc with
// its start, end and centre, in mm (the interpreter converts inches) as
// JSON: {"units": "G21", "moves": [{"motion": "G2", "from": [x, y, z],
// "to": [...], "centre": [...]}, ...], "unhandled": ["G64", ...], "errors":
// [...]}. "unhandled" lists the codes it has no handler for; "errors" what
// it reported (console.error, a parse failure). gcode_check.cpp compares
// the motion with casteljau's curves.
import { createRequire } from 'node:module';
import { writeFile } from 'node:fs/promises';

const require = createRequire(import.meta.url);
const Toolpath = require('gcode-toolpath');

const [inPath, outPath] = process.argv.slice(2);
if (!inPath || !outPath) {
  console.error('usage: node interpret.mjs IN.nc OUT.json');
  process.exit(2);
}

const moves = [];
const unhandled = new Set();
const errors = [];
const point = (v) => [v.x, v.y, v.z];
// The interpreter reports its problems on the console: keep them as errors.
const consoleError = console.error;
console.error = (...args) => errors.push(args.map(String).join(' '));

const toolpath = new Toolpath({
  addLine: (modal, v1, v2) => moves.push({ motion: modal.motion, from: point(v1), to: point(v2) }),
  addArcCurve: (modal, v1, v2, v0) =>
    moves.push({ motion: modal.motion, from: point(v1), to: point(v2), centre: point(v0) }),
});
// Codes the toolpath has no handler for (gcode-interpreter's defaultHandler).
toolpath.defaultHandler = (cmd) => unhandled.add(cmd);

let units = 'G21';
toolpath.loadFromFileSync(inPath, () => {
  units = toolpath.getModal().units;
});
console.error = consoleError;
await writeFile(outPath, JSON.stringify({ units, moves, unhandled: [...unhandled], errors }));
