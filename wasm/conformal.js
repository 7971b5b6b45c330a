/* wasm/conformal.js: the script of docs/interactive/conformal.html.
 * Every number the page shows comes from the library compiled to WebAssembly
 * (wasm/shim.c passes arrays to the public API); this script only draws.
 * window.garotorPage.state() returns what the page computed, for the browser
 * test (tests/page_test.py), which recomputes it with the native library. */
'use strict';
window.onerror = function (m) { document.body.setAttribute('data-error', String(m)); };
(function () {
var t00 = performance.now();
var KIND = ['empty', 'flat point', 'line', 'plane', 'point pair', 'circle', 'sphere'];
var REAL = ['real', 'tangent', 'imaginary'];
var COL = { pair: '#9467bd', line: '#1f77b4', circle: '#2ca02c', plane: '#17becf', sphere: '#ff7f0e',
            S: '#7f7f7f', meet: '#d62728', image: '#e377c2', path: '#333333' };
var DEF = { pts: [[1, 0, 0], [0, 1, 0], [-0.6, -0.5, 0.2], [0.2, 0.1, 1.1], [1.3, 0.9, 0.3]], rho: 1,
            az: 0.8, el: 0.45, zoom: 1.25, versor: 'inversion', vparam: 1, scheme: 0, s: 0.5 };
var st = JSON.parse(JSON.stringify(DEF));
var c = document.getElementById('view'), g = c.getContext('2d');
var M, H, base, R = null, keys = [], times = [], pathPts = [], pathRange = [0, 1], pathStatus = 0;
var timing = { load: 0, script: 0, module: 0, start: t00, last: 0, max: 0, n: 0, times: [] };

/* ---- the library, through wasm/shim.c ---- */
function at(k) { return (base + 40 * k) * 8; }
function put(k, a) { H.set(a, base + 40 * k); }
function get(k, n) { return Array.from(H.subarray(base + 40 * k, base + 40 * k + n)); }
function call(fn, ins, n, extra) { /* ins: arrays into slots 0.., the result from the next slot */
  ins.forEach(function (a, i) { put(i, a); });
  var args = ins.map(function (a, i) { return at(i); });
  if (extra !== undefined) args.push(extra);
  args.push(at(ins.length));
  var s = fn.apply(null, args);
  return { status: typeof s === 'number' ? s : 0, v: get(ins.length, n) };
}
function mv(fn, ins, extra) { return call(fn, ins, 32, extra).v; }
function object(X) { var r = call(M._gw_object, [X], 12); return r.status ? { status: r.status } : {
  status: 0, kind: r.v[0], reality: r.v[1], centre: r.v.slice(2, 5), direction: r.v.slice(5, 8), r2: r.v[8] }; }
function text(X) { put(0, X); var n = M._gw_format(at(0));
  return n < 0 ? statusText(n) : M.UTF8ToString(M._gw_text(), n); }
function statusText(s) { return M.UTF8ToString(M._ga_status_string(s)); }
function apply(V, X) { var r = call(M._gw_versor_apply, [V, X], 32); return r.status ? null : r.v; }

/* the versor of the current choice (docs/versors.md) */
function versor() {
  var q = st.pts[4], p = st.vparam;
  if (st.versor === 'reflection') return mv(M._gw_reflection, [[1, 0, 0]], p);
  if (st.versor === 'inversion') return mv(M._gw_inversion, [q], st.rho);
  if (st.versor === 'dilation') { var r = call(M._gw_dilation, [q], 32, p); return r.status ? null : r.v; }
  if (st.versor === 'screw') { /* T(q) Rz(p) T(-q) T(0.3 p e3): a screw about the vertical through q */
    var T = mv(M._gw_translation, [q]), Rz = mv(M._gw_rotation, [[0, 0, 1]], p);
    var Ti = mv(M._gw_translation, [[-q[0], -q[1], -q[2]]]), Tz = mv(M._gw_translation, [[0, 0, 0.3 * p]]);
    return mv(M._gw_gp, [mv(M._gw_gp, [mv(M._gw_gp, [T, Rz]), Ti]), Tz]);
  }
  return null;
}

/* ---- the scene ---- */
function compute() {
  var P = st.pts, o = {};
  o.pair = mv(M._gw_pointpair, [P[0], P[1]]);
  o.line = mv(M._gw_line, [P[0], P[1]]);
  o.circle = mv(M._gw_circle, [P[0], P[1], P[2]]);
  o.plane = mv(M._gw_plane, [P[0], P[1], P[2]]);
  o.sphere = mv(M._gw_sphere, [P[0], P[1], P[2], P[3]]);
  o.S = mv(M._gw_sphere_dual, [P[4]], st.rho);
  var meets = { 'sphere ∧ S': mv(M._gw_meet, [o.sphere, o.S]), 'line ∧ S': mv(M._gw_meet, [o.line, o.S]),
                'circle ∧ S': mv(M._gw_meet, [o.circle, o.S]) };
  var V = versor(), images = {};
  if (V) ['line', 'circle', 'sphere'].forEach(function (k) { images[k] = apply(V, o[k]); });
  var list = [];
  function add(name, group, colour, X) {
    var e = { name: name, group: group, colour: colour, mv: X };
    e.obj = X ? object(X) : { status: -6 };
    e.text = X ? text(X) : 'not applied';
    list.push(e);
  }
  ['pair', 'line', 'circle', 'plane', 'sphere', 'S'].forEach(function (k) { add(k, 'object', COL[k], o[k]); });
  Object.keys(meets).forEach(function (k) { add(k, 'meet', COL.meet, meets[k]); });
  Object.keys(images).forEach(function (k) { add(st.versor + ' of ' + k, 'image', COL.image, images[k]); });
  return { list: list, versor: V ? text(V) : 'none' };
}

function buildPath() {
  var n = st.scheme === 2 ? 3 : 4; /* quadratic: exactly 3 keys */
  var flat = [];
  for (var i = 0; i < n; i++) flat = flat.concat(keys[i]);
  H.set(times.slice(0, n), base);
  H.set(flat, base + 8);
  pathStatus = M._gw_path_build(st.scheme, n, base * 8, (base + 8) * 8);
  pathPts = [];
  if (pathStatus) return;
  M._gw_path_range(base * 8);
  pathRange = [H[base], H[base + 1]];
  for (var k = 0; k <= 64; k++) {
    var t = pathRange[0] + (pathRange[1] - pathRange[0]) * k / 64;
    if (M._gw_path_eval(t, base * 8) === 0) pathPts.push([H[base + 3], H[base + 7], H[base + 11]]);
  }
}
function poseAt() {
  var t = pathRange[0] + (pathRange[1] - pathRange[0]) * st.s;
  var r = { t: t, status: pathStatus };
  if (pathStatus) return r;
  r.status = M._gw_path_eval(t, base * 8);
  r.pose = Array.from(H.subarray(base, base + 16));
  var s2 = M._gw_path_velocity(t, (base + 16) * 8);
  r.status = r.status || s2;
  r.velocity = Array.from(H.subarray(base + 16, base + 22));
  return r;
}

/* ---- drawing: orthographic, azimuth az about z, elevation el ---- */
function scale() { return 0.16 * Math.min(c.width, c.height) * st.zoom; }
function proj(p) {
  var ca = Math.cos(st.az), sa = Math.sin(st.az), ce = Math.cos(st.el), se = Math.sin(st.el);
  var u = ca * p[0] - sa * p[1], v = sa * p[0] + ca * p[1], w = ce * p[2] - se * v, s = scale();
  return [c.width / 2 + s * u, 0.44 * c.height - s * w];
}
function add3(a, b, k) { return [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]; }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function unit(a) { var n = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / n, a[1] / n, a[2] / n]; }
function perp(nrm) { var a = Math.abs(nrm[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]; var e1 = unit(cross(nrm, a));
  return [e1, cross(unit(nrm), e1)]; }
function stroke(col, wd, dash) { g.strokeStyle = col; g.lineWidth = wd; g.setLineDash(dash || []); }
function poly(ps, close) { g.beginPath(); ps.forEach(function (p, i) { var q = proj(p);
  if (i) g.lineTo(q[0], q[1]); else g.moveTo(q[0], q[1]); }); if (close) g.closePath(); g.stroke(); }
function dot(p, col, r, hollow) { var q = proj(p); g.beginPath(); g.arc(q[0], q[1], r, 0, 7);
  if (hollow) { stroke(col, 2); g.stroke(); } else { g.fillStyle = col; g.fill(); } }
function ring(cen, nrm, rad) { var b = perp(nrm), ps = [];
  for (var i = 0; i < 72; i++) { var a = i * Math.PI / 36;
    ps.push(add3(add3(cen, b[0], rad * Math.cos(a)), b[1], rad * Math.sin(a))); }
  poly(ps, true); }
function drawObject(e) {
  var o = e.obj; if (o.status) return;
  var real = o.reality === 0, tan = o.reality === 1, rad = Math.sqrt(Math.abs(o.r2));
  var wd = e.group === 'meet' ? 3 : 2, dash = real ? [] : [6, 5];
  if (e.group === 'image') dash = real ? [2, 3] : [6, 5];
  stroke(e.colour, wd, dash);
  if (o.kind === 4) { /* point pair */
    if (tan) { dot(o.centre, e.colour, 4); dot(o.centre, e.colour, 8, true); return; }
    var a = add3(o.centre, o.direction, -rad), b = add3(o.centre, o.direction, rad);
    poly([a, b]); dot(a, e.colour, 4, !real); dot(b, e.colour, 4, !real);
  } else if (o.kind === 5) {
    if (tan) { dot(o.centre, e.colour, 4); dot(o.centre, e.colour, 8, true); return; }
    ring(o.centre, o.direction, rad);
  } else if (o.kind === 6) {
    if (tan) { dot(o.centre, e.colour, 4); dot(o.centre, e.colour, 8, true); return; }
    var q = proj(o.centre); g.beginPath(); g.arc(q[0], q[1], rad * scale(), 0, 7); g.stroke();
    if (real) { g.globalAlpha = 0.07; g.fillStyle = e.colour; g.fill(); g.globalAlpha = 1; }
    stroke(e.colour, 1, [3, 4]); ring(o.centre, [0, 0, 1], rad);
  } else if (o.kind === 2) {
    poly([add3(o.centre, o.direction, -6), add3(o.centre, o.direction, 6)]);
  } else if (o.kind === 3) {
    var b2 = perp(o.direction), h = 1.6, ps = [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(function (s) {
      return add3(add3(o.centre, b2[0], h * s[0]), b2[1], h * s[1]); });
    g.globalAlpha = 0.08; g.fillStyle = e.colour; g.beginPath();
    ps.forEach(function (p, i) { var qq = proj(p); if (i) g.lineTo(qq[0], qq[1]); else g.moveTo(qq[0], qq[1]); });
    g.fill(); g.globalAlpha = 1; stroke(e.colour, 1); poly(ps, true);
  } else if (o.kind === 1) dot(o.centre, e.colour, 5);
}
function frameAt(m, len, wd) {
  var o = [m[3], m[7], m[11]];
  ['#d62728', '#2ca02c', '#1f77b4'].forEach(function (col, j) {
    stroke(col, wd); poly([o, add3(o, [m[j], m[4 + j], m[8 + j]], len)]); });
}

var scene = null, pose = null;
function draw() {
  g.setLineDash([]); g.fillStyle = '#fff'; g.fillRect(0, 0, c.width, c.height);
  [[[-3, 0, 0], [3, 0, 0], 'x'], [[0, -3, 0], [0, 3, 0], 'y'], [[0, 0, -2], [0, 0, 2.5], 'z']].forEach(function (a) {
    stroke('#cccccc', 1); poly([a[0], a[1]]); var q = proj(a[1]); g.fillStyle = '#888';
    g.font = '13px sans-serif'; g.fillText(a[2], q[0] + 4, q[1] - 4); });
  if (document.getElementById('show-images').checked)
    scene.list.forEach(function (e) { if (e.group === 'image') drawObject(e); });
  scene.list.forEach(function (e) { if (e.group !== 'image') drawObject(e); });
  st.pts.forEach(function (p, i) { dot(p, i === 4 ? COL.S : '#000', 6); var q = proj(p);
    g.fillStyle = '#000'; g.font = 'bold 13px sans-serif'; g.fillText(i === 4 ? 'Q' : 'P' + i, q[0] + 8, q[1] + 14); });
  /* the motion: path, keys, the pose at the slider and its velocity */
  if (pathPts.length) { stroke(COL.path, 1.5, [4, 3]); poly(pathPts); }
  for (var i = 0; i < (st.scheme === 2 ? 3 : 4); i++) frameAt(keys[i], 0.35, 2);
  if (pose && pose.pose) {
    frameAt(pose.pose, 0.6, 4);
    var m = pose.pose, v = pose.velocity, o = [m[3], m[7], m[11]];
    var wv = [m[0] * v[3] + m[1] * v[4] + m[2] * v[5], m[4] * v[3] + m[5] * v[4] + m[6] * v[5],
              m[8] * v[3] + m[9] * v[4] + m[10] * v[5]];
    stroke('#000', 2); poly([o, add3(o, wv, 0.3)]); dot(add3(o, wv, 0.3), '#000', 3);
  }
}
function fmt(x) { return (Math.abs(x) < 5e-15 ? 0 : x).toPrecision(6).replace(/\.?0+$/, '').replace(/\.?0+e/, 'e'); }
function vec(a) { return '(' + a.map(fmt).join(', ') + ')'; }
var rows = [];
function panel() { /* the table's rows are made once per set of objects, then only their texts change */
  var tb = document.getElementById('objects');
  if (rows.length !== scene.list.length || rows.some(function (r, i) { return r.name !== scene.list[i].name; })) {
    tb.textContent = ''; rows = scene.list.map(function (e) {
      var tr = document.createElement('tr'), r = { name: e.name, td: [] };
      for (var j = 0; j < 4; j++) { var td = document.createElement('td'); tr.appendChild(td); r.td.push(td); }
      r.td[0].innerHTML = '<span class="sw" style="background:' + e.colour + '"></span>';
      r.td[0].appendChild(document.createTextNode(e.name)); r.td[3].className = 'mv';
      tb.appendChild(tr); return r; });
  }
  scene.list.forEach(function (e, i) {
    var o = e.obj, td = rows[i].td;
    td[1].textContent = o.status ? statusText(o.status) : KIND[o.kind] + (o.kind >= 4 ? ', ' + REAL[o.reality] : '');
    td[2].textContent = o.status ? '' : 'centre ' + vec(o.centre) + (o.kind >= 4 ? ', r² ' + fmt(o.r2) : '');
    td[3].textContent = e.text;
  });
  document.getElementById('versor-text').textContent = scene.versor;
  var p = document.getElementById('pose');
  if (!pose || pose.status) p.textContent = 'path: ' + statusText(pathStatus || (pose ? pose.status : -6));
  else { var m = pose.pose, v = pose.velocity;
    p.textContent = 't = ' + fmt(pose.t) + '   position ' + vec([m[3], m[7], m[11]]) +
      '\nbody velocity  ω = ' + vec(v.slice(0, 3)) + '   v = ' + vec(v.slice(3, 6)); }
}
function update() {
  var t0 = performance.now();
  scene = compute(); pose = poseAt(); draw(); panel();
  var dt = performance.now() - t0;
  timing.last = dt; timing.max = Math.max(timing.max, dt); timing.n++;
  if (timing.times.length < 1000) timing.times.push(dt);
}

/* ---- controls ---- */
function syncInputs() {
  st.pts.forEach(function (p, i) { for (var j = 0; j < 3; j++) document.getElementById('p' + i + j).value = fmt(p[j]); });
  document.getElementById('rho').value = st.rho;
  document.getElementById('versor').value = st.versor;
  document.getElementById('vparam').value = st.vparam;
  document.getElementById('scheme').value = st.scheme;
  document.getElementById('tslider').value = Math.round(st.s * 1000);
}
function vparamRange() { var r = { reflection: [-2, 2, 0.01], inversion: [0, 0, 1], dilation: [0.2, 3, 0.01],
  screw: [-3.14, 3.14, 0.01], none: [0, 0, 1] }[st.versor]; var e = document.getElementById('vparam');
  e.min = r[0]; e.max = r[1]; e.step = r[2]; e.disabled = st.versor === 'inversion' || st.versor === 'none';
  document.getElementById('vparam-label').textContent = { reflection: 'plane x =', inversion: '(sphere S)',
    dilation: 'factor', screw: 'angle (rad)', none: '' }[st.versor]; }
function init() {
  var tb = document.getElementById('points');
  st.pts.forEach(function (p, i) {
    var tr = document.createElement('tr'); tr.innerHTML = '<th scope="row">' + (i === 4 ? 'Q' : 'P' + i) + '</th>';
    for (var j = 0; j < 3; j++) { var td = document.createElement('td'), inp = document.createElement('input');
      inp.type = 'number'; inp.step = '0.1'; inp.id = 'p' + i + j; inp.setAttribute('aria-label', (i === 4 ? 'Q' : 'P' + i) + ' ' + 'xyz'[j]);
      inp.oninput = (function (ii, jj) { return function () { var x = parseFloat(this.value);
        if (isFinite(x)) { st.pts[ii][jj] = x; update(); } }; })(i, j);
      td.appendChild(inp); tr.appendChild(td); }
    tb.appendChild(tr); });
  var sel = document.getElementById('scheme');
  for (var k = 0; k < 10; k++) { var op = document.createElement('option'); op.value = k;
    op.textContent = M.UTF8ToString(M._ga_scheme_name(k)); sel.appendChild(op); }
  sel.onchange = function () { st.scheme = +this.value; buildPath(); update(); };
  document.getElementById('tslider').oninput = function () { st.s = this.value / 1000; update(); };
  document.getElementById('rho').oninput = function () { st.rho = +this.value; update(); };
  document.getElementById('versor').onchange = function () { st.versor = this.value;
    st.vparam = { reflection: 0.5, dilation: 1.5, screw: 1, inversion: 1, none: 1 }[st.versor];
    vparamRange(); syncInputs(); update(); };
  document.getElementById('vparam').oninput = function () { st.vparam = +this.value; update(); };
  document.getElementById('show-images').onchange = update;
  document.getElementById('reset').onclick = function () { st = JSON.parse(JSON.stringify(DEF));
    vparamRange(); syncInputs(); buildPath(); update(); };
  /* mouse: drag a point in the view plane, or orbit; wheel: zoom */
  var drag = null;
  c.onmousedown = function (e) { var r = c.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top, best = -1, bd = 12;
    st.pts.forEach(function (p, i) { var q = proj(p), d = Math.hypot(q[0] - x, q[1] - y); if (d < bd) { bd = d; best = i; } });
    drag = { i: best, x: e.clientX, y: e.clientY }; c.style.cursor = best >= 0 ? 'move' : 'grabbing'; e.preventDefault(); };
  window.onmouseup = function () { if (drag && drag.i >= 0) syncInputs(); drag = null; c.style.cursor = 'grab'; };
  window.onmousemove = function (e) { if (!drag) return; var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (drag.i >= 0) { var s = scale(), ca = Math.cos(st.az), sa = Math.sin(st.az), ce = Math.cos(st.el), se = Math.sin(st.el);
      var a = dx / s, b = -dy / s, p = st.pts[drag.i];
      st.pts[drag.i] = [p[0] + a * ca - b * se * sa, p[1] - a * sa - b * se * ca, p[2] + b * ce];
    } else { st.az += 0.01 * dx; st.el = Math.max(-1.55, Math.min(1.55, st.el + 0.01 * dy)); }
    update(); };
  c.onwheel = function (e) { st.zoom = Math.max(0.2, Math.min(8, st.zoom * Math.exp(-0.0015 * e.deltaY)));
    e.preventDefault(); update(); };
  c.onkeydown = function (e) { var k = e.key, used = true;
    if (k === 'ArrowLeft') st.az -= 0.1; else if (k === 'ArrowRight') st.az += 0.1;
    else if (k === 'ArrowUp') st.el = Math.min(1.55, st.el + 0.1); else if (k === 'ArrowDown') st.el = Math.max(-1.55, st.el - 0.1);
    else if (k === '+' || k === '=') st.zoom = Math.min(8, st.zoom * 1.2); else if (k === '-') st.zoom = Math.max(0.2, st.zoom / 1.2);
    else used = false;
    if (used) { e.preventDefault(); update(); } };
  /* the four key poses of the motion: turns about z and a rise */
  times = [0, 1, 2, 3];
  keys = [0, 1, 2, 3].map(function (i) { var a = i * Math.PI / 4, ca = Math.cos(a), sa = Math.sin(a);
    return [ca, -sa, 0, -2.4 + 1.6 * i, sa, ca, 0, -2.4 + 0.5 * i * (3 - i), 0, 0, 1, -2.6 + 0.3 * i, 0, 0, 0, 1]; });
  vparamRange(); syncInputs(); buildPath(); update();
}
var f64 = new Float64Array(1), u32 = new Uint32Array(f64.buffer);
function hx(v) { /* every number as the 16 hex digits of its bits: -0 and the last bit count */
  if (typeof v === 'number') { f64[0] = v;
    return ('0000000' + u32[1].toString(16)).slice(-8) + ('0000000' + u32[0].toString(16)).slice(-8); }
  if (Array.isArray(v)) return v.map(hx);
  if (v && typeof v === 'object') { var o = {}; for (var k in v) o[k] = hx(v[k]); return o; }
  return v;
}
window.garotorPage = {
  stateHex: function () { var s = this.state(); delete s.timing; delete s.view; return JSON.stringify(hx(s)); },
  /* the mean time of each part of a redraw over n runs, in ms */
  profile: function (n) { var r = {}; [['compute', function () { scene = compute(); }], ['pose', function () { pose = poseAt(); }],
    ['draw', draw], ['panel', panel]].forEach(function (f) { var t0 = performance.now();
      for (var i = 0; i < n; i++) f[1](); r[f[0]] = (performance.now() - t0) / n; }); return r; },
  resetTiming: function () { timing.max = 0; timing.n = 0; timing.times = []; },
  state: function () {
    return { points: st.pts, rho: st.rho, versor: st.versor, vparam: st.vparam,
             objects: scene.list.map(function (e) { return { name: e.name, group: e.group, mv: e.mv, obj: e.obj, text: e.text }; }),
             scheme: st.scheme, schemeName: M.UTF8ToString(M._ga_scheme_name(st.scheme)), s: st.s,
             times: times.slice(0, st.scheme === 2 ? 3 : 4), keys: keys.slice(0, st.scheme === 2 ? 3 : 4),
             range: pathRange, pose: pose, timing: timing,
             view: { az: st.az, el: st.el, zoom: st.zoom, width: c.width, height: c.height, scale: scale() } };
  },
  project: function (p) { var q = proj(p), r = c.getBoundingClientRect(); return [q[0] + r.left, q[1] + r.top]; }
};
garotorWasm().then(function (mod) {
  timing.module = performance.now() - t00; /* the module decoded, compiled and instantiated */
  M = mod; H = M.HEAPF64; base = M._gw_scratch() >> 3;
  init();
  timing.load = performance.now(); /* since the navigation began */
  timing.script = performance.now() - t00;
  document.body.setAttribute('data-state', 'ready');
});
})();
