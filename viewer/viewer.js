// SPDX-License-Identifier: BSD-3-Clause
// kinestat report viewer: draws the scene embedded as window.KINESTAT_SCENE with three.js
// (global THREE). Rotate by dragging, zoom with the wheel. window.kinestatViewer gives tests
// and users a small API: setView, setAmplitude, freeze, elementColours, ready, and for traced
// modes setFirstOrder, traced, nodePositions, barLengths.
//
// A framework mode whose finite motion was traced (mode.trace) is animated through the traced
// configurations themselves: the animation's arc length picks the nearest traced point and
// nothing is interpolated between points (a straight line between two configurations shortens
// every turning bar by about (its ends' relative displacement)^2 / (8 length)), so every drawn
// configuration keeps the bar lengths to the trace's closure residual plus the rounding of the
// scene (a quantum of 1e-8 of the shortest moving bar).
(function () {
  'use strict';
  const S = window.KINESTAT_SCENE;
  const api = { ready: false, frames: 0 };
  window.kinestatViewer = api;
  const $ = (id) => document.getElementById(id);
  const text = (tag, content, cls) => {
    const e = document.createElement(tag);
    e.textContent = content;
    if (cls) e.className = cls;
    return e;
  };
  // Dense network modes list motion magnitudes, framework modes coordinates; the modes of a
  // sparse network (the first basis vectors of mode_total) list the couplings that move.
  const movingHeading = () => (S.sparse ? 'Moving couplings: ' : 'Moving coordinates: ');

  // ---- side panel
  $('title').textContent = S.name || 'kinestat report';
  const table = $('summary');
  for (const [key, value] of S.summary) {
    const row = document.createElement('tr');
    row.appendChild(text('td', key));
    row.appendChild(text('td', value));
    table.appendChild(row);
  }
  // Verdict first: what a designer acts on. Without a computed verdict, the classification.
  const verdictBox = $('verdict');
  const fact = (key) => { const f = S.summary.find((x) => x[0] === key); return f ? f[1] : ''; };
  if (S.verdict) {
    const v = S.verdict;
    verdictBox.appendChild(text('p', v.summary, 'verdict-summary'));
    verdictBox.appendChild(text('p', (v.exactly_constrained ? 'exactly constrained' : 'not exactly constrained') + ': ' +
      v.extra_motions + ' extra motion(s), ' + v.redundant_constraints + ' redundant constraint(s)', 'note'));
    const where = (title, list) => {
      if (!list.length) return;
      verdictBox.appendChild(text('p', title + ': ' + list.slice(0, 8).map((p) => p.name + ' (' + Math.round(100 * p.participation) + '%)').join(', ') +
        (list.length > 8 ? ', ...' : ''), 'note'));
    };
    // Every rank decision with its status (exact, certain, close, unproven) and its distance to
    // another rank, as the text report prints them.
    S.summary.filter(([key]) => key.startsWith('rank ')).forEach(([key, value]) =>
      verdictBox.appendChild(text('p', key + ': ' + value, 'note')));
    // The generic answer: what the topology gives and what only this geometry adds.
    (v.special_geometry || []).forEach((sentence) => verdictBox.appendChild(text('p', 'Generic: ' + sentence, 'note')));
    where('Extra motion in', v.motion_participants);
    where('Redundancy in', v.constraint_participants);
    if (v.changes.length) {
      verdictBox.appendChild(text('p', 'Change' + (v.changes_verified ? ' (verified by re-analysis)' : ' (not verified)') + ':', 'verdict-head'));
      const list = document.createElement('ul');
      v.changes.forEach((c) => list.appendChild(text('li', c.action + ' ' + c.target + (c.becomes ? ' \u2192 ' + c.becomes : '') + (c.reason ? ' \u2014 ' + c.reason : ''))));
      verdictBox.appendChild(list);
      if (v.becomes) verdictBox.appendChild(text('p', 'The design becomes: ' + v.becomes, 'note'));
    }
  } else {
    verdictBox.appendChild(text('p', fact('class') || fact('complete decomposition') || S.kind, 'verdict-summary'));
  }
  verdictBox.appendChild(text('p', 'Lengths in ' + S.units + '. Signs as in the text report: modes and self-stresses as the analysis decided them (tension positive).', 'note'));
  const viewSelect = $('mode');
  const views = [{ kind: 'configuration', label: 'configuration' }];
  // Eigenmodes of vibration (issue 38) carry their frequency in the label.
  S.modes.forEach((m, i) => views.push({ kind: 'mode', index: i,
    label: m.label + (m.kind === 'vibration' ? '' : m.trace ? ' (finite motion, traced)' : ' (kinematic)') }));
  S.stresses.forEach((s, i) => views.push({ kind: 'stress', index: i, label: s.label }));
  views.forEach((v, i) => {
    const o = text('option', v.label);
    o.value = String(i);
    viewSelect.appendChild(o);
  });
  if (S.sparse && !S.large && (S.mode_total > S.modes.length || S.stress_total > S.stresses.length))
    $('notes').appendChild(text('p', 'Sparse analysis: the first ' + S.modes.length + ' of ' + S.mode_total + ' mode(s) and the first ' +
      S.stresses.length + ' of ' + S.stress_total + ' self-stress(es) are shown, as basis vectors of the sparse QR.', 'note'));
  if (S.large) $('notes').appendChild(text('p', 'Large model (' + S.elements.count + ' elements): drawn as one line set, without glyphs, labels or modes.', 'note'));
  if (S.kind === 'structure') $('notes').appendChild(text('p', 'A structure model has no geometry: bodies are placed on a circle (the frame black, at the bottom), pairs drawn as bars, bodies coloured by structural group.', 'note'));
  else if (!S.large && S.modes.length === 0 && S.stresses.length === 0) $('notes').appendChild(text('p', 'No kinematic modes and no self-stress states to show.', 'note'));

  // ---- three.js scene
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ canvas: $('view'), antialias: true, preserveDrawingBuffer: true });
  } catch (error) {
    $('message').textContent = 'WebGL is not available in this browser: ' + error.message;
    return;
  }
  renderer.setPixelRatio(1);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.AmbientLight(0xffffff, 0.7));
  const sun = new THREE.DirectionalLight(0xffffff, 0.8);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e7);
  camera.up.set(0, 0, 1);

  const P = S.nodes.position;
  const n = P.length / 3;
  const base = (i) => new THREE.Vector3(P[3 * i], P[3 * i + 1], P[3 * i + 2]);
  const box = new THREE.Box3();
  for (let i = 0; i < n; i++) box.expandByPoint(base(i));
  if (n === 0) box.expandByPoint(new THREE.Vector3());
  const centre = box.getCenter(new THREE.Vector3());
  // All points at one place (e.g. a spherical linkage whose axes meet at its centre): draw at
  // unit scale so joint glyphs and screw axes are visible.
  const extent = box.getSize(new THREE.Vector3()).length();
  const size = extent > 0 ? extent : 1;
  const E = S.elements.pairs;
  const m = E.length / 2;
  const light = S.large || m > 2000 || n > 2000;
  const radius = size * 0.008;

  const grey = new THREE.Color(0x444444);
  // Float64: traced positions keep bar lengths to 1e-8, beyond single precision.
  const current = new Float64Array(3 * n);
  current.set(P);
  // Rigid bodies as thick light bars, flexures (beams) as thin dark rods, trusses in between.
  const types = S.elements.type || [];
  const baseColour = (e) => new THREE.Color(types[e] === 'rigid' ? 0x9fb3c8 : types[e] === 'beam' ? 0x222222 : types[e] === 'link' ? 0x555555 : 0x444444);
  const baseRadius = (e) => radius * (types[e] === 'rigid' ? 2.4 : types[e] === 'beam' ? 0.8 : 1);
  const colours = [];
  for (let e = 0; e < m; e++) colours.push(baseColour(e));

  // Elements: cylinders for ordinary models, one line set for large ones.
  let lineSet = null;
  const bars = [];
  const yAxis = new THREE.Vector3(0, 1, 0);
  if (light) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6 * m), 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(6 * m), 3));
    lineSet = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true }));
    scene.add(lineSet);
  } else {
    const cylinder = new THREE.CylinderGeometry(1, 1, 1, 12);
    for (let e = 0; e < m; e++) {
      const mesh = new THREE.Mesh(cylinder, new THREE.MeshLambertMaterial({ color: grey }));
      scene.add(mesh);
      bars.push(mesh);
    }
  }
  const spheres = [];
  if (!light) {
    const ball = new THREE.SphereGeometry(radius * 1.8, 16, 12);
    const groupBall = new THREE.SphereGeometry(radius * 4, 16, 12);
    for (let i = 0; i < n; i++) {
      const fixed = S.nodes.fixed[i];
      // Structures: bodies coloured by structural group, as in the SVG drawings.
      const palette = [0xa6cee3, 0xb2df8a, 0xfdbf6f, 0xcab2d6, 0xfb9a99, 0xffff99, 0xd9d9d9];
      const group = S.kind === 'structure' && S.group_of ? S.group_of[i] : 0;
      const colour = fixed ? 0x222222 : (group > 0 ? palette[(group - 1) % palette.length] : 0xf0f0f0);
      const mesh = new THREE.Mesh(group > 0 ? groupBall : ball, new THREE.MeshLambertMaterial({ color: colour }));
      scene.add(mesh);
      spheres.push(mesh);
    }
  }
  // Coupling glyphs (networks): a box at the point and the joint axis.
  const glyphs = [];
  const glyphGroup = new THREE.Group();
  scene.add(glyphGroup);
  const lineBetween = (a, b, colour) => {
    const g = new THREE.BufferGeometry().setFromPoints([a, b]);
    return new THREE.Line(g, new THREE.LineBasicMaterial({ color: colour }));
  };
  if (!light) {
    S.glyphs.forEach((g, k) => {
      const group = new THREE.Group();
      const cube = new THREE.Mesh(new THREE.BoxGeometry(radius * 5, radius * 5, radius * 5),
                                  new THREE.MeshLambertMaterial({ color: 0x1b7837 }));
      group.add(cube);
      const axis = g.axis || g.normal;
      if (axis) {
        const d = new THREE.Vector3(axis[0], axis[1], axis[2]).normalize().multiplyScalar(size * 0.12);
        group.add(lineBetween(d.clone().negate(), d, 0x1b7837));
      }
      group.position.set(g.point[0], g.point[1], g.point[2]);
      glyphGroup.add(group);
      glyphs.push({ group: group, node: S.bodies.length + 2 * k + 1 });
    });
  }

  // Screw axes of unit motions: rotations as lines along the axis, translations as arrows.
  const full = (screw) => {
    if (screw.length === 6) return screw;
    const out = [0, 0, 0, 0, 0, 0];
    S.screw_components.forEach((c, i) => { out[c] = screw[i]; });
    return out;
  };
  const screwObject = (screw, colour, at) => {
    const s = full(screw);
    const w = new THREE.Vector3(s[0], s[1], s[2]);
    const v = new THREE.Vector3(s[3], s[4], s[5]);
    if (w.length() > 1e-12) {
      const p = new THREE.Vector3().crossVectors(w, v).divideScalar(w.lengthSq());
      const d = w.clone().normalize().multiplyScalar(size * 0.25);
      return lineBetween(p.clone().sub(d), p.clone().add(d), colour);
    }
    if (v.length() < 1e-12) return new THREE.Group();
    return new THREE.ArrowHelper(v.clone().normalize(), at, size * 0.15, colour);
  };
  const screwGroup = new THREE.Group();
  scene.add(screwGroup);
  const pairGroup = new THREE.Group();
  scene.add(pairGroup);
  if (S.kind === 'network' && !light) {
    $('network').style.display = '';
    S.glyphs.forEach((g) => {
      const at = new THREE.Vector3(g.point[0], g.point[1], g.point[2]);
      g.motions.forEach((s) => screwGroup.add(screwObject(s, 0xe66101, at)));
    });
    screwGroup.visible = false;
    $('screws').addEventListener('change', () => { screwGroup.visible = $('screws').checked; });
    const pairSelect = $('pair');
    pairSelect.appendChild(text('option', '(none)'));
    S.pairs.forEach((p, i) => {
      const o = text('option', 'bodies ' + S.bodies[p.i] + ', ' + S.bodies[p.j] + ': fij = ' + p.fij);
      o.value = String(i);
      pairSelect.appendChild(o);
    });
    pairSelect.addEventListener('change', () => {
      pairGroup.clear();
      const p = S.pairs[Number(pairSelect.value)];
      $('pairinfo').textContent = '';
      if (!p) return;
      const at = base(p.j);
      p.motions.forEach((s) => pairGroup.add(screwObject(s, 0x7b3294, at)));
      $('pairinfo').textContent = 'Motion system of body ' + S.bodies[p.j] + ' relative to ' + S.bodies[p.i] + ': ' +
        p.motions.length + ' screw(s) shown (purple), rank fij = ' + p.fij + '.';
    });
  }

  // Sheets (leaf springs): a light quadrilateral along each, following its nodes.
  const sheetMeshes = [];
  if (!light) {
    (S.elements.sheets || []).forEach((sh) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(12), 3));
      g.setIndex([0, 1, 2, 0, 2, 3]);
      const mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ color: 0xe8d9b5, side: THREE.DoubleSide, transparent: true, opacity: 0.75 }));
      scene.add(mesh);
      sheetMeshes.push({ mesh, e: sh.element, across: new THREE.Vector3(sh.across[0], sh.across[1], sh.across[2]) });
    });
  }
  // The undeformed shape in light grey, shown under every mode.
  const ghost = (() => {
    const g = new THREE.BufferGeometry();
    const p = new Float32Array(6 * m);
    for (let e = 0; e < m; e++) for (let k = 0; k < 3; k++) { p[6 * e + k] = P[3 * E[2 * e] + k]; p[6 * e + 3 + k] = P[3 * E[2 * e + 1] + k]; }
    g.setAttribute('position', new THREE.BufferAttribute(p, 3));
    return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0xb0b0b0 }));
  })();
  ghost.visible = false;
  scene.add(ghost);
  // Screw axes: a rod along the axis with an arrow (force or ω), or an arrow for a pure
  // couple / translation; used for coupling wrenches and body twists.
  const wrenchGroup = new THREE.Group(), twistGroup = new THREE.Group();
  scene.add(wrenchGroup);
  scene.add(twistGroup);
  const rodGeometry = new THREE.CylinderGeometry(1, 1, 1, 8);
  const screwAxis = (w, colour) => {
    const g = new THREE.Group();
    const d = new THREE.Vector3(w.direction[0], w.direction[1], w.direction[2]).normalize();
    if (w.pure) {
      const at = new THREE.Vector3(w.anchor[0], w.anchor[1], w.anchor[2]);
      g.add(new THREE.ArrowHelper(d, at, size * 0.2, colour, size * 0.05, size * 0.03));
      return g;
    }
    const p = new THREE.Vector3(w.point[0], w.point[1], w.point[2]);
    const rod = new THREE.Mesh(rodGeometry, new THREE.MeshLambertMaterial({ color: colour }));
    rod.position.copy(p);
    rod.quaternion.setFromUnitVectors(yAxis, d);
    rod.scale.set(radius * 0.7, size * 0.6, radius * 0.7);
    g.add(rod);
    g.add(new THREE.ArrowHelper(d, p.clone().addScaledVector(d, size * 0.2), size * 0.12, colour, size * 0.05, size * 0.03));
    return g;
  };
  // Supports (frameworks): fixed a block, pinned a cone, roller a cone with arrows along the
  // free directions; placed below the node (against z in space, y in the plane).
  const down = S.dimension === 2 ? new THREE.Vector3(0, -1, 0) : new THREE.Vector3(0, 0, -1);
  (S.supports || []).forEach((sp) => {
    if (light) return;
    const at = base(sp.node);
    const h = radius * 3.5;
    const mesh = sp.kind === 'fixed'
      ? new THREE.Mesh(new THREE.BoxGeometry(h * 1.6, h * 1.6, h * 1.6), new THREE.MeshLambertMaterial({ color: 0x555555 }))
      : new THREE.Mesh(new THREE.ConeGeometry(h * 0.7, h, 4), new THREE.MeshLambertMaterial({ color: sp.kind === 'roller' ? 0x9e9e9e : 0x555555 }));
    mesh.position.copy(at).addScaledVector(down, h * 0.8);
    mesh.quaternion.setFromUnitVectors(yAxis, down.clone().negate());
    scene.add(mesh);
    (sp.free || []).forEach((f) => {
      const d = new THREE.Vector3(f[0], f[1], f[2]);
      const c = at.clone().addScaledVector(down, h * 1.8);
      scene.add(new THREE.ArrowHelper(d, c, h * 2, 0x222222, h * 0.6, h * 0.4));
      scene.add(new THREE.ArrowHelper(d.clone().negate(), c, h * 2, 0x222222, h * 0.6, h * 0.4));
    });
  });
  // Axes of a round length at the corner of the model: x red, y green, z blue.
  const roundLength = (t) => { const dec = Math.pow(10, Math.floor(Math.log10(t))); for (const s of [1, 2, 5]) if (s * dec >= 0.75 * t) return s * dec; return 10 * dec; };
  const axisLength = roundLength(size * 0.15);
  const corner = box.min.clone().addScaledVector(new THREE.Vector3(1, 1, S.dimension === 2 ? 0 : 1), -size * 0.08);
  [[1, 0, 0, 0xd62728], [0, 1, 0, 0x2ca02c], [0, 0, 1, 0x1f77b4]].forEach(([x, y, z, c], k) => {
    if (S.dimension === 2 && k === 2) return;
    scene.add(new THREE.ArrowHelper(new THREE.Vector3(x, y, z), corner, axisLength, c, axisLength * 0.2, axisLength * 0.1));
  });
  $('scale').textContent = 'axes x red, y green' + (S.dimension === 2 ? '' : ', z blue') + ': each ' + axisLength + ' ' + S.units + ' long';
  // Labels: nodes (bodies for networks), elements once each, couplings; HTML text over the canvas.
  const labelLayer = $('labelLayer');
  const labels = [];
  const addLabel = (content, where, cls) => {
    const e = text('div', content, 'label ' + cls);
    labelLayer.appendChild(e);
    labels.push({ e, where });
  };
  if (!light) {
    const nodeCount = S.kind === 'network' ? S.bodies.length : n;
    for (let i = 0; i < nodeCount && i < 400; i++) addLabel(S.nodes.name[i] || '', () => new THREE.Vector3(current[3 * i], current[3 * i + 1], current[3 * i + 2]), 'node');
    if (S.kind !== 'network')
      for (let e = 0; e < m && e < 400; e++)
        if (!S.elements.label || S.elements.label[e]) addLabel(S.elements.name[e] || '', () => {
          const a = E[2 * e], b = E[2 * e + 1];
          return new THREE.Vector3((current[3 * a] + current[3 * b]) / 2, (current[3 * a + 1] + current[3 * b + 1]) / 2, (current[3 * a + 2] + current[3 * b + 2]) / 2);
        }, 'element');
    S.glyphs.forEach((g) => addLabel(g.name + ' (' + g.type + ')', () => new THREE.Vector3(g.point[0], g.point[1], g.point[2]), 'coupling'));
  }
  labelLayer.style.display = 'none';
  $('labels').addEventListener('change', () => { labelLayer.style.display = $('labels').checked ? '' : 'none'; });
  const placeLabels = () => {
    if (labelLayer.style.display === 'none') return;
    const w = canvas.clientWidth, h = canvas.clientHeight;
    // Labels that land on one spot (couplings at one point) are stacked 13 px apart.
    const taken = new Map();
    labels.forEach((l) => {
      const v = l.where().project(camera);
      const x = (v.x + 1) / 2 * w, y = (1 - v.y) / 2 * h;
      const key = Math.round(x / 8) + ',' + Math.round(y / 8);
      const k = taken.get(key) || 0;
      taken.set(key, k + 1);
      l.e.style.left = x.toFixed(1) + 'px';
      l.e.style.top = (y + 13 * k).toFixed(1) + 'px';
    });
  };

  // ---- view state
  const state = { view: 0, amplitude: 0.5, frozen: null, start: performance.now(), largest: 0, firstOrder: false, point: -1 };
  // The traced path of a mode shown as traced, or null (first order).
  const tracedPath = (v) => (v.kind === 'mode' && !state.firstOrder && S.modes[v.index].trace) || null;
  // The traced point at animation phase `phase`: the arc length amplitude × sin(phase) of the
  // traced arc of the side it falls on (a side traced short is as far as it goes; a side with
  // no point beyond the start mirrors the other), then the nearest traced point.
  const tracedPoint = (t, phase) => {
    const a = t.arc, last = a.length - 1;
    let s = state.amplitude * Math.sin(phase);
    const forward = a[last], backward = -a[0];
    if (s < 0 && backward <= 0) s = -s;
    if (s > 0 && forward <= 0) s = -s;
    const target = s >= 0 ? s * forward : s * backward;
    let best = t.start;
    for (let k = 0; k <= last; k++) if (Math.abs(a[k] - target) < Math.abs(a[best] - target)) best = k;
    return best;
  };
  const velocityScale = (mode) => {
    let largest = 0;
    for (let i = 0; i < n; i++)
      largest = Math.max(largest, Math.hypot(mode.velocity[3 * i], mode.velocity[3 * i + 1], mode.velocity[3 * i + 2]));
    return largest > 0 ? size * 0.25 / largest : 0;
  };
  const red = new THREE.Color(0xc0392b), blue = new THREE.Color(0x2166ac), light_grey = new THREE.Color(0xdddddd);
  const purple = new THREE.Color(0x7b3294), green = new THREE.Color(0x1b9e77), brown = new THREE.Color(0x8c510a);
  const row = (cells, head) => {
    const r = document.createElement('tr');
    cells.forEach((c) => r.appendChild(text(head ? 'th' : 'td', String(c))));
    return r;
  };
  // The over-constraint as SPACAR users read it: element x deformation of the resultants.
  const resultantTable = (st) => {
    if (!st.resultants || !st.resultants.length) return;
    const columns = [...new Set(st.resultants.map((r) => r[1]))];
    const rows = [...new Set(st.resultants.map((r) => r[0]))];
    const table = document.createElement('table');
    table.className = 'resultants';
    table.appendChild(row(['element'].concat(columns), true));
    rows.forEach((el) => table.appendChild(row([el].concat(columns.map((c) => {
      const r = st.resultants.find((x) => x[0] === el && x[1] === c);
      return r ? (st.unit ? r[2].toPrecision(4) : r[2].toFixed(3)) : '';
    })))));
    $('resultants').appendChild(text('h2', st.unit ? 'Resultants of the misfit stress (per element)' : 'Resultants (element \u00d7 deformation)'));
    $('resultants').appendChild(table);
  };
  const applyColours = () => {
    const v = views[state.view];
    const legend = $('legend');
    legend.textContent = '';
    for (let e = 0; e < m; e++) colours[e].copy(baseColour(e));
    wrenchGroup.clear();
    twistGroup.clear();
    ghost.visible = v.kind === 'mode';
    $('moving').textContent = '';
    $('motion').textContent = '';
    $('firstOrderBox').style.display = 'none';
    $('resultants').textContent = '';
    if (v.kind === 'stress') {
      const st = S.stresses[v.index];
      const values = st.value;
      const kinds = st.kind || [];
      let largest = 0;
      for (const x of values) largest = Math.max(largest, Math.abs(x));
      state.largest = largest;
      const seen = new Set();
      for (let e = 0; e < m; e++) {
        const x = values[e] || 0;
        const t = largest > 0 ? Math.abs(x) / largest : 0;
        const kind = kinds[e] || 'elongation';
        if (x !== 0) seen.add(kind);
        const hue = kind === 'bending' ? purple : kind === 'torsion' ? green : kind === 'rigid' ? brown : (x > 0 ? red : blue);
        colours[e].copy(light_grey).lerp(hue, t);
      }
      if (st.wrenches && st.wrenches.length) {
        st.wrenches.forEach((w) => wrenchGroup.add(screwAxis(w, 0x7b3294)));
        state.largest = Math.max(...st.wrenches.map((w) => w.magnitude));
        legend.textContent = st.label + ': purple lines are the lines of action of the wrench each coupling transmits, the arrow the force for the primary = +1 (sign as in the text report); largest |F| = ' + state.largest.toPrecision(4);
        const table = document.createElement('table');
        table.appendChild(row(['coupling', '|F| or |M|', 'pitch']));
        st.wrenches.forEach((w) => table.appendChild(row([w.name, (w.pure ? 'couple ' : '') + w.magnitude.toPrecision(4), w.pure ? '\u221e' : w.pitch.toPrecision(4)])));
        $('resultants').appendChild(text('h2', 'Wrench of each coupling'));
        $('resultants').appendChild(table);
      } else {
        const kindsShown = [];
        if (seen.has('elongation')) {
          legend.appendChild(text('span', 'elongation: compression '));
          legend.appendChild(text('span', '', 'bar'));
          legend.appendChild(text('span', ' tension (tension positive)'));
        }
        if (seen.has('bending')) kindsShown.push('bending purple');
        if (seen.has('torsion')) kindsShown.push('torsion green');
        if (seen.has('rigid')) kindsShown.push('rigid-body constraint brown');
        legend.appendChild(text('span', (seen.has('elongation') && kindsShown.length ? '; ' : '') + kindsShown.join('; ') +
          '. ' + st.label + (st.unit
            ? ': each element by its peak stress, shade by magnitude; largest = ' + largest.toPrecision(4) + ' ' + st.unit
            : ': each element by its dominant resultant, shade by magnitude; largest = ' + largest.toPrecision(4) + ' (unit-norm stress state)')));
        resultantTable(st);
      }
    } else if (v.kind === 'mode') {
      const mode = S.modes[v.index];
      (mode.twists || []).forEach((t) => twistGroup.add(screwAxis(t, 0xe66101)));
      if (mode.moving && mode.moving.length) $('moving').appendChild(text('p', movingHeading() + mode.moving.join(', '), 'note'));
      $('firstOrderBox').style.display = mode.trace ? '' : 'none';
      const t = tracedPath(v);
      if (mode.trace) {
        $('motion').appendChild(text('p', 'finite motion, traced (max residual ' + mode.trace.max_residual.toPrecision(3) + ' of the characteristic length)' +
          (state.firstOrder ? ': shown to first order instead' : ''), 'note traced'));
        if (mode.trace.note) $('motion').appendChild(text('p', mode.trace.note, 'note'));
      } else if (mode.first_order) {
        $('motion').appendChild(text('p', 'first order only: ' + mode.first_order, 'note first-order'));
      }
      if (t && t.nodes.length === 0) {
        legend.textContent = mode.label + ': finite motion, traced, that moves no drawn point (only rotations of node triads)';
      } else if (t) {
        const a = t.arc;
        legend.textContent = mode.label + ': finite motion through ' + a.length + ' traced configurations; amplitude ' + state.amplitude.toFixed(2) +
          ' of the traced arc length (' + a[a.length - 1].toPrecision(3) + ' forward, ' + (-a[0]).toPrecision(3) + ' backward, ' + S.units + ')';
      } else {
        legend.textContent = velocityScale(S.modes[v.index]) === 0
          ? S.modes[v.index].label + ': moves no drawn point (only rotations, or rotation about an axis through every point of the moving bodies)'
          : S.modes[v.index].label + ': first order, amplitude ' + state.amplitude.toFixed(2) + ' (largest displacement ' +
            (state.amplitude * 25).toFixed(0) + '% of the model size)';
      }
    } else {
      legend.textContent = 'drag to rotate, wheel to zoom';
      const lines = S.modes.filter((md) => md.moving && md.moving.length).map((md) => md.label + ' moves ' + md.moving.join(', '));
      if (lines.length) $('moving').appendChild(text('p', movingHeading() + lines.join('; '), 'note'));
    }
    if (lineSet) {
      const c = lineSet.geometry.attributes.color.array;
      for (let e = 0; e < m; e++) for (let k = 0; k < 2; k++) colours[e].toArray(c, 6 * e + 3 * k);
      lineSet.geometry.attributes.color.needsUpdate = true;
    } else {
      bars.forEach((bar, e) => bar.material.color.copy(colours[e]));
    }
  };
  const place = (phase) => {
    const v = views[state.view];
    current.set(P);
    const t = tracedPath(v);
    state.point = -1;
    if (t) {
      const point = tracedPoint(t, phase);
      state.point = point;
      const offsets = t.offsets[point], q = t.quantum;
      t.nodes.forEach((i, j) => { for (let k = 0; k < 3; k++) current[3 * i + k] = P[3 * i + k] + q * offsets[3 * j + k]; });
    } else if (v.kind === 'mode') {
      const mode = S.modes[v.index];
      const k = velocityScale(mode) * state.amplitude * Math.sin(phase);
      for (let i = 0; i < 3 * n; i++) current[i] += k * mode.velocity[i];
    }
    const at = (i) => new THREE.Vector3(current[3 * i], current[3 * i + 1], current[3 * i + 2]);
    if (lineSet) {
      const p = lineSet.geometry.attributes.position.array;
      for (let e = 0; e < m; e++) {
        const a = E[2 * e], b = E[2 * e + 1];
        for (let k = 0; k < 3; k++) { p[6 * e + k] = current[3 * a + k]; p[6 * e + 3 + k] = current[3 * b + k]; }
      }
      lineSet.geometry.attributes.position.needsUpdate = true;
      lineSet.geometry.computeBoundingSphere();
    }
    bars.forEach((bar, e) => {
      const a = at(E[2 * e]), b = at(E[2 * e + 1]);
      const d = b.clone().sub(a);
      const length = Math.max(d.length(), 1e-12);
      bar.position.copy(a).add(b).multiplyScalar(0.5);
      bar.quaternion.setFromUnitVectors(yAxis, d.divideScalar(length));
      bar.scale.set(baseRadius(e), length, baseRadius(e));
    });
    spheres.forEach((s, i) => s.position.copy(at(i)));
    sheetMeshes.forEach((sh) => {
      const a = at(E[2 * sh.e]), b = at(E[2 * sh.e + 1]);
      const half = sh.across.clone().multiplyScalar(0.5 * S.elements.sheet_width * a.distanceTo(b));
      const p = sh.mesh.geometry.attributes.position;
      [a.clone().add(half), b.clone().add(half), b.clone().sub(half), a.clone().sub(half)].forEach((v, k) => p.setXYZ(k, v.x, v.y, v.z));
      p.needsUpdate = true;
      sh.mesh.geometry.computeVertexNormals();
      sh.mesh.geometry.computeBoundingSphere();
    });
    glyphs.forEach((g) => g.group.position.copy(at(g.node)));
  };

  // ---- camera: orbit around the centre
  const orbit = { azimuth: S.dimension === 2 ? -Math.PI / 2 : -Math.PI / 3, elevation: S.dimension === 2 ? 1.5 : 0.45, distance: size * 2.4 };
  const placeCamera = () => {
    const c = Math.cos(orbit.elevation);
    camera.position.set(centre.x + orbit.distance * c * Math.cos(orbit.azimuth),
                        centre.y + orbit.distance * c * Math.sin(orbit.azimuth),
                        centre.z + orbit.distance * Math.sin(orbit.elevation));
    camera.lookAt(centre);
    sun.position.copy(camera.position);
  };
  const canvas = $('view');
  let drag = null;
  canvas.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY }; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener('pointerup', () => { drag = null; });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    orbit.azimuth -= (e.clientX - drag.x) * 0.01;
    orbit.elevation = Math.max(-1.55, Math.min(1.55, orbit.elevation + (e.clientY - drag.y) * 0.01));
    drag = { x: e.clientX, y: e.clientY };
  });
  canvas.addEventListener('wheel', (e) => { e.preventDefault(); orbit.distance *= Math.exp(e.deltaY * 0.001); }, { passive: false });

  const resize = () => {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    if (canvas.width !== w || canvas.height !== h) {
      renderer.setSize(w, h, false);
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
    }
  };
  const frame = () => {
    resize();
    const phase = state.frozen !== null ? state.frozen : (performance.now() - state.start) / 1000 * Math.PI;
    place(phase);
    placeCamera();
    renderer.render(scene, camera);
    placeLabels();
    api.frames++;
    requestAnimationFrame(frame);
  };

  viewSelect.addEventListener('change', () => { state.view = Number(viewSelect.value); applyColours(); });
  const slider = $('amplitude');
  slider.addEventListener('input', () => { state.amplitude = Number(slider.value); applyColours(); });

  api.views = views.map((v) => v.label);
  api.setView = (i) => { viewSelect.value = String(i); viewSelect.dispatchEvent(new Event('change')); };
  api.setAmplitude = (a) => { slider.value = String(a); slider.dispatchEvent(new Event('input')); };
  api.freeze = (phase) => { state.frozen = phase; };
  // A traced mode moves a drawn point when some node moves along its trace (a mode that only
  // turns beam ends moves none).
  api.modeMoves = (i) => (S.modes[i].trace ? S.modes[i].trace.nodes.length > 0 : velocityScale(S.modes[i]) > 0);
  const firstOrderBox = $('firstorder');
  firstOrderBox.addEventListener('change', () => { state.firstOrder = firstOrderBox.checked; applyColours(); });
  // Traced modes: show the first-order animation instead (true) or the traced one (false).
  api.setFirstOrder = (on) => { firstOrderBox.checked = on; firstOrderBox.dispatchEvent(new Event('change')); };
  api.traced = (i) => !!S.modes[i].trace;
  // The traced point last drawn (index into the mode's trace), or -1 for a first-order picture.
  api.tracedPoint = () => state.point;
  // Node positions as drawn (the spheres of the 3D scene; the position buffer for line sets).
  api.nodePositions = () => spheres.length ? spheres.map((s) => [s.position.x, s.position.y, s.position.z])
    : Array.from({ length: n }, (_, i) => [current[3 * i], current[3 * i + 1], current[3 * i + 2]]);
  // The drawn length of every element (the cylinders' lengths), or null for line sets.
  api.barLengths = () => bars.length ? bars.map((b) => b.scale.y) : null;
  api.elementColours = () => colours.map((c) => '#' + c.getHexString());
  api.setLabels = (on) => { $('labels').checked = on; $('labels').dispatchEvent(new Event('change')); placeLabels(); };
  api.labelsShown = () => labelLayer.style.display !== 'none' ? labels.length : 0;
  api.ghostShown = () => ghost.visible;
  api.stressRange = () => state.largest;
  api.wrenchCount = () => wrenchGroup.children.length;
  api.twistCount = () => twistGroup.children.length;
  api.render = () => { place(state.frozen !== null ? state.frozen : 0); placeCamera(); renderer.render(scene, camera); placeLabels(); };
  applyColours();
  placeCamera();
  requestAnimationFrame(frame);
  api.ready = true;
})();
