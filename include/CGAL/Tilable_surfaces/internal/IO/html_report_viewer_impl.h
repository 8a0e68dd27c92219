// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_IO_HTML_REPORT_VIEWER_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_IO_HTML_REPORT_VIEWER_IMPL_H

// The bodies of the non-template functions declared in html_report_viewer.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/IO/html_report_viewer.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
const char* html_report_style()
{
  return R"CSS(
body { font-family: system-ui, sans-serif; margin: 0; color: #123; background: #f6f7f9; }
header, section { padding: 0.6em 1.2em; }
h1 { font-size: 1.4em; margin: 0.3em 0; } h2 { font-size: 1.15em; border-bottom: 1px solid #ccd; }
#viewer { display: grid; grid-template-columns: minmax(0, 1fr) 22em; gap: 1em; }
#view3d { position: relative; height: 70vh; min-height: 360px; background: #fff; border: 1px solid #ccd; }
#view3d canvas { width: 100%; height: 100%; display: block; }
#side label { display: block; margin: 0.2em 0; }
#info { margin-top: 1em; padding: 0.5em; background: #fff; border: 1px solid #ccd; min-height: 6em; }
#legend .bar { height: 0.8em; background: linear-gradient(to right, #2040c0, #f0e040, #d02020); }
#legend .ends { display: flex; justify-content: space-between; font-size: 0.85em; }
table { border-collapse: collapse; } td, th { padding: 0.15em 0.8em 0.15em 0; text-align: left; vertical-align: top; }
.molds { display: grid; grid-template-columns: repeat(auto-fill, minmax(17em, 1fr)); gap: 0.8em; }
.mold { background: #fff; border: 1px solid #ccd; padding: 0.4em; }
.mold.selected { outline: 3px solid #d02020; }
.mold svg { width: 100%; height: auto; } .mold p { margin: 0.2em 0; font-size: 0.9em; }
.swatch { display: inline-block; width: 0.9em; height: 0.9em; border: 1px solid #456; vertical-align: middle; }
#curve svg { max-width: 40em; width: 100%; height: auto; background: #fff; border: 1px solid #ccd; }
)CSS";
}

CGAL_TILABLE_SURFACES_INLINE
const char* html_report_script()
{
  return R"JS(
const $ = (id) => document.getElementById(id);
const data = JSON.parse($('mesh-data').textContent);
function decode(text, Type) {
  const s = atob(text), bytes = new Uint8Array(s.length);
  for (let i = 0; i < s.length; ++i) bytes[i] = s.charCodeAt(i);
  return new Type(bytes.buffer);
}
const M = {
  positions: decode(data.positions, Float32Array), input: decode(data.input_positions, Float32Array),
  faceVertices: decode(data.face_vertices, Uint32Array), faceSizes: decode(data.face_sizes, Uint8Array),
  clusters: decode(data.clusters, Uint32Array), orientations: decode(data.orientations, Uint8Array),
  deviation: decode(data.deviation, Float32Array),
};
const faceStart = new Uint32Array(M.faceSizes.length + 1);
M.faceSizes.forEach((n, f) => { faceStart[f + 1] = faceStart[f] + n; });
const corners = (f) => M.faceVertices.subarray(faceStart[f], faceStart[f + 1]);
// Each face as a fan of triangles from its first corner.
const triangleFace = [], triangleVertices = [];
M.faceSizes.forEach((n, f) => {
  const c = corners(f);
  for (let k = 2; k < n; ++k) { triangleFace.push(f); triangleVertices.push(c[0], c[k - 1], c[k]); }
});
const maxDeviation = M.deviation.reduce((a, b) => Math.max(a, b), 0);
const state = { mode: 'mold', tile: -1, face: -1 };
const report = window.tilableReport = { ready: false, error: null, state, triangleFace, clusterOf: (f) => M.clusters[f] };
const fmt = (x, d = 4) => Number(x).toPrecision(d);
const antialiasedFaces = 2000;

function heat(t) {
  const stops = [[0.125, 0.25, 0.75], [0.94, 0.88, 0.25], [0.82, 0.125, 0.125]];
  const s = Math.min(Math.max(t, 0), 1) * 2, i = Math.min(Math.floor(s), 1), u = s - i;
  return stops[i].map((a, k) => a + (stops[i + 1][k] - a) * u);
}
function tileColor(c) {
  const h = data.colors[c];
  return [1, 3, 5].map((k) => parseInt(h.substr(k, 2), 16) / 255);
}
function faceDeviation(f) { return Math.max(...Array.from(corners(f), (v) => M.deviation[v])); }
function card(c) { return document.getElementById('tile-' + c); }

function describe(f) {
  const c = M.clusters[f], d = card(c).dataset, dev = faceDeviation(f);
  $('info').innerHTML = `<b>panel ${f}</b>: tile ${c}, mold ${d.mold}<br>${d.instances} instances` +
    ` (${d.mirrored} mirrored), PLY orientation ${M.orientations[f]}<br>deviation ${fmt(dev)}` +
    ` (${fmt(100 * dev / data.bbox_diagonal, 3)}% of the diagonal)<br><a href="#tile-${c}">its mold sheet</a>`;
  $('info').dataset.face = f; $('info').dataset.tile = c;
}

async function start() {
  const threeSource = $('three-module').textContent;
  if (!threeSource.trim()) { $('view3d').textContent = 'This report was written without the 3D viewer.'; return; }
  const url = (s) => URL.createObjectURL(new Blob([s], { type: 'text/javascript' }));
  const threeUrl = url(threeSource);
  const THREE = await import(threeUrl);
  const orbit = $('orbit-controls').textContent.replace(/from\s*['"]three['"]/g, `from '${threeUrl}'`);
  const { OrbitControls } = await import(url(orbit));
  const canvas = $('canvas'), box = $('view3d');
  // Antialiasing doubles a frame's time where WebGL is rendered in software.
  const antialias = M.faceSizes.length <= antialiasedFaces;
  const renderer = new THREE.WebGLRenderer({ canvas, antialias, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  const scene = new THREE.Scene(); scene.background = new THREE.Color(0xffffff);
  const camera = new THREE.PerspectiveCamera(40, 1, 1e-3, 1e3);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
  const light = new THREE.DirectionalLight(0xffffff, 1.4); camera.add(light); scene.add(camera);

  const count = triangleFace.length, pos = new Float32Array(9 * count), ghostPos = new Float32Array(9 * count);
  triangleVertices.forEach((v, i) => {
    for (let a = 0; a < 3; ++a) { pos[3 * i + a] = M.positions[3 * v + a]; ghostPos[3 * i + a] = M.input[3 * v + a]; }
  });
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(pos, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(9 * count), 3));
  geometry.computeVertexNormals(); geometry.computeBoundingSphere();
  const surface = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
  scene.add(surface);
  const ghostGeometry = new THREE.BufferGeometry();
  ghostGeometry.setAttribute('position', new THREE.BufferAttribute(ghostPos, 3)); ghostGeometry.computeVertexNormals();
  const ghost = new THREE.Mesh(ghostGeometry, new THREE.MeshLambertMaterial({ color: 0x8899aa, transparent: true,
    opacity: 0.3, depthWrite: false, side: THREE.DoubleSide }));
  ghost.visible = false; scene.add(ghost);
  scene.add(panelEdges(THREE));

  ghostGeometry.computeBoundingSphere();
  const sphere = geometry.boundingSphere.clone().union(ghostGeometry.boundingSphere);
  camera.up.set(0, 0, 1); camera.near = sphere.radius / 100; camera.far = sphere.radius * 100;
  // Far enough for the bounding sphere of both surfaces to fit the narrower field of view.
  const fov = THREE.MathUtils.degToRad(camera.fov) * Math.min(1, box.clientWidth / box.clientHeight);
  camera.position.copy(sphere.center).add(new THREE.Vector3(1, -1.6, 1.1).normalize().multiplyScalar(1.1 * sphere.radius / Math.sin(fov / 2)));
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(sphere.center);
  controls.update();
  const render = () => renderer.render(scene, camera);
  const resize = () => { renderer.setSize(box.clientWidth, box.clientHeight, false);
    camera.aspect = box.clientWidth / box.clientHeight; camera.updateProjectionMatrix(); render(); };
  controls.addEventListener('change', render); window.addEventListener('resize', resize);

  function recolour() {
    const colors = geometry.getAttribute('color');
    triangleVertices.forEach((v, i) => {
      const f = triangleFace[Math.floor(i / 3)];
      let rgb = state.mode === 'deviation' ? heat(maxDeviation > 0 ? M.deviation[v] / maxDeviation : 0)
                                           : tileColor(M.clusters[f]);
      if (state.tile >= 0 && M.clusters[f] !== state.tile) rgb = rgb.map((x) => 0.78 + 0.15 * x);
      if (f === state.face) rgb = [0.1, 0.1, 0.1];
      colors.setXYZ(i, rgb[0], rgb[1], rgb[2]);
    });
    colors.needsUpdate = true; render();
  }
  report.selectTile = (c) => { state.tile = c; recolour();
    document.querySelectorAll('.mold.selected').forEach((e) => e.classList.remove('selected'));
    if (c >= 0) card(c).classList.add('selected'); };
  report.selectFace = (f) => { state.face = f; describe(f); report.selectTile(M.clusters[f]); };
  const raycaster = new THREE.Raycaster(), down = { x: 0, y: 0 };
  canvas.addEventListener('pointerdown', (e) => { down.x = e.clientX; down.y = e.clientY; });
  canvas.addEventListener('pointerup', (e) => {
    if (Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
    const r = canvas.getBoundingClientRect();
    raycaster.setFromCamera(new THREE.Vector2(2 * (e.clientX - r.left) / r.width - 1, 1 - 2 * (e.clientY - r.top) / r.height), camera);
    const hit = raycaster.intersectObject(surface)[0];
    if (hit) report.selectFace(triangleFace[hit.faceIndex]);
  });
  document.querySelectorAll('input[name=colour]').forEach((r) => r.addEventListener('change', () => {
    state.mode = r.value; $('legend').hidden = r.value !== 'deviation'; recolour(); }));
  $('ghost').addEventListener('change', () => { ghost.visible = $('ghost').checked; render(); });
  $('show-all').addEventListener('click', () => { state.face = -1; report.selectTile(-1); });
  document.querySelectorAll('button.show').forEach((b) => b.addEventListener('click', () => {
    state.face = -1; report.selectTile(Number(b.dataset.tile)); box.scrollIntoView({ behavior: 'smooth' }); }));
  // Orbits the camera once around in `frames` frames, each drawn to the end
  // (a pixel read back waits for it): the milliseconds a frame takes.
  report.orbit = (frames) => {
    const axis = new THREE.Vector3(0, 0, 1), angle = 2 * Math.PI / frames, gl = renderer.getContext();
    const pixel = new Uint8Array(4), t0 = performance.now();
    for (let i = 0; i < frames; ++i) {
      camera.position.sub(controls.target).applyAxisAngle(axis, angle).add(controls.target);
      camera.lookAt(controls.target); render(); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    }
    return (performance.now() - t0) / frames;
  };
  report.project = (f) => { const c = corners(f), p = new THREE.Vector3();
    c.forEach((v) => p.add(new THREE.Vector3(M.positions[3 * v], M.positions[3 * v + 1], M.positions[3 * v + 2])));
    p.divideScalar(c.length).project(camera); const r = canvas.getBoundingClientRect();
    return { x: r.left + (p.x + 1) / 2 * r.width, y: r.top + (1 - p.y) / 2 * r.height }; };
  resize(); recolour(); report.ready = true;
}

function panelEdges(THREE) {
  const seen = new Set(), points = [];
  M.faceSizes.forEach((n, f) => {
    const c = corners(f);
    for (let k = 0; k < n; ++k) {
      const a = c[k], b = c[(k + 1) % n], key = Math.min(a, b) * 4294967296 + Math.max(a, b);
      if (seen.has(key)) continue;
      seen.add(key);
      for (const v of [a, b]) points.push(M.positions[3 * v], M.positions[3 * v + 1], M.positions[3 * v + 2]);
    }
  });
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(points), 3));
  return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x223344, transparent: true, opacity: 0.5 }));
}

$('legend-max').textContent = `${fmt(maxDeviation)} (${fmt(100 * maxDeviation / data.bbox_diagonal, 3)}%)`;
start().catch((e) => { report.error = String(e); $('view3d').textContent = '3D view failed: ' + e; });
)JS";
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_IO_HTML_REPORT_VIEWER_IMPL_H
