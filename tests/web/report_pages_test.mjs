// Opens `pbrfit report` pages in headless Chromium (Debian's, driven by playwright-core) and checks each as a
// reader would meet it:
//  - no console error and no uncaught page error;
//  - no failed request, no HTTP status >= 400, nothing loaded from another origin (the page is self-contained);
//  - every <img> loaded (complete, naturalWidth > 0), visible with a non-zero box, and drawn at its size: the
//    report's figures carry no width, height or scaling style, so each shows at its natural size (within
//    SIZE_SLACK px); an image that CSS scales on purpose must keep its aspect ratio;
//  - every <a href> resolves: an in-page anchor (#id) names an element of the page, a relative link names a file
//    inside the report's directory that the server returns with status 200, and no link leaves the report
//    (http, https or any other scheme to another origin);
//  - a full-page screenshot NAME.png in OUT.
// Prints a JSON summary (per page: images, links, console messages) and writes it to OUT/results.json; on the
// first failure prints one line `the NAME page: problem` on stderr and exits 1 (2: usage).
//   node report_pages_test.mjs MODULES_DIR OUT NAME=URL...
import { mkdir, writeFile } from 'node:fs/promises';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const SIZE_SLACK = 2;   // CSS px a figure's box may differ from its natural size (sub-pixel layout, borders)
const [modulesDir, outDir, ...pageArgs] = process.argv.slice(2);
const pages = pageArgs.map((arg) => {
  const at = arg.indexOf('=');
  return at > 0 ? { name: arg.slice(0, at), url: arg.slice(at + 1) } : null;
});
if (!outDir || pages.length === 0 || pages.includes(null)) {
  console.error('usage: node report_pages_test.mjs MODULES_DIR OUT NAME=URL...');
  process.exit(2);
}
const out = resolve(outDir);
const { chromium } = await import(pathToFileURL(join(resolve(modulesDir), 'playwright-core', 'index.mjs')).href);

class PageProblem extends Error {}
const summary = [];

// Everything the page itself shows about its images and links, measured in the page after it loaded.
function measure() {
  const scaledByStyle = (img) => {
    if (img.hasAttribute('width') || img.hasAttribute('height')) return true;
    const sizing = ['width', 'height', 'max-width', 'max-height', 'min-width', 'min-height', 'transform', 'zoom'];
    if (sizing.some((p) => img.style.getPropertyValue(p))) return true;
    for (const sheet of document.styleSheets) {
      for (const rule of sheet.cssRules) {
        if (!rule.selectorText || !img.matches(rule.selectorText)) continue;
        if (sizing.some((p) => rule.style.getPropertyValue(p))) return true;
      }
    }
    return false;
  };
  const images = [...document.images].map((img) => {
    const box = img.getBoundingClientRect();
    const style = getComputedStyle(img);
    return { src: img.getAttribute('src'), url: img.currentSrc || img.src, complete: img.complete,
             naturalWidth: img.naturalWidth, naturalHeight: img.naturalHeight, width: box.width,
             height: box.height, visible: style.visibility !== 'hidden' && style.display !== 'none' && style.opacity !== '0',
             scaledByStyle: scaledByStyle(img) };
  });
  const links = [...document.querySelectorAll('a[href]')].map((a) => {
    const href = a.getAttribute('href');
    const url = new URL(href, document.baseURI);
    const samePage = url.origin === location.origin && url.pathname === location.pathname && url.search === location.search;
    let fragment = null;
    try { fragment = decodeURIComponent(url.hash.slice(1)); } catch { fragment = url.hash.slice(1); }
    const target = samePage && fragment
      ? document.getElementById(fragment) || document.getElementsByName(fragment)[0] || null : null;
    return { href, url: url.href, origin: url.origin, pathname: url.pathname, text: a.textContent.trim().slice(0, 60),
             samePage, fragment, targetFound: target !== null };
  });
  return { title: document.title, images, links };
}

