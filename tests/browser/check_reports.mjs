// SPDX-License-Identifier: BSD-3-Clause
// Browser tests of the HTML reports: headless Chromium (Debian's `chromium`) driven by
// playwright-core from the npm registry. For every shipped example: the report opens without
// console errors, the 3D canvas is not blank, the verdict panel leads the side panel and the
// labels toggle shows and hides labels; a kinematic mode at two amplitudes gives two different
// pictures with the undeformed shape in grey under it; the 12-truss self-stress colours its
// twelve bars with two colours; Davies' network shows its self-stresses as coupling wrenches
// and its modes as body twists; the folded-sheet guide's self-stress has a non-zero range.
// Traced finite motion (issue 13): the 12-truss and the four-bar of bars animate their mode
// through traced configurations whose bar lengths, measured on the drawn 3D scene at many
// animation times (frozen and playing), stay within 1e-6 of the rest lengths, while the same
// mode drawn to first order stretches its bars; an infinitesimal mode says "first order only".
// Screenshots go to --out. Exit 0 all passed, 1 failures, 77 skipped (no playwright-core).
//
// node tests/browser/check_reports.mjs --cli build/release/kinestat \
//   --modules build/release/viewer/node_modules --examples examples \
//   --out build/release/browser-artifacts --chromium /usr/bin/chromium
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const option = (name, fallback) => {
  const i = process.argv.indexOf('--' + name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const cli = option('cli', 'build/release/kinestat');
const modules = option('modules', 'build/release/viewer/node_modules');
const examples = option('examples', 'examples');
const out = option('out', 'build/release/browser-artifacts');
const executable = option('chromium', '/usr/bin/chromium');
const only = option('only', '');

if (!fs.existsSync(path.join(modules, 'playwright-core')) || !fs.existsSync(executable)) {
  // CI sets KINESTAT_REQUIRE_BROWSER=1 so that a missing piece fails instead of skipping.
  const required = process.env.KINESTAT_REQUIRE_BROWSER === '1';
  console.log((required ? 'FAILED: ' : 'SKIP: ') + 'playwright-core (' + modules + ') or Chromium (' + executable + ') is missing');
  process.exit(required ? 1 : 77);
}
const require = createRequire(path.join(path.resolve(modules), 'index.js'));
const { chromium } = require('playwright-core');

fs.mkdirSync(out, { recursive: true });
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'kinestat-browser-'));
const context = await chromium.launchPersistentContext(path.join(work, 'profile'), {
  executablePath: executable,
  headless: true,
  viewport: { width: 1100, height: 700 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
});

const failures = [];
let checks = 0;
const check = (condition, message) => {
  checks++;
  if (!condition) failures.push(message);
};

// Pixel statistics of the WebGL canvas, read through a 2D canvas.
const pixels = () => {
  const source = document.getElementById('view');
  const c = document.createElement('canvas');
  c.width = source.width;
  c.height = source.height;
  const g = c.getContext('2d');
  g.drawImage(source, 0, 0);
  const data = g.getImageData(0, 0, c.width, c.height).data;
  let ink = 0, red = 0, blue = 0, grey = 0;
  for (let i = 0; i < data.length; i += 4) {
    const r = data[i], gr = data[i + 1], b = data[i + 2];
    if (r < 235 || gr < 235 || b < 235) ink++;
    if (r > gr + 60 && r > b + 60) red++;
    if (b > r + 60 && b > gr + 20) blue++;
    // The undeformed shape's light grey (#b0b0b0).
    if (Math.abs(r - 176) < 20 && Math.abs(gr - 176) < 20 && Math.abs(b - 176) < 20) grey++;
  }
  return { total: data.length / 4, ink, red, blue, grey, url: source.toDataURL() };
};

// Opens a report and waits for the viewer to draw a few frames. Returns the page, the console
// and page errors seen (the list keeps growing while the page is used), and whether it started.
const openReport = async (html, timeout) => {
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(pathToFileURL(html).href);
  try {
    await page.waitForFunction(() => window.kinestatViewer && window.kinestatViewer.frames > 3, null, { timeout });
    return { page, errors, started: true };
  } catch (e) {
    return { page, errors, started: false };
  }
};

// Largest relative bar-length error over the drawn 3D scene: node positions read from the
// spheres and lengths read from the bar cylinders, each against the rest length computed from
// the scene's configuration (window.KINESTAT_SCENE.nodes.position).
const barErrors = () => {
  const v = window.kinestatViewer;
  const S = window.KINESTAT_SCENE;
  const P = S.nodes.position, E = S.elements.pairs;
  const pos = v.nodePositions(), drawn = v.barLengths();
  let nodes = 0, bars = 0, moved = 0;
  for (let e = 0; e < E.length / 2; e++) {
    const a = E[2 * e], b = E[2 * e + 1];
    const rest = Math.hypot(P[3 * b] - P[3 * a], P[3 * b + 1] - P[3 * a + 1], P[3 * b + 2] - P[3 * a + 2]);
    const now = Math.hypot(pos[b][0] - pos[a][0], pos[b][1] - pos[a][1], pos[b][2] - pos[a][2]);
    nodes = Math.max(nodes, Math.abs(now - rest) / rest);
    bars = Math.max(bars, Math.abs(drawn[e] - rest) / rest);
  }
  for (let i = 0; i < pos.length; i++)
    moved = Math.max(moved, Math.hypot(pos[i][0] - P[3 * i], pos[i][1] - P[3 * i + 1], pos[i][2] - P[3 * i + 2]));
  return { nodes, bars, moved, point: v.tracedPoint() };
};

// Plays the traced animation of mode 1 and measures bar lengths on the drawn scene.
const checkTracedMotion = async (page, name, views) => {
  const view = views.findIndex((v) => v.startsWith('mode 1'));
  const setup = await page.evaluate((i) => {
    const v = window.kinestatViewer;
    v.setFirstOrder(false);
    v.setView(i);
    v.setAmplitude(1);
    const t = window.KINESTAT_SCENE.modes[0].trace;
    return { traced: v.traced(0), label: v.views[i], panel: document.getElementById('motion').textContent,
             points: t ? t.arc.length : 0, start: t ? t.start : -1 };
  }, view);
  check(setup.traced && setup.panel.startsWith('finite motion, traced (max residual '),
        name + ': mode 1 is not shown as a traced finite motion (' + JSON.stringify(setup) + ')');
  if (!setup.traced) return;
  // Frozen animation times over a whole period, then the live animation at a few frames.
  const phases = [];
  for (let k = 0; k < 24; k++) phases.push(k * Math.PI / 12 + 0.05);
  const frozen = await page.evaluate(([measure, list]) => {
    const f = new Function('return ' + measure)();
    const v = window.kinestatViewer;
    return list.map((phase) => { v.freeze(phase); v.render(); return f(); });
  }, [barErrors.toString(), phases]);
  await page.evaluate(() => window.kinestatViewer.freeze(null));
  const live = [];
  for (let k = 0; k < 8; k++) {
    await page.waitForTimeout(130);
    live.push(await page.evaluate((measure) => new Function('return ' + measure)()(), barErrors.toString()));
  }
  const all = frozen.concat(live);
  const worst = Math.max(...all.map((r) => Math.max(r.nodes, r.bars)));
  const points = all.map((r) => r.point);
  const moved = Math.max(...all.map((r) => r.moved));
  check(worst <= 1e-6, name + ': the traced animation changes a bar length by ' + worst.toExponential(2) + ' of its rest length (> 1e-6)');
  check(Math.min(...points) >= 0 && Math.min(...points) < setup.start && Math.max(...points) > setup.start,
        name + ': the traced animation does not visit both sides of the configuration (points ' + [...new Set(points)].join(', ') + ', start ' + setup.start + ')');
  check(moved > 1e-3, name + ': the traced animation moves no node (largest displacement ' + moved + ')');
  console.log('     ' + name + ': traced animation through ' + setup.points + ' points, ' + new Set(points).size +
              ' visited; largest relative bar-length error ' + worst.toExponential(2) + ', largest displacement ' + moved.toPrecision(3));
  await page.evaluate(() => { const v = window.kinestatViewer; v.freeze(Math.PI / 2); v.render(); });
  await page.screenshot({ path: path.join(out, name + '-traced.png') });
  await page.evaluate(() => document.getElementById('mode').scrollIntoView());
  await page.screenshot({ path: path.join(out, name + '-traced-panel.png') });
  // The same mode to first order: the bars stretch (the measurement sees it).
  const first = await page.evaluate(([measure, list]) => {
    const f = new Function('return ' + measure)();
    const v = window.kinestatViewer;
    v.setFirstOrder(true);
    const out = list.map((phase) => { v.freeze(phase); v.render(); return f(); });
    v.freeze(Math.PI / 2);
    v.render();
    return { out, panel: document.getElementById('motion').textContent };
  }, [barErrors.toString(), phases]);
  const stretch = Math.max(...first.out.map((r) => r.nodes));
  check(stretch > 1e-3, name + ': the first-order animation should stretch bars, largest relative change ' + stretch.toExponential(2));
  console.log('     ' + name + ': first-order animation of the same mode: largest relative bar-length change ' + stretch.toExponential(2));
  await page.screenshot({ path: path.join(out, name + '-first-order.png') });
  await page.evaluate(() => { const v = window.kinestatViewer; v.setFirstOrder(false); v.freeze(null); });
};

const files = fs.readdirSync(examples).filter((f) => f.endsWith('.yaml') && (!only || f.includes(only))).sort();
for (const file of files) {
  const name = file.replace(/\.yaml$/, '');
  const html = path.join(work, name + '.html');
  execFileSync(cli, ['report', path.join(examples, file), '-o', html]);
  const { page, errors, started } = await openReport(html, 30000);
  if (!started) {
    failures.push(name + ': the viewer did not start: ' + errors.join('; '));
    await page.screenshot({ path: path.join(out, name + '.png') });
    await page.close();
    continue;
  }
  const still = await page.evaluate(pixels);
  check(still.ink > still.total * 0.002, name + ': the 3D canvas is blank (' + still.ink + ' inked pixels)');
  await page.screenshot({ path: path.join(out, name + '.png') });
  const views = await page.evaluate(() => window.kinestatViewer.views);
  // The verdict panel comes first in the side panel and says something.
  const verdict = await page.evaluate(() => {
    const box = document.getElementById('verdict');
    const side = document.getElementById('side');
    return { text: box ? box.textContent.trim() : '', first: box && [...side.children].indexOf(box) <= 1 };
  });
  check(verdict.text.length > 10 && verdict.first, name + ': no verdict panel at the top of the side panel');
  // Labels: hidden by default, shown by the toggle, hidden again.
  const labels = await page.evaluate(() => {
    const v = window.kinestatViewer;
    const before = v.labelsShown();
    v.setLabels(true);
    const shown = v.labelsShown();
    const visible = [...document.querySelectorAll('#labelLayer .label')].filter((e) => e.getBoundingClientRect().width > 0).length;
    v.setLabels(false);
    return { before, shown, visible, after: v.labelsShown() };
  });
  check(labels.before === 0 && labels.shown > 0 && labels.visible > 0 && labels.after === 0,
        name + ': the labels toggle does not show and hide labels (' + JSON.stringify(labels) + ')');
  if (['truss-12', 'davies-2-circuit'].includes(name)) {
    await page.evaluate(() => window.kinestatViewer.setLabels(true));
    await page.screenshot({ path: path.join(out, name + '-labels.png') });
    await page.evaluate(() => window.kinestatViewer.setLabels(false));
  }
  // Every mode that moves a drawn point must change the picture when the slider moves.
  let moving = 0;
  for (let mode = 0; mode < views.length; mode++) {
    if (!views[mode].startsWith('mode')) continue;
    const modeIndex = await page.evaluate((i) => window.kinestatViewer.views.slice(0, i).filter((v) => v.startsWith('mode')).length, mode);
    if (!(await page.evaluate((k) => window.kinestatViewer.modeMoves(k), modeIndex))) continue;
    moving++;
    const a = await page.evaluate((i) => {
      const v = window.kinestatViewer;
      v.freeze(Math.PI / 2);
      v.setView(i);
      v.setAmplitude(0);
      v.render();
      return document.getElementById('view').toDataURL();
    }, mode);
    const b = await page.evaluate(() => {
      const v = window.kinestatViewer;
      v.setAmplitude(1);
      v.render();
      return document.getElementById('view').toDataURL();
    });
    check(a !== b, name + ': moving the amplitude slider of ' + views[mode] + ' does not change the picture');
    // The undeformed shape stays in grey under the displaced one.
    const grey = { shown: await page.evaluate(() => window.kinestatViewer.ghostShown()), pixels: (await page.evaluate(pixels)).grey };
    check(grey.shown && grey.pixels > 20, name + ': no undeformed shape under ' + views[mode] + ' (' + JSON.stringify(grey) + ')');
    if (moving === 1) await page.screenshot({ path: path.join(out, name + '-mode.png') });
  }
  if (['truss-12', 'davies-2-circuit', 'four-bar-linkage'].includes(name))
    check(moving > 0, name + ': no kinematic mode that moves a drawn point');
  // Networks: the coupling screw axes and the motion system of a chosen pair are drawn.
  if (name === 'davies-2-circuit') {
    const result = await page.evaluate(() => {
      const v = window.kinestatViewer;
      v.freeze(0);
      v.setView(0);
      v.render();
      const before = document.getElementById('view').toDataURL();
      const box = document.getElementById('screws');
      box.checked = true;
      box.dispatchEvent(new Event('change'));
      v.render();
      const screws = document.getElementById('view').toDataURL();
      const pair = document.getElementById('pair');
      pair.value = '0';
      pair.dispatchEvent(new Event('change'));
      v.render();
      const withPair = document.getElementById('view').toDataURL();
      return { screws: screws !== before, pair: withPair !== screws, info: document.getElementById('pairinfo').textContent,
               pairs: pair.options.length - 1 };
    });
    check(result.screws, name + ': showing the coupling screw axes does not change the picture');
    check(result.pairs === 6, name + ': expected 6 pairs of bodies, found ' + result.pairs);
    check(result.pair && result.info.includes('Motion system'), name + ': choosing a pair does not show its motion system');
    await page.screenshot({ path: path.join(out, name + '-screws.png') });
  }
  const stress = views.findIndex((v) => v.startsWith('self-stress'));
  if (stress >= 0) {
    const result = await page.evaluate((i) => {
      const v = window.kinestatViewer;
      v.freeze(0);
      v.setView(i);
      v.render();
      return v.elementColours();
    }, stress);
    const seen = await page.evaluate(pixels);
    const range = await page.evaluate(() => window.kinestatViewer.stressRange());
    check(range > 0, name + ': the self-stress view has a zero range');
    if (name.startsWith('folded-sheet-guide')) {
      const coloured = result.filter((c) => !['#222222', '#444444', '#9fb3c8', '#dddddd', '#555555'].includes(c)).length;
      check(coloured >= 10, name + ': the flexure self-stress colours only ' + coloured + ' elements');
    }
    if (name === 'davies-2-circuit') {
      // Screenshots of the wrenches alone, with labels: hide the coupling screws and the pair.
      await page.evaluate(() => {
        const box = document.getElementById('screws');
        box.checked = false;
        box.dispatchEvent(new Event('change'));
        const pair = document.getElementById('pair');
        pair.selectedIndex = 0;
        pair.dispatchEvent(new Event('change'));
        window.kinestatViewer.setLabels(true);
      });
      const wrenches = [];
      for (let i = 0; i < views.length; i++) {
        if (!views[i].startsWith('self-stress')) continue;
        wrenches.push(await page.evaluate((k) => { const v = window.kinestatViewer; v.setView(k); v.render(); return v.wrenchCount(); }, i));
        await page.screenshot({ path: path.join(out, name + '-stress' + wrenches.length + '.png') });
      }
      check(wrenches.length === 2 && wrenches.every((w) => w > 0), name + ': expected two self-stress views with coupling wrenches, got ' + JSON.stringify(wrenches));
      const twists = [];
      for (let i = 0; i < views.length; i++) {
        if (!views[i].startsWith('mode')) continue;
        twists.push(await page.evaluate((k) => { const v = window.kinestatViewer; v.setView(k); v.render(); return v.twistCount(); }, i));
      }
      check(twists.length === 3 && twists.every((t) => t > 0), name + ': expected three modes with body twists, got ' + JSON.stringify(twists));
      await page.evaluate(() => window.kinestatViewer.setLabels(false));
      await page.evaluate((i) => { const v = window.kinestatViewer; v.setView(i); v.render(); }, stress);
    }
    if (name === 'truss-12') {
      await page.evaluate(() => window.kinestatViewer.setLabels(true));
      await page.screenshot({ path: path.join(out, name + '-stress-labels.png') });
      await page.evaluate(() => window.kinestatViewer.setLabels(false));
      check(result.length === 12, name + ': expected 12 bars, found ' + result.length);
      check(new Set(result).size === 2, name + ': the self-stress should colour the bars with two colours, found ' + [...new Set(result)].join(', '));
      check(seen.red > 100 && seen.blue > 100, name + ': tension (red) and compression (blue) not both visible (' + seen.red + ' red, ' + seen.blue + ' blue pixels)');
    }
    await page.screenshot({ path: path.join(out, name + '-stress.png') });
  }
  if (['truss-12', 'four-bar-linkage'].includes(name)) await checkTracedMotion(page, name, views);
  if (name === 'pellegrino-calladine-two-bar') {
    // The collinear two-bar's mode is blocked at second order: first-order animation, said so.
    const note = await page.evaluate((i) => {
      const v = window.kinestatViewer;
      v.setView(i);
      return { traced: v.traced(0), text: document.getElementById('motion').textContent };
    }, views.findIndex((v) => v.startsWith('mode 1')));
    await page.evaluate(() => document.getElementById('mode').scrollIntoView());
    await page.screenshot({ path: path.join(out, name + '-first-order-panel.png') });
    check(!note.traced && note.text.startsWith('first order only: blocked at second order'),
          name + ': the infinitesimal mode should say "first order only: blocked at second order ...", says ' + JSON.stringify(note));
  }
  check(errors.length === 0, name + ': console errors: ' + errors.join('; '));
  console.log((errors.length ? 'FAIL ' : 'ok   ') + name + ' (' + views.length + ' views)');
  await page.close();
}
// A generated planar strip of about 200 000 bars: the report opens and draws.
if (!only || only === 'large') {
  const columns = 66700;
  const lines = ['kinestat: 1', 'kind: framework', 'name: large strip', 'dimension: planar', 'nodes:'];
  for (let i = 0; i < columns; i++) lines.push('  a' + i + ': [' + i + ', 0]', '  b' + i + ': [' + i + ', 1]');
  lines.push('supports: {a0: fixed, b0: fixed}', 'elements:');
  for (let i = 0; i + 1 < columns; i++)
    lines.push('  - {type: truss, nodes: [a' + i + ', a' + (i + 1) + ']}', '  - {type: truss, nodes: [b' + i + ', b' + (i + 1) + ']}',
               '  - {type: truss, nodes: [a' + (i + 1) + ', b' + i + ']}');
  const model = path.join(work, 'large.yaml');
  fs.writeFileSync(model, lines.join('\n') + '\n');
  const html = path.join(work, 'large.html');
  execFileSync(cli, ['report', model, '-o', html]);
  const size = fs.statSync(html).size;
  check(size < 12 * 1024 * 1024, 'large: the report is ' + size + ' bytes');
  const { page, errors, started } = await openReport(html, 60000);
  if (started) {
    const seen = await page.evaluate(pixels);
    check(seen.ink > 0, 'large: the 3D canvas is blank');
  } else {
    failures.push('large: the viewer did not start: ' + errors.join('; '));
  }
  await page.screenshot({ path: path.join(out, 'large-strip.png') });
  check(errors.length === 0, 'large: console errors: ' + errors.join('; '));
  console.log((errors.length ? 'FAIL ' : 'ok   ') + 'large strip (' + (size / 1048576).toFixed(1) + ' MB)');
  await page.close();
}
await context.close();
fs.rmSync(work, { recursive: true, force: true });
console.log(checks + ' checks, ' + failures.length + ' failed; screenshots in ' + out);
for (const f of failures) console.log('FAILED: ' + f);
process.exit(failures.length ? 1 : 0);
