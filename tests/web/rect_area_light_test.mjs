// Renders rect_area_light.html in headless Chromium (Debian's, driven by playwright-core) with three.js's LTC
// tables and with pbrfit's exports in their place, and compares the images (absolute differences of every
// pixel's R, G and B, in levels of 255):
//  - pbrfit's export of the published table it holds, the numbers three.js ships: a drop-in replacement must
//    render the same image (mean at most 0.01, largest at most 1 level);
//  - pbrfit's own GGX fit: a table of the same lobe, fitted anew, must agree closely (mean at most FIT_MEAN,
//    99.9th percentile at most FIT_P999; where they differ the fits do, at grazing silhouettes);
//  - that fit transposed (u and v swapped) must fail the fit's comparison, so the comparison can fail.
// Writes the screenshots and a summary (results.json) to OUT.
//   node rect_area_light_test.mjs MODULES_DIR EXPORTED_DIR OUT
import { createServer } from 'node:http';
import { readFile, writeFile, mkdir } from 'node:fs/promises';
import { extname, join, normalize, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const FIT_MEAN = 2.0;   // levels of 255
const FIT_P999 = 32;
const [modulesDir, exportedDir, out] = process.argv.slice(2).map((p) => resolve(p));
if (!out) { console.error('usage: node rect_area_light_test.mjs MODULES_DIR EXPORTED_DIR OUT'); process.exit(2); }
const pageDir = fileURLToPath(new URL('.', import.meta.url));
const { chromium } = await import(pathToFileURL(join(modulesDir, 'playwright-core', 'index.mjs')).href);

const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json' };
const server = createServer(async (request, response) => {
  if (request.url === '/favicon.ico') { response.writeHead(204); response.end(); return; }
  const path = normalize(decodeURIComponent(new URL(request.url, 'http://x').pathname));
  const file = path.startsWith('/node_modules/') ? join(modulesDir, path.slice('/node_modules/'.length))
             : path.startsWith('/exported/') ? join(exportedDir, path.slice('/exported/'.length))
             : join(pageDir, path);
  try {
    const body = await readFile(file);
    response.writeHead(200, { 'content-type': types[extname(file)] || 'application/octet-stream' });
    response.end(body);
  } catch {
    response.writeHead(404);
    response.end();
  }
});
await new Promise((done) => server.listen(0, '127.0.0.1', done));
const base = `http://127.0.0.1:${server.address().port}/rect_area_light.html`;

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--disable-gpu-sandbox',
         '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run',
         '--disable-quic'] });
await mkdir(out, { recursive: true });
const problems = [];
async function render(mode) {
  const page = await browser.newPage({ viewport: { width: 512, height: 256 } });
  page.on('console', (message) => { if (message.type() === 'error') problems.push(`${mode}: console: ${message.text()}`); });
  page.on('requestfailed', (request) => problems.push(`${mode}: request failed: ${request.url()}`));
  page.on('response', (response) => { if (response.status() >= 400) problems.push(`${mode}: ${response.status()} for ${response.url()}`); });
  page.on('pageerror', (error) => problems.push(`${mode}: page error: ${error.message}`));
  await page.goto(`${base}?tables=${mode}`);
  await page.waitForFunction(() => window.renderResult !== undefined, null, { timeout: 120000 });
  const result = await page.evaluate(() => window.renderResult);
  await page.screenshot({ path: join(out, `${mode}.png`) });
  await page.close();
  if (result.error) throw new Error(`${mode}: ${result.error}`);
  return result;
}

function compare(a, b) {
  const differences = [];
  let sum = 0;
  for (let i = 0; i < a.pixels.length; i += 4)
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(a.pixels[i + c] - b.pixels[i + c]);
      sum += d;
      differences.push(d);
    }
  differences.sort((x, y) => x - y);
  return { mean: sum / differences.length, p999: differences[Math.floor(0.999 * (differences.length - 1))],
           max: differences[differences.length - 1] };
}

let status = 0;
try {
  const three = await render('three'), published = await render('published');
  const pbrfit = await render('pbrfit'), transposed = await render('transposed');
  const lit = three.pixels.filter((v, i) => i % 4 !== 3 && v > 8).length / (three.pixels.length * 0.75);
  const exact = compare(three, published), fit = compare(three, pbrfit), wrong = compare(three, transposed);
  const summary = { lit_share: lit, published_vs_three: exact, fit_vs_three: fit, transposed_vs_three: wrong,
                    float_tables: three.floatTables, sheen_shader_patched: pbrfit.sheenPatched,
                    limits: { published: { mean: 0.01, max: 1 }, fit: { mean: FIT_MEAN, p999: FIT_P999 } } };
  await writeFile(join(out, 'results.json'), JSON.stringify(summary, null, 2));
  console.log(JSON.stringify(summary));
  if (lit < 0.05) problems.push(`the scene is dark: ${(100 * lit).toFixed(1)} % of the channels above 8`);
  if (!(exact.mean <= 0.01 && exact.max <= 1))
    problems.push(`the exported published table renders unlike three.js's own: mean ${exact.mean.toFixed(4)}, max ${exact.max}`);
  if (!(fit.mean <= FIT_MEAN && fit.p999 <= FIT_P999))
    problems.push(`pbrfit's fit renders unlike three.js's table: mean ${fit.mean.toFixed(3)}, p99.9 ${fit.p999}`);
  if (wrong.mean <= FIT_MEAN && wrong.p999 <= FIT_P999)
    problems.push(`the transposed table passes the comparison: mean ${wrong.mean.toFixed(3)}, p99.9 ${wrong.p999}`);
  if (!pbrfit.sheenPatched) problems.push('the sheen shader chunk was not patched in');
} catch (error) {
  problems.push(String(error.stack || error));
}
await browser.close();
server.close();
for (const p of problems) console.error('FAIL: ' + p);
status = problems.length ? 1 : 0;
process.exit(status);
