// Opens an HTML report in headless chromium and checks what a user sees: the
// molds listed, the 3D view drawn, a click that selects a panel. Exits 1 with
// the reasons on failure. Run by html_report_browser_test.sh.
//   node html_report_browser_check.js REPORT.html K [SCREENSHOT.png] [ORBIT_FRAMES]
const path = require('path');
const puppeteer = require(process.env.PUPPETEER_CORE);

const [html, k, screenshot, frames] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };

// The pixels of the WebGL canvas that differ from its white background.
function drawnPixels() {
  const canvas = document.getElementById('canvas'), copy = document.createElement('canvas');
  copy.width = canvas.width; copy.height = canvas.height;
  const context = copy.getContext('2d');
  context.drawImage(canvas, 0, 0);
  const pixels = context.getImageData(0, 0, copy.width, copy.height).data;
  let drawn = 0;
  for (let i = 0; i < pixels.length; i += 4)
    if (pixels[i] < 250 || pixels[i + 1] < 250 || pixels[i + 2] < 250) ++drawn;
  return { drawn, total: pixels.length / 4 };
}

// Clicks the panels nearest the middle of the view until one is selected.
async function clickAPanel(page) {
  const faces = await page.evaluate(() => {
    const r = window.tilableReport, n = r.triangleFace[r.triangleFace.length - 1] + 1, box = document.getElementById('canvas').getBoundingClientRect();
    const middle = { x: box.left + box.width / 2, y: box.top + box.height / 2 };
    return Array.from({ length: n }, (_, f) => ({ f, ...r.project(f) }))
      .sort((a, b) => Math.hypot(a.x - middle.x, a.y - middle.y) - Math.hypot(b.x - middle.x, b.y - middle.y)).slice(0, 5);
  });
  for (const face of faces) {
    await page.mouse.click(face.x, face.y);
    const selected = await page.evaluate(() => document.getElementById('info').dataset.face);
    if (selected !== undefined) return face;
  }
  return null;
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM, headless: true,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist'],
  });
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('request', (r) => { if (!/^(file|blob|data):/.test(r.url())) errors.push('network request: ' + r.url()); });
    await page.setViewport({ width: 1400, height: 900 });
    await page.goto('file://' + path.resolve(html), { waitUntil: 'load' });
    await page.waitForFunction('window.tilableReport && (window.tilableReport.ready || window.tilableReport.error)', { timeout: 120000 });
    check(!(await page.evaluate(() => window.tilableReport.error)), '3D view started');
    const report = await page.evaluate(() => JSON.parse(document.getElementById('report-data').textContent));
    const tiles = await page.$$eval('#catalog .mold', (e) => e.map((m) => Number(m.dataset.tile)));
    const withInstances = report.cluster_sizes.filter((n) => n > 0).length;
    check(tiles.length === Number(k) && tiles.length === withInstances, `${tiles.length} molds listed, K = ${k}`);
    const sheets = await page.$$eval('#catalog .mold svg.mold-sheet', (e) => e.length);
    check(sheets === tiles.length, `${sheets} mold sheets drawn`);
    const pixels = await page.evaluate(drawnPixels);
    check(pixels.drawn > 0.05 * pixels.total, `3D view drawn: ${pixels.drawn} of ${pixels.total} pixels not background`);
    const face = await clickAPanel(page);
    const info = await page.evaluate(() => ({ ...document.getElementById('info').dataset,
      text: document.getElementById('info').textContent,
      marked: Array.from(document.querySelectorAll('.mold.selected'), (e) => e.dataset.tile) }));
    check(face !== null && info.face !== undefined, `a click on the view selected panel ${info.face}`);
    const cluster = face ? await page.evaluate((f) => window.tilableReport.clusterOf(Number(f)), info.face) : -1;
    check(info.tile === String(cluster) && info.marked.length === 1 && info.marked[0] === info.tile &&
          info.text.includes(`tile ${cluster}`), `its tile ${info.tile} told and its mold sheet marked`);
    await page.click('input[name=colour][value=deviation]');
    await page.click('#ghost');
    const afterToggles = await page.evaluate(drawnPixels);
    check(afterToggles.drawn > 0.05 * afterToggles.total, 'deviation colours and the ghost drawn');
    check(errors.length === 0, 'no errors and no network requests' + (errors.length ? ': ' + errors.join('; ') : ''));
    if (Number(frames) > 0)
      console.log(`orbit: ${(await page.evaluate((n) => window.tilableReport.orbit(n), Number(frames))).toFixed(2)} ms per frame`);
    if (screenshot) {
      await page.click('input[name=colour][value=mold]');
      await page.click('#ghost');
      await page.screenshot({ path: screenshot });
      console.log(`screenshot: ${screenshot}`);
    }
  } finally {
    await browser.close();
  }
  process.exit(failures.length ? 1 : 0);
})().catch((e) => { console.error(e); process.exit(1); });
