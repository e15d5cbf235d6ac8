// The step player as a teacher uses it, in headless Chromium (Debian's),
// opened from its files: it loads without an error, steps forward and back,
// plays and pauses, and after its last step shows the rendered image and
// counts every pixel final that every step, shown or not, made final.
//
//   node step_player_test.mjs PLAYER_FOLDER...
import { chromium } from 'playwright-core';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const failures = [];
function check(condition, what) {
  if (!condition) failures.push(what);
}

const counter = (page) => page.textContent('#counter');

// The pixels of an image of the page's folder, as the page's canvas reads them.
async function pixelsOf(page, source) {
  return page.evaluate(async (src) => {
    const image = new Image();
    image.src = src;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.naturalWidth;
    canvas.height = image.naturalHeight;
    canvas.getContext('2d').drawImage(image, 0, 0);
    return Array.from(canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data);
  }, source);
}

async function testPlayer(page, folder) {
  const name = path.basename(folder);
  const errors = [];
  page.removeAllListeners('pageerror');
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(pathToFileURL(path.join(folder, 'index.html')).href);
  const total = Number((await counter(page)).match(/of (\d+)/)[1]);
  check(total > 1, `${name}: ${total} steps`);
  check((await counter(page)).startsWith('step 1 of'), `${name}: starts at ${await counter(page)}`);
  const firstText = await page.textContent('#text');
  await page.click('#next');
  check((await counter(page)).startsWith('step 2 of'), `${name}: next gave ${await counter(page)}`);
  check((await page.textContent('#text')) !== firstText || total < 3, `${name}: next kept the text`);
  await page.click('#previous');
  check((await counter(page)).startsWith('step 1 of'), `${name}: previous gave ${await counter(page)}`);
  await page.selectOption('#speed', '40');
  await page.click('#play');
  await page.waitForTimeout(600);
  await page.click('#play');
  const played = Number((await counter(page)).match(/step (\d+)/)[1]);
  check(played > 3, `${name}: playing reached step ${played}`);
  await page.waitForTimeout(300);
  check(Number((await counter(page)).match(/step (\d+)/)[1]) === played, `${name}: pause did not stop`);
  await page.keyboard.press('End');
  check((await counter(page)) === `step ${total} of ${total}`, `${name}: End gave ${await counter(page)}`);
  const last = await page.getAttribute('#frame', 'src');
  const [shown, rendered] = [await pixelsOf(page, last), await pixelsOf(page, 'image.png')];
  let differing = 0;
  for (let i = 0; i < rendered.length; i += 4)
    if (Math.abs(shown[i] - rendered[i]) + Math.abs(shown[i + 1] - rendered[i + 1]) +
        Math.abs(shown[i + 2] - rendered[i + 2]) > 3) differing += 1;
  check(shown.length === rendered.length && differing === 0,
        `${name}: the last frame differs from the image at ${differing} pixels`);
  // What the counts say at the end is of every step, shown or not.
  const final = (await page.textContent('#sofar')).match(/(\d+) pixels final/);
  check(!final || Number(final[1]) === rendered.length / 4,
        `${name}: the last step says ${final && final[1]} pixels final of ${rendered.length / 4}`);
  await page.screenshot({ path: path.join(folder, 'player.png') });
  check(errors.length === 0, `${name}: page errors: ${errors.join('; ')}`);
}

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--no-sandbox', '--headless', '--disable-gpu', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--no-first-run',
         // Lets the test read the page's images (file: pages are of no origin).
         '--allow-file-access-from-files'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1300, height: 950 } });
  for (const folder of process.argv.slice(2)) await testPlayer(page, path.resolve(folder));
} finally {
  await browser.close();
}
for (const failure of failures) console.log(`FAILED: ${failure}`);
console.log(`${process.argv.length - 2} players, ${failures.length} failures`);
process.exit(failures.length ? 1 : 0);
