// drycut report: the interactive 3D view of the tool-centre trace (embedded into the binary at
// build time and inlined into each report after three.js and its OrbitControls).
//
// Data: the JSON script element with id trace-data (format in html_trace_viewer.hpp).
// Scene: the trace is shifted so the centre of the framed box is the origin (float32 positions
// keep micrometres); Z is up. Cutting moves are line segments coloured by the velocity bin of their
// end sample (the top view's colours), rapids grey dashed segments, the worst dips red balls
// with their rank as a label, the tool a cone whose tip is the tool centre.
// Playback: the position is a sample index (the slider's value); playing advances the time by
// the wall-clock time × speed and shows the last sample at or before it.
// Self-test (location hash contains "selftest"; used by the browser test): renders once, reads
// the pixels back (preserveDrawingBuffer) and checks that pixels at projected path samples are
// painted while pixels away from the path are background, then moves the playback bar from the
// first to the last sample and checks that the shown block changes (and that shift + left arrow
// goes back a block); the verdict is written into the pre element with id trace-selftest, which
// `chromium --dump-dom` prints. Then it plays from the start at the highest speed and writes
// where the playback got to into the pre element trace-selftest-playback.
(function () {
  'use strict';
  var root = document.getElementById('trace-viewer');
  var dataNode = document.getElementById('trace-data');
  if (!root || !dataNode) return;
  var $ = function (id) { return document.getElementById(id); };
  var status = $('trace-status');
  if (typeof THREE === 'undefined' || !THREE.OrbitControls) {
    status.textContent = 'three.js did not load: no 3D view. The top view below shows the path.';
    return;
  }
  var D = JSON.parse(dataNode.textContent);
  var n = Math.floor(D.p.length / 7);
  var X = new Float64Array(n), Y = new Float64Array(n), Z = new Float64Array(n);
  var T = new Float64Array(n), V = new Float64Array(n), B = new Int32Array(n), R = new Uint8Array(n);
  for (var i = 0; i < n; ++i) {
    var k = 7 * i;
    X[i] = D.p[k]; Y[i] = D.p[k + 1]; Z[i] = D.p[k + 2]; T[i] = D.p[k + 3];
    V[i] = D.p[k + 4]; B[i] = D.p[k + 5]; R[i] = D.p[k + 6];
  }

  // The framed box: per axis the 5th to 95th percentile of the kept samples in motion. They are
  // about evenly spread in time (the decimator keeps two per stretch of equal sample count), so
  // this is where the tool spends 90 % of its moving time: the part, not a long approach,
  // retract or a standstill at the tool change position. `size` scales the markers, the camera
  // distance and the dashes.
  var moving = [];
  for (i = 0; i < n; ++i) if (V[i] > 0) moving.push(i);
  if (moving.length < 2) moving = Array.from({ length: n }, function (_, j) { return j; });
  var lo = [], hi = [];
  [X, Y, Z].forEach(function (axis) {
    var sorted = moving.map(function (j) { return axis[j]; }).sort(function (u, w) { return u - w; });
    lo.push(sorted[Math.floor(0.05 * (sorted.length - 1))]);
    hi.push(sorted[Math.ceil(0.95 * (sorted.length - 1))]);
  });
  var centre = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
  var size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-3);
  function local(j) { return new THREE.Vector3(X[j] - centre[0], Y[j] - centre[1], Z[j] - centre[2]); }

  var canvas = $('trace-canvas');
  var renderer;
  try {
    renderer = new THREE.WebGLRenderer({ canvas: canvas, antialias: true, preserveDrawingBuffer: true });
  } catch (e) {
    status.textContent = 'WebGL is not available in this browser: no 3D view. The top view below shows the path.';
    return;
  }
  var W = canvas.width, H = canvas.height;
  renderer.setPixelRatio(window.devicePixelRatio || 1);  // sharp on high-density screens
  renderer.setSize(W, H);
  renderer.setClearColor(0xffffff, 1);
  var scene = new THREE.Scene();
  var camera = new THREE.PerspectiveCamera(40, W / H, size / 2000, size * 200);
  camera.up.set(0, 0, 1);
  var controls = new THREE.OrbitControls(camera, canvas);
  controls.enableKeys = false;  // the arrow keys step the playback
  controls.screenSpacePanning = true;

  // Velocity colour of a sample: the top view's bins (colour_bin in svg_colour_map.cpp).
  var palette = D.colours.map(function (c) { return new THREE.Color(c); });
  function binColour(v) {
    var f = D.scale > 0 ? v / D.scale : 0;
    var bin = !(f > 0) ? 0 : f >= 1 ? palette.length - 1 : Math.min(palette.length - 1, Math.floor(f * palette.length));
    return palette[bin];
  }

  // Segment j-1 -> j belongs to sample j: its block, its rapid flag, its velocity colour.
  var cutPos = [], cutCol = [], rapidPos = [];
  for (i = 1; i < n; ++i) {
    var p0 = local(i - 1), p1 = local(i);
    if (R[i]) {
      rapidPos.push(p0.x, p0.y, p0.z, p1.x, p1.y, p1.z);
    } else {
      var c = binColour(V[i]);
      cutPos.push(p0.x, p0.y, p0.z, p1.x, p1.y, p1.z);
      cutCol.push(c.r, c.g, c.b, c.r, c.g, c.b);
    }
  }
  // Fat lines (a width in pixels) when the page has them, else WebGL's one-pixel lines.
  var fat = !!(THREE.LineSegments2 && THREE.LineMaterial && THREE.LineSegmentsGeometry);
  function segments(pos, col, style) {
    var s;
    if (fat) {
      var g = new THREE.LineSegmentsGeometry();
      g.setPositions(pos);
      if (col) g.setColors(col);
      var m = new THREE.LineMaterial({ color: col ? 0xffffff : style.color, linewidth: style.width });
      if (col) m.vertexColors = THREE.VertexColors;
      if (style.dashed) { m.dashed = true; m.dashSize = size / 80; m.gapSize = size / 120; }
      m.resolution.set(W, H);
      s = new THREE.LineSegments2(g, m);
    } else {
      var bg = new THREE.BufferGeometry();
      bg.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
      if (col) bg.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
      s = new THREE.LineSegments(bg, style.dashed
          ? new THREE.LineDashedMaterial({ color: style.color, dashSize: size / 80, gapSize: size / 120 })
          : new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors }));
    }
    if (style.dashed) s.computeLineDistances();
    scene.add(s);
    return s;
  }
  if (cutPos.length) segments(cutPos, cutCol, { width: 2.5 });
  if (rapidPos.length) segments(rapidPos, null, { color: 0x707070, width: 1.5, dashed: true });

  // Orientation: a grid in the XY plane under the path and the machine axes at its corner.
  var grid = new THREE.GridHelper(size * 1.2, 12, 0xd8d8d8, 0xececec);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(0, 0, lo[2] - centre[2]);
  scene.add(grid);
  var axes = new THREE.AxesHelper(size * 0.12);
  axes.position.set(lo[0] - centre[0], lo[1] - centre[1], lo[2] - centre[2]);
  scene.add(axes);

  // Labels are HTML over the canvas, placed at projected points on every render.
  var labels = [], labelBox = $('trace-labels');
  function addLabel(text, title, pos, cls) {
    var el = document.createElement('span');
    el.textContent = text;
    if (title) el.title = title;
    if (cls) el.className = cls;
    labelBox.appendChild(el);
    labels.push({ el: el, pos: pos });
  }
  ['X', 'Y', 'Z'].forEach(function (name, axis) {
    var p = axes.position.clone();
    p.setComponent(axis, p.getComponent(axis) + size * 0.14);
    addLabel(name, '', p);
  });

  // The worst dips, placed by their time on the trace.
  function sampleAtTime(t) {  // last sample with T <= t (0 if none)
    var l = 0, h = n - 1;
    if (t <= T[0]) return 0;
    while (l < h) { var m = (l + h + 1) >> 1; if (T[m] <= t) l = m; else h = m - 1; }
    return l;
  }
  function positionAtTime(t) {
    var j = sampleAtTime(t);
    if (j + 1 >= n || T[j + 1] <= T[j]) return local(j);
    return local(j).lerp(local(j + 1), Math.min(1, Math.max(0, (t - T[j]) / (T[j + 1] - T[j]))));
  }
  var dipGeometry = new THREE.SphereBufferGeometry(size * 0.008, 16, 12);
  var dipMaterial = new THREE.MeshBasicMaterial({ color: 0xd01c1c });
  D.dips.forEach(function (d) {
    var ball = new THREE.Mesh(dipGeometry, dipMaterial);
    ball.position.copy(positionAtTime(d[0]));
    scene.add(ball);
    addLabel(String(d[1]), d[2], ball.position);
  });

  // The tool: a cone whose tip is the tool centre, pointing down the Z axis.
  var toolHeight = size * 0.1;
  var tool = new THREE.Mesh(new THREE.ConeBufferGeometry(toolHeight * 0.3, toolHeight, 20),
                            new THREE.MeshBasicMaterial({ color: 0x202020, transparent: true, opacity: 0.85 }));
  tool.rotation.x = -Math.PI / 2;  // the cone's apex is +Y in its own frame; turn it to -Z
  scene.add(tool);

  // Views from three directions about the centre of the framed box.
  // The framed box's bounding sphere fits the 40 degree vertical field of view.
  var radius = Math.max(0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]), 1e-3);
  var fitDistance = 1.05 * radius / Math.sin(20 * Math.PI / 180);
  function view(dir) {
    var d = new THREE.Vector3(dir[0], dir[1], dir[2]).normalize().multiplyScalar(fitDistance);
    controls.target.set(0, 0, 0);
    camera.position.copy(d);
    controls.update();
    requestRender();
  }
  var views = { iso: [0.55, -1, 0.9], top: [0, -0.0001, 1], front: [0, -1, 0.0001] };
  $('trace-view-iso').onclick = function () { view(views.iso); };
  $('trace-view-top').onclick = function () { view(views.top); };
  $('trace-view-front').onclick = function () { view(views.front); };

  // Rendering on demand (orbiting, playback), labels follow the camera.
  var pending = false;
  function draw() {
    pending = false;
    renderer.render(scene, camera);
    labels.forEach(function (l) {
      var s = l.pos.clone().project(camera);
      var visible = s.z < 1 && Math.abs(s.x) <= 1 && Math.abs(s.y) <= 1;
      l.el.style.display = visible ? 'block' : 'none';
      l.el.style.left = ((s.x + 1) / 2 * W).toFixed(1) + 'px';
      l.el.style.top = ((1 - s.y) / 2 * H).toFixed(1) + 'px';
    });
  }
  function requestRender() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(draw);
  }
  controls.addEventListener('change', requestRender);

  // Playback position and read-out.
  var slider = $('trace-slider'), playButton = $('trace-play'), speedSelect = $('trace-speed');
  var current = 0, playing = false, playTime = 0, lastFrame = 0;
  var total = T[n - 1];
  function feedText(mmMin) { return Math.round(mmMin).toLocaleString('en-US') + ' mm/min'; }
  function show(j) {
    current = Math.max(0, Math.min(n - 1, j));
    slider.value = String(current);
    tool.position.copy(local(current));
    tool.position.z += toolHeight / 2;
    var b = D.blocks[B[current]] || [0, 0, '', 0];
    $('trace-block').textContent = b[2];
    $('trace-where').textContent = (D.files[b[0]] || '') + ':' + b[1];
    $('trace-time').textContent = T[current].toFixed(3) + ' s of ' + total.toFixed(3) + ' s';
    $('trace-feed').textContent = 'v ' + feedText(V[current]) +
        (R[current] ? ', rapid' : ', F ' + feedText(b[3])) + ' (tool centre)';
    requestRender();
  }
  function setPlaying(on) {
    playing = on && n > 1;
    playButton.innerHTML = playing ? '&#10073;&#10073;' : '&#9654;';
    if (!playing) return;
    if (current >= n - 1) show(0);
    playTime = T[current];
    lastFrame = performance.now();
    requestAnimationFrame(tick);
  }
  function tick(now) {
    if (!playing) return;
    playTime += (now - lastFrame) / 1000 * Number(speedSelect.value);
    lastFrame = now;
    var j = sampleAtTime(playTime);
    if (j !== current) show(j);
    if (playTime >= total) { setPlaying(false); return; }
    requestAnimationFrame(tick);
  }
  // Speeds: real time and faster; the default plays the program in about half a minute.
  [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 5000].forEach(function (s) {
    var o = document.createElement('option');
    o.value = String(s);
    o.textContent = '\u00d7' + s;
    speedSelect.appendChild(o);
  });
  speedSelect.value = String([1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 5000].filter(function (s) {
    return s <= Math.max(1, total / 30);
  }).pop());
  speedSelect.onchange = function () { playTime = T[current]; };
  slider.addEventListener('input', function () { show(Number(slider.value)); playTime = T[current]; });
  playButton.onclick = function () { setPlaying(!playing); };

  // Keyboard (on the focused viewer): space, arrows (shift: by block), Home, End.
  function blockStart(j) { while (j > 0 && B[j - 1] === B[j]) --j; return j; }
  function stepBlock(dir) {  // to the first sample of the next or the previous block
    if (dir > 0) { var j = current; while (j < n - 1 && B[j] === B[current]) ++j; return j; }
    var s = blockStart(current);
    return s > 0 ? blockStart(s - 1) : 0;
  }
  root.addEventListener('keydown', function (e) {
    // The speed list keeps its own keys; a focused button takes space as its own click.
    if (e.target.tagName === 'SELECT' || (e.key === ' ' && e.target.tagName === 'BUTTON')) return;
    var handled = true;
    if (e.key === ' ') setPlaying(!playing);
    else if (e.key === 'ArrowRight') show(e.shiftKey ? stepBlock(1) : current + 1);
    else if (e.key === 'ArrowLeft') show(e.shiftKey ? stepBlock(-1) : current - 1);
    else if (e.key === 'Home') show(0);
    else if (e.key === 'End') show(n - 1);
    else handled = false;
    if (handled) { e.preventDefault(); if (e.key !== ' ') setPlaying(false); }
  });
  canvas.addEventListener('pointerdown', function () { root.focus({ preventScroll: true }); });

  // Double-click: the sample nearest to the pointer on screen becomes the playback position.
  function nearestSample(px, py) {
    var best = -1, bestD = Infinity, v = new THREE.Vector3();
    for (var j = 0; j < n; ++j) {
      v.set(X[j] - centre[0], Y[j] - centre[1], Z[j] - centre[2]).project(camera);
      var dx = (v.x + 1) / 2 * W - px, dy = (1 - v.y) / 2 * H - py, d = dx * dx + dy * dy;
      if (v.z < 1 && d < bestD) { bestD = d; best = j; }
    }
    return bestD <= 400 ? best : -1;  // within 20 px
  }
  canvas.addEventListener('dblclick', function (e) {
    var r = canvas.getBoundingClientRect();
    var j = nearestSample((e.clientX - r.left) * W / r.width, (e.clientY - r.top) * H / r.height);
    if (j >= 0) { setPlaying(false); show(j); }
  });

  // Legend: the colour ramp with its scale, rapids, dips.
  var ramp = 'linear-gradient(to right,' + D.colours.join(',') + ')';
  $('trace-legend').innerHTML = '0 <span class="ramp" style="background:' + ramp + '"></span> ' +
      Math.round(D.scale).toLocaleString('en-US') + ' mm/min path velocity &nbsp; ' +
      '<span style="color:#707070">- - -</span> rapid &nbsp; <span style="color:#d01c1c">&#9679;</span> feed dip' +
      ' &nbsp; (' + n.toLocaleString('en-US') + ' of ' + D.samples.toLocaleString('en-US') + ' IPO samples drawn)';

  view(views.iso);
  var at = /at=([0-9.]+)/.exec(location.hash);
  show(at ? Math.round(Number(at[1]) * (n - 1)) : 0);
  draw();
  if (/viewer-only/.test(location.hash)) {  // for a screenshot of the view alone
    Array.prototype.forEach.call(document.body.children, function (el) {
      if (el !== root && !el.contains(root) && el.tagName !== 'SCRIPT') el.style.display = 'none';
    });
  }
  if (/selftest/.test(location.hash)) selfTest();

  function selfTest() {
    tool.visible = false; grid.visible = false; axes.visible = false;
    draw();
    var gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    var px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    function painted(x, y, r) {  // any non-white pixel within r of (x, y) (y from the top)
      for (var yy = Math.max(0, y - r); yy <= Math.min(h - 1, y + r); ++yy)
        for (var xx = Math.max(0, x - r); xx <= Math.min(w - 1, x + r); ++xx) {
          var o = 4 * ((h - 1 - yy) * w + xx);
          if (px[o] < 235 || px[o + 1] < 235 || px[o + 2] < 235) return true;
        }
      return false;
    }
    var screen = [], v = new THREE.Vector3();
    for (var j = 0; j < n; ++j) {
      v.copy(local(j)).project(camera);
      screen.push([Math.round((v.x + 1) / 2 * w), Math.round((1 - v.y) / 2 * h), v.z]);
    }
    var tried = 0, hit = 0, control = 0, controlPainted = 0, step = Math.max(1, Math.floor(n / 200));
    var sampled = 0;
    for (j = 0; j < n; j += step) {  // samples framed out of the view do not count
      ++sampled;
      if (screen[j][0] < 0 || screen[j][0] >= w || screen[j][1] < 0 || screen[j][1] >= h || screen[j][2] >= 1) continue;
      ++tried;
      if (painted(screen[j][0], screen[j][1], 2)) ++hit;
    }
    // Control points: a grid over the canvas, kept where no path sample projects within 25 px.
    for (var gy = 10; gy < h; gy += 40)
      for (var gx = 10; gx < w; gx += 40) {
        var far = screen.every(function (s) { return Math.abs(s[0] - gx) > 25 || Math.abs(s[1] - gy) > 25; });
        if (!far) continue;
        ++control;
        if (painted(gx, gy, 0)) ++controlPainted;
      }
    var paintedPixels = 0;
    for (var o = 0; o < px.length; o += 4) if (px[o] < 235 || px[o + 1] < 235 || px[o + 2] < 235) ++paintedPixels;
    tool.visible = true; grid.visible = true; axes.visible = true;
    slider.value = '0';
    slider.dispatchEvent(new Event('input'));
    var first = $('trace-where').textContent + ' ' + $('trace-block').textContent;
    var firstTool = tool.position.clone();
    slider.value = String(n - 1);
    slider.dispatchEvent(new Event('input'));
    var last = $('trace-where').textContent + ' ' + $('trace-block').textContent;
    var moved = tool.position.distanceTo(firstTool) > 0;
    // The keyboard: shift + left arrow goes back one block, End returns to the last sample.
    root.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowLeft', shiftKey: true }));
    var back = $('trace-where').textContent + ' ' + $('trace-block').textContent;
    root.dispatchEvent(new KeyboardEvent('keydown', { key: 'End' }));
    var keys = back !== last && Number(slider.value) === n - 1;
    var ok = tried >= 0.5 * sampled && hit >= 0.9 * tried && control > 0 && controlPainted <= 0.05 * control &&
             first !== last && moved && keys;
    var out = document.createElement('pre');
    out.id = 'trace-selftest';
    out.textContent = 'path samples painted ' + hit + '/' + tried + ' (' + sampled + ' tried, ' + tried +
        ' in view); control points painted ' + controlPainted +
        '/' + control + '; painted pixels ' + paintedPixels + '; block at start [' + first + ']; block at end [' + last +
        ']; tool moved ' + moved + '; shift+left shows [' + back + ']; VERDICT ' + (ok ? 'PASS' : 'FAIL');
    root.appendChild(out);
    // Playback: from the start at the highest speed; where it got to is written beside the
    // verdict on every frame (the browser test gives the page virtual time to play).
    var played = document.createElement('pre');
    played.id = 'trace-selftest-playback';
    root.appendChild(played);
    show(0);
    speedSelect.value = speedSelect.options[speedSelect.options.length - 1].value;
    setPlaying(true);
    (function watch() {
      played.textContent = 'playback at sample ' + current + ' of ' + (n - 1) + ', playing ' + playing +
          ', block [' + $('trace-where').textContent + ' ' + $('trace-block').textContent + ']';
      if (playing) requestAnimationFrame(watch);
    })();
  }
})();
