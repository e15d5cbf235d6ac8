// The built manual as a reader meets it, in headless Chromium (Debian's),
// opened from its files, in each language:
//  - every page is reached from the first by links; every internal link
//    leads to a file that exists, and to an element of it when it names one;
//  - every image loads and is not blank (not one colour all over);
//  - "next" walks the whole book in order and "previous" walks it back;
//  - the language switch opens the same page in the other language;
//  - the search box finds a chapter by a word of it;
// and screenshots of the first page and of an algorithm chapter are saved
// in OUTPUT/screenshots.
//
//   node browser_test.mjs build/manual
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL, fileURLToPath } from 'node:url';

const LANGUAGES = { en: 'pt_BR', pt_BR: 'en' };
const CHAPTER = 'algorithms/scanline.html';
// A word of each language that its search box must find a chapter by.
const SEARCHES = { en: ['Catmull', 'algorithms/z-buffer.html'], pt_BR: ['arestas', 'algorithms/scanline.html'] };

const output = path.resolve(process.argv[2] ?? 'build/manual');
const results = { passed: 0, failures: [] };

function check(condition, what) {
  if (condition) results.passed += 1;
  else results.failures.push(what);
}

const fileOf = (url) => fileURLToPath(url.split('#')[0].split('?')[0]);
const urlOf = (file) => pathToFileURL(file).href;
const relative = (file) => path.relative(output, file);

// Every link, image and element id of the page open in `page`.
async function readPage(page) {
  return page.evaluate(async () => {
    const images = await Promise.all(
      [...document.images].map(async (image) => {
        if (!image.complete) await new Promise((done) => { image.onload = image.onerror = done; });
        if (!image.naturalWidth) return { src: image.src, problem: 'did not load' };
        const canvas = document.createElement('canvas');
        canvas.width = image.naturalWidth;
        canvas.height = image.naturalHeight;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        const pixels = context.getImageData(0, 0, canvas.width, canvas.height).data;
        let lowest = 765;
        let highest = 0;
        for (let i = 0; i < pixels.length; i += 4) {
          const value = pixels[i] + pixels[i + 1] + pixels[i + 2];
          lowest = Math.min(lowest, value);
          highest = Math.max(highest, value);
        }
        return { src: image.src, problem: highest - lowest < 12 ? 'is blank' : null };
      }),
    );
    return {
      // Links, and the stylesheets, scripts and next/previous links of the head.
      links: [
        ...[...document.querySelectorAll('a[href], link[href]')].map((element) => element.href),
        ...[...document.querySelectorAll('script[src]')].map((script) => script.src),
      ],
      ids: [...document.querySelectorAll('[id]')].map((element) => element.id),
      images,
    };
  });
}

// Opens every page reachable from the first; checks links, anchors, images.
async function crawl(page, language) {
  const root = path.join(output, language);
  const start = path.join(root, 'index.html');
  const seen = new Map();
  const anchors = [];
  const queue = [start];
  while (queue.length) {
    const file = queue.shift();
    if (seen.has(file)) continue;
    await page.goto(urlOf(file));
    const content = await readPage(page);
    seen.set(file, new Set(content.ids));
    for (const image of content.images)
      check(!image.problem, `${relative(file)}: the image ${image.src} ${image.problem}`);
    for (const link of content.links) {
      if (!link.startsWith('file:')) continue;
      const target = fileOf(link);
      check(fs.existsSync(target), `${relative(file)}: the link ${link} leads to no file`);
      const fragment = decodeURIComponent(new URL(link).hash.slice(1));
      if (fragment) anchors.push([file, target, fragment]);
      // The other language's pages are checked to exist, and crawled in their turn.
      if (target.endsWith('.html') && target.startsWith(root + path.sep) && fs.existsSync(target)) queue.push(target);
    }
  }
  for (const [from, target, fragment] of anchors)
    if (seen.has(target))
      check(seen.get(target).has(fragment), `${relative(from)}: no #${fragment} in ${relative(target)}`);
  const pages = fs.readdirSync(root, { recursive: true }).filter((name) => name.endsWith('.html'));
  // The search page is reached through the search box, not by a link.
  for (const name of pages.filter((page) => page !== 'search.html'))
    check(seen.has(path.join(root, name)), `${language}/${name} is not reached from the first page`);
  return pages;
}

