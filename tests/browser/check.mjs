// The browser test (issue 45): every generated page opened from file:// in
// the system's Chromium, driven by playwright-core (no browser download).
// For each page: no request leaves it; without JavaScript every <math> has a
// nonzero rendered size; with it, → shows the next step and ← the previous,
// and (worked solutions) a wrong prediction is graded wrong and a right one
// right. Screenshots go to target/browser-artefacts/ (not committed).
//
//   node tests/browser/check.mjs            (from the repository's root)
//   CONTACT_LAB_BIN=path/to/contact-lab CHROMIUM=/usr/bin/chromium node …
import { chromium } from 'playwright-core';
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const root = resolve(new URL('../..', import.meta.url).pathname);
const target = process.env.CARGO_TARGET_DIR || join(root, 'target');
const bin = process.env.CONTACT_LAB_BIN || join(target, 'debug', 'contact-lab');
const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
const out = join(root, 'target', 'browser-artefacts');
mkdirSync(out, { recursive: true });

// The pages: [file name, command line, kind].
const pages = [
  ['solve-lecture-2.html', ['solve', 'lecture-2'], 'stages'],
  ['solve-lecture-3.html', ['solve', 'lecture-3'], 'stages'],
  ['solve-friction-cube.html', ['solve', 'friction-cube'], 'stages'],
  ['solve-box-four-corners-all.html', ['solve', 'box-four-corners', '--all-contacts'], 'stages'],
  ['resolve-box-four-corners.html', ['resolve', 'box-four-corners'], 'steps'],
  ['detect-epa-edge-edge.html', ['detect', 'epa-edge-edge'], 'detect'],
];

const flags = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) { failures += 1; }
}

async function browse(javaScriptEnabled, fn) {
  const dir = mkdtempSync(join(tmpdir(), 'contact-lab-chromium-'));
  const context = await chromium.launchPersistentContext(dir, {
    executablePath: chromiumPath, headless: true, args: flags, javaScriptEnabled,
    viewport: { width: 1280, height: 900 }, offline: true,
  });
  const left = [];
  // Nothing may leave the page: every request but the page's own file is
  // recorded and refused.
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:')) { return route.continue(); }
    left.push(url);
    return route.abort();
  });
  try {
    return await fn(context, left);
  } finally {
    await context.close();
    rmSync(dir, { recursive: true, force: true });
  }
}

async function visible(page) {
  return page.evaluate(() => Array.from(document.querySelectorAll('[data-step]'))
    .filter((s) => s.getBoundingClientRect().height > 0).map((s) => s.id));
}

for (const [name, args, kind] of pages) {
  const file = join(out, name);
  execFileSync(bin, [...args, '--format', 'html', '-o', file], { stdio: ['ignore', 'ignore', 'inherit'] });
  const url = pathToFileURL(file).href;
  const kb = (statSync(file).size / 1024).toFixed(0);
  console.log(`# ${name} (${kb} kB)`);

  await browse(false, async (context, left) => {
    const page = await context.newPage();
    await page.goto(url);
    const sizes = await page.evaluate(() => Array.from(document.querySelectorAll('math'))
      .map((m) => { const r = m.getBoundingClientRect(); return [r.width, r.height]; }));
    const empty = sizes.filter(([w, h]) => !(w > 0 && h > 0)).length;
    check((kind === 'detect' || sizes.length > 0) && empty === 0, `without JavaScript: ${sizes.length} <math> elements, ${empty} of zero size`);
    const steps = await visible(page);
    check(steps.length > 1, `without JavaScript every step shows (${steps.length})`);
    await page.screenshot({ path: file.replace(/\.html$/, '-plain.png'), fullPage: false });
    check(left.length === 0, `no request left the page (plain)${left.length ? ': ' + left.join(', ') : ''}`);
  });

  await browse(true, async (context, left) => {
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(url);
    const first = await visible(page);
    check(first.length === 1, `with JavaScript one step shows (${first.join(', ')})`);
    await page.keyboard.press('ArrowRight');
    const second = await visible(page);
    check(second.length === 1 && second[0] !== first[0], `→ shows the next step (${second.join(', ')})`);
    await page.keyboard.press('ArrowLeft');
    const back = await visible(page);
    check(back.length === 1 && back[0] === first[0], `← shows the previous step (${back.join(', ')})`);
    await page.click('[data-go="next"]');
    check((await visible(page))[0] === second[0], 'the Next button shows the next step');
    if (kind === 'stages') {
      // The first stage with a result to predict (lecture-2: the contact
      // frame's t0), through the stage list: wrong, then right.
      const stage = await page.evaluate(() => document.querySelector('.formula[data-answer]').closest('[data-step]').id);
      await page.click(`nav.steps a[href="#${stage}"]`);
      await page.check('#predict');
      const formula = page.locator('[data-step].current .formula[data-answer]').first();
      const hidden = await formula.locator('.result').evaluate((e) => getComputedStyle(e).visibility);
      check(hidden === 'hidden', `predict mode hides the result (${hidden})`);
      const input = page.locator('[data-step].current .guess input').first();
      await input.fill('12345');
      await input.press('Enter');
      const wrong = page.locator('[data-step].current .guess output').first();
      check(await wrong.evaluate((e) => e.className) === 'wrong', `a wrong prediction is graded wrong: ${await wrong.textContent()}`);
      const shown = await formula.getAttribute('data-shown');
      await input.fill(shown);
      await input.press('Enter');
      check(await wrong.evaluate((e) => e.className) === 'right', `the right value (${shown}) is graded right`);
      await page.screenshot({ path: file.replace(/\.html$/, '-predict.png'), fullPage: false });
    } else if (kind === 'detect') {
      // The first iteration: its Minkowski picture shows.
      const figure = page.locator('[data-step].current svg.figure');
      check(await figure.count() === 1 && await figure.isVisible(), 'an iteration shows its Minkowski picture');
    } else {
      const row = page.locator('[data-step].current tr[data-open]').first();
      if (await row.count()) {
        const panel = await row.getAttribute('data-open');
        await row.focus();
        await page.keyboard.press('Enter');
        const open = await page.locator(`[id="${panel}"]`).isVisible();
        check(open, `Enter on a contact row opens its stages (${panel})`);
        const n = await page.locator(`[id="${panel}"] math`).count();
        check(n > 0, `the opened stages have their formulas (${n} <math>)`);
      } else {
        check(false, 'an iteration with a contact row to open');
      }
    }
    await page.screenshot({ path: file.replace(/\.html$/, '.png'), fullPage: false });
    check(errors.length === 0, `no script error${errors.length ? ': ' + errors.join('; ') : ''}`);
    check(left.length === 0, `no request left the page${left.length ? ': ' + left.join(', ') : ''}`);
  });
}

console.log(failures ? `${failures} check(s) failed` : 'every check passed');
process.exit(failures ? 1 : 0);
