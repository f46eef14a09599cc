// SPDX-License-Identifier: BSD-3-Clause
// Executed notebooks in headless Chromium (issue 39, item 3): the HTML page that
// `jupyter nbconvert --to html` makes of an executed notebook holds its reports, each in its own
// sandboxed iframe. For every page of --spec: the notebook keeps its own layout (the reports'
// styles do not reach it: the body is not a flex box, the frames stand one below the other);
// every frame loads its report without console errors, its viewer draws (the 3D canvas is not
// blank) and its verdict panel says that report's verdict and not another's. Screenshots of each
// frame go to --out. Same harness as check_reports.mjs (playwright-core + Debian's chromium).
// Exit 0 all passed, 1 failures, 77 skipped (no playwright-core or Chromium).
//
// node tests/browser/check_notebooks.mjs --modules build/release/viewer/node_modules \
//   --chromium /usr/bin/chromium --out build/release/browser-artifacts/notebooks --spec spec.json
// spec.json: [{"html": "network.html", "reports": [{"verdict": ["Exactly constrained"],
//              "not": ["redundant"]}, ...]}, ...], one entry per report, in page order.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const option = (name, fallback) => {
  const i = process.argv.indexOf('--' + name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const modules = option('modules', 'build/release/viewer/node_modules');
const executable = option('chromium', '/usr/bin/chromium');
const out = option('out', 'build/release/browser-artifacts/notebooks');
const spec = JSON.parse(fs.readFileSync(option('spec', 'spec.json'), 'utf8'));

if (!fs.existsSync(path.join(modules, 'playwright-core')) || !fs.existsSync(executable)) {
  const required = process.env.KINESTAT_REQUIRE_BROWSER === '1';
  console.log((required ? 'FAILED: ' : 'SKIP: ') + 'playwright-core (' + modules + ') or Chromium (' + executable + ') is missing');
  process.exit(required ? 1 : 77);
}
const require = createRequire(path.join(path.resolve(modules), 'index.js'));
const { chromium } = require('playwright-core');

fs.mkdirSync(out, { recursive: true });
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'kinestat-notebooks-'));
const context = await chromium.launchPersistentContext(path.join(work, 'profile'), {
  executablePath: executable,
  headless: true,
  viewport: { width: 1100, height: 900 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
});

const failures = [];
let checks = 0;
const check = (condition, message) => {
  checks++;
  if (!condition) failures.push(message);
};

// Inked pixels of the report's WebGL canvas (read through a 2D canvas), as check_reports.mjs.
const ink = () => {
  const source = document.getElementById('view');
  if (!source) return { total: 0, ink: 0 };
  const c = document.createElement('canvas');
  c.width = source.width;
  c.height = source.height;
  const g = c.getContext('2d');
  g.drawImage(source, 0, 0);
  const data = g.getImageData(0, 0, c.width, c.height).data;
  let inked = 0;
  for (let i = 0; i < data.length; i += 4) if (data[i] < 235 || data[i + 1] < 235 || data[i + 2] < 235) inked++;
  return { total: data.length / 4, ink: inked };
};

// One notebook page: its layout, then each report frame in turn. Pages are checked at the same
// time (most of the time is Chromium loading and the viewers starting); the log keeps page order.
const checkNotebook = async (notebook, log) => {
  const name = path.basename(notebook.html, '.html');
  const page = await context.newPage();
  const errors = [];
  // nbconvert's page links a custom.css beside it that it does not write, and Debian's nbconvert
  // links require.js from /usr/share/javascript (libjs-requirejs): not errors of kinestat's.
  page.on('console', (m) => {
    const url = m.location().url || '';
    if (m.type() === 'error' && !url.endsWith('/custom.css') && !url.includes('/usr/share/javascript/')) errors.push(m.text() + ' ' + url);
  });
  page.on('pageerror', (e) => errors.push(String(e)));
  const opened = Date.now();
  await page.goto(pathToFileURL(path.resolve(notebook.html)).href);
  log.push(name + ': page loaded in ' + (Date.now() - opened) + ' ms');
  // The notebook's own layout: the reports' `body {display: flex}` and `html, body {height:
  // 100%}` must not reach it, and the frames stand one below the other at the page's width.
  const layout = await page.evaluate(() => ({
    display: getComputedStyle(document.body).display,
    width: document.body.getBoundingClientRect().width,
    frames: [...document.querySelectorAll('iframe')].map((f) => {
      const r = f.getBoundingClientRect();
      return { top: r.top + window.scrollY, bottom: r.bottom + window.scrollY, width: r.width };
    }),
  }));
  check(layout.display !== 'flex', name + ': the notebook body became a flex box');
  check(layout.frames.length === notebook.reports.length,
        name + ': ' + layout.frames.length + ' report frames, expected ' + notebook.reports.length);
  for (let i = 1; i < layout.frames.length; i++) {
    check(layout.frames[i].top >= layout.frames[i - 1].bottom, name + ': report ' + (i + 1) + ' is not below report ' + i);
  }
  for (const f of layout.frames) check(f.width > layout.width * 0.5, name + ': a report frame is narrower than half the page');

  const handles = await page.$$('iframe');
  for (let i = 0; i < Math.min(handles.length, notebook.reports.length); i++) {
    const expected = notebook.reports[i];
    const label = name + ' report ' + (i + 1);
    const begun = Date.now();
    // The frames load lazily: bring each into view first.
    await handles[i].scrollIntoViewIfNeeded();
    const frame = await handles[i].contentFrame();
    let started = false;
    try {
      await frame.waitForFunction(() => window.kinestatViewer && window.kinestatViewer.frames > 3, null, { timeout: 30000 });
      started = true;
    } catch (e) {
      failures.push(label + ': the viewer did not start: ' + errors.join('; '));
    }
    const state = await frame.evaluate((measure) => {
      const box = document.getElementById('verdict');
      const text = box ? box.textContent.replace(/\s+/g, ' ').trim() : '';
      // The panel leads with the verdict sentence; details (counts, rank evidence) follow it.
      const first = box && box.firstElementChild ? box.firstElementChild.textContent.replace(/\s+/g, ' ').trim() : text;
      return { verdict: text, summary: first, title: document.title,
               pixels: new Function('return ' + measure)()() };
    }, ink.toString());
    await handles[i].screenshot({ path: path.join(out, name + '-' + (i + 1) + '.png') });
    if (!started) continue;
    check(state.pixels.ink > state.pixels.total * 0.002, label + ': the 3D canvas is blank (' + state.pixels.ink + ' inked pixels)');
    for (const text of expected.verdict) {
      check(state.verdict.includes(text), label + ': the verdict panel does not say "' + text + '": ' + state.verdict.slice(0, 300));
    }
    for (const text of expected.not || []) {
      check(!state.summary.includes(text), label + ': the verdict says "' + text + '" (another report\'s?): ' + state.summary);
    }
    log.push(label + ' (' + state.title + ', ' + (Date.now() - begun) + ' ms): ' + state.summary);
  }
  check(errors.length === 0, name + ': console errors: ' + errors.join('; '));
  await page.close();
};
const logs = spec.map(() => []);
await Promise.all(spec.map((notebook, i) => checkNotebook(notebook, logs[i])));
for (const line of logs.flat()) console.log(line);
await context.close();
fs.rmSync(work, { recursive: true, force: true });
console.log(checks + ' checks, ' + failures.length + ' failed');
for (const f of failures) console.log('FAILED: ' + f);
process.exit(failures.length ? 1 : 0);