// Follows a link chosen by `selector` from page to page until there is none.
async function walk(page, file, selector) {
  const visited = [file];
  await page.goto(urlOf(file));
  for (;;) {
    const link = page.locator(selector).first();
    if (!(await link.count())) return visited;
    await Promise.all([page.waitForURL((url) => fileOf(url.href) !== visited.at(-1)), link.click()]);
    visited.push(fileOf(page.url()));
    if (visited.length > 500) throw new Error(`${selector} goes round in circles`);
  }
}

async function previousAndNext(page, language, pages) {
  const forward = await walk(page, path.join(output, language, 'index.html'), 'a.next-page');
  const backward = await walk(page, forward.at(-1), 'a.prev-page');
  check(
    JSON.stringify([...backward].reverse()) === JSON.stringify(forward),
    `${language}: "previous" does not walk back the way "next" came`,
  );
  const book = pages.filter((name) => name !== 'search.html');
  check(forward.length === book.length, `${language}: "next" visits ${forward.length} of the book's ${book.length} pages`);
}

async function languageSwitch(page, language) {
  const other = LANGUAGES[language];
  await page.goto(urlOf(path.join(output, language, CHAPTER)));
  const link = page.locator(`.rise-languages a[hreflang="${other.replace('_', '-')}"]`);
  check((await link.count()) === 1, `${language}/${CHAPTER}: no link to the ${other} page`);
  if (!(await link.count())) return;
  await Promise.all([page.waitForURL(/./), link.click()]);
  await page.waitForLoadState();
  check(fileOf(page.url()) === path.join(output, other, CHAPTER), `${language}: the switch opened ${page.url()}`);
  const lang = await page.getAttribute('html', 'lang');
  check(lang?.replace('-', '_').startsWith(other.slice(0, 2)), `${other}/${CHAPTER}: <html lang="${lang}">`);
}

async function search(page, language) {
  const [word, expected] = SEARCHES[language];
  await page.goto(urlOf(path.join(output, language, 'index.html')));
  await page.fill('input.sidebar-search', word);
  await Promise.all([page.waitForURL(/search\.html/), page.press('input.sidebar-search', 'Enter')]);
  const hits = page.locator('#search-results ul.search li a');
  await hits.first().waitFor({ timeout: 15000 }).catch(() => {});
  const found = await hits.evaluateAll((links) => links.map((a) => a.href));
  check(found.some((href) => fileOf(href) === path.join(output, language, expected)),
    `${language}: searching for "${word}" does not find ${expected} (found ${found.length} pages)`);
}

async function screenshots(page, language) {
  const folder = path.join(output, 'screenshots');
  fs.mkdirSync(folder, { recursive: true });
  for (const [name, file] of [['first-page', 'index.html'], ['scanline', CHAPTER]]) {
    await page.goto(urlOf(path.join(output, language, file)));
    const shot = path.join(folder, `${language}-${name}.png`);
    await page.screenshot({ path: shot, fullPage: name === 'first-page' });
    check(fs.statSync(shot).size > 10000, `${shot} is nearly empty`);
  }
}

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: [
    '--no-sandbox', '--headless', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run',
    // Lets the pages read their own images (file: pages are of no origin).
    '--allow-file-access-from-files',
  ],
});
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  page.on("pageerror", (error) => check(false, `${page.url()}: ${error.stack}`));
  for (const language of Object.keys(LANGUAGES)) {
    const pages = await crawl(page, language);
    console.log(`${language}: ${pages.length} pages crawled`);
    await previousAndNext(page, language, pages);
    await languageSwitch(page, language);
    // Before the search, whose words Sphinx then highlights on every page.
    await screenshots(page, language);
    await search(page, language);
  }
} finally {
  await browser.close();
}
for (const failure of results.failures) console.log(`FAILED ${failure}`);
console.log(`${results.passed} passed, ${results.failures.length} failed`);
process.exit(results.failures.length || !results.passed ? 1 : 0);