async function checkPage(browser, { name, url }) {
  const started = Date.now();
  const problems = [];   // what the page's own loading reported; the first one fails the page
  const consoleMessages = [];
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const origin = new URL(url).origin;
  const directory = new URL('.', url).pathname;
  page.on('console', (message) => {
    consoleMessages.push({ type: message.type(), text: message.text() });
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`uncaught page error: ${error.message}`));
  page.on('requestfailed', (request) => {
    if (new URL(request.url()).origin === origin)
      problems.push(`request failed: ${request.url()} (${request.failure()?.errorText})`);
  });
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()} for ${response.url()}`);
  });
  // Nothing leaves the machine: a request to another origin is a defect, and is refused.
  await context.route('**/*', (route) => {
    const requested = route.request().url();
    if (requested.startsWith('data:') || new URL(requested).origin === origin) return route.continue();
    problems.push(`loads an external resource: ${requested}`);
    return route.abort();
  });

  const response = await page.goto(url, { waitUntil: 'load', timeout: 60000 });
  if (!response) throw new PageProblem('no response for the page');
  if (response.status() !== 200) throw new PageProblem(`the page itself answers HTTP ${response.status()}`);
  const seen = await page.evaluate(measure);
  await mkdir(out, { recursive: true });
  await page.screenshot({ path: join(out, `${name}.png`), fullPage: true });
  const pageSize = await page.evaluate(() => ({ width: document.documentElement.scrollWidth,
                                                height: document.documentElement.scrollHeight }));
  if (problems.length) throw new PageProblem(problems[0]);

  if (seen.images.length === 0) throw new PageProblem('the page shows no image');
  for (const img of seen.images) {
    const what = `image ${img.src}`;
    if (new URL(img.url).origin !== origin || !new URL(img.url).pathname.startsWith(directory))
      throw new PageProblem(`${what} lies outside the report directory (${img.url})`);
    if (!img.complete || img.naturalWidth === 0 || img.naturalHeight === 0)
      throw new PageProblem(`${what} did not load (complete ${img.complete}, natural size ${img.naturalWidth} x ${img.naturalHeight})`);
    if (!(img.width > 0 && img.height > 0) || !img.visible)
      throw new PageProblem(`${what} is not rendered: its box is ${img.width} x ${img.height}${img.visible ? '' : ', hidden'}`);
    const box = `${img.width.toFixed(1)} x ${img.height.toFixed(1)}`, natural = `${img.naturalWidth} x ${img.naturalHeight}`;
    if (img.scaledByStyle) {
      const expectedHeight = img.width * img.naturalHeight / img.naturalWidth;
      if (Math.abs(img.height - expectedHeight) > SIZE_SLACK)
        throw new PageProblem(`${what} is distorted: shown at ${box} px, its natural size is ${natural}`);
    } else if (Math.abs(img.width - img.naturalWidth) > SIZE_SLACK || Math.abs(img.height - img.naturalHeight) > SIZE_SLACK) {
      throw new PageProblem(`${what} is not shown at its size: ${box} px, its natural size is ${natural}, and no style scales it`);
    }
  }

  let fetched = 0;
  for (const link of seen.links) {
    const what = `link "${link.href}" (${link.text})`;
    if (link.samePage) {
      if (!link.fragment) throw new PageProblem(`${what} names no anchor`);
      if (!link.targetFound) throw new PageProblem(`${what} names anchor #${link.fragment}, which is not on the page`);
      continue;
    }
    if (link.origin !== origin) throw new PageProblem(`${what} leaves the report: external link to ${link.url}`);
    if (!link.pathname.startsWith(directory)) throw new PageProblem(`${what} points outside the report directory`);
    const answer = await page.request.get(link.url.split('#')[0], { maxRedirects: 0, timeout: 30000 });
    fetched += 1;
    if (answer.status() !== 200) throw new PageProblem(`${what} answers HTTP ${answer.status()}`);
  }

  summary.push({ name, url, title: seen.title, size: pageSize, images: seen.images.length,
                 scaled_images: seen.images.filter((i) => i.scaledByStyle).length,
                 links: seen.links.length, in_page_anchors: seen.links.filter((l) => l.samePage).length,
                 files_linked: fetched,
                 console_errors: consoleMessages.filter((m) => m.type === 'error').map((m) => m.text),
                 console_messages: consoleMessages.length, screenshot: join(out, `${name}.png`),
                 seconds: (Date.now() - started) / 1000 });
  await context.close();
}

let browser, failure = null;
try {
  browser = await chromium.launch({
    executablePath: '/usr/bin/chromium', headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
           '--disable-sync', '--no-first-run', '--disable-quic', '--disable-extensions'] });
} catch (error) {
  console.error(`chromium cannot start: ${String(error.message || error).split('\n')[0]}`);
  process.exit(1);
}
for (const page of pages) {
  try {
    await checkPage(browser, page);
  } catch (error) {
    failure = `the ${page.name} page: ${error instanceof PageProblem ? error.message : String(error.message || error).split('\n')[0]}`;
    break;
  }
}
await browser.close();
await mkdir(out, { recursive: true });
await writeFile(join(out, 'results.json'), JSON.stringify({ pages: summary, failure }, null, 2));
console.log(JSON.stringify({ pages: summary, failure }));
if (failure) {
  console.error(failure.replace(/\s+/g, ' '));
  process.exit(1);
}
