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
  ['detect-toi-bullet-wall.html', ['detect', 'bullet-wall', '--toi'], 'toi'],
  ['simulate-stack-5.html', ['simulate', 'stack-5', '--steps', '120', '--every', '2', '--trace-step', '30'], 'player'],
  ['study-ball-drop.html', ['study', 'ball-drop', '--quick', '--no-timing', '--seconds', '0.5'], 'study'],
];
// The step-at-a-time pages (← → and the Next button).
const stepped = ['stages', 'steps', 'detect', 'toi'];

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
    check((!['stages', 'steps'].includes(kind) || sizes.length > 0) && empty === 0, `without JavaScript: ${sizes.length} <math> elements, ${empty} of zero size`);
    const steps = await visible(page);
    if (stepped.includes(kind)) {
      check(steps.length > 1, `without JavaScript every step shows (${steps.length})`);
    } else if (kind === 'player') {
      const film = await page.locator('#film svg.figure').isVisible();
      const player = await page.locator('#player').isVisible();
      const events = await page.locator('ol.events li').count();
      check(film && !player && events > 0, `without JavaScript the film strip (${film}) and ${events} events show, the player hides (${player})`);
    } else {
      const sorted = await page.locator('table.sortable button.sort').count();
      check(sorted === 0 && await page.locator('table.sortable').first().isVisible(), 'without JavaScript the tables are plain');
    }
    await page.screenshot({ path: file.replace(/\.html$/, '-plain.png'), fullPage: false });
    check(left.length === 0, `no request left the page (plain)${left.length ? ': ' + left.join(', ') : ''}`);
  });

  await browse(true, async (context, left) => {
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(url);
    if (kind === 'player') {
      await player(page, file);
    } else if (kind === 'study') {
      await study(page);
    } else {
      await stepping(page, kind, file);
    }
    await page.screenshot({ path: file.replace(/\.html$/, '.png'), fullPage: false });
    check(errors.length === 0, `no script error${errors.length ? ': ' + errors.join('; ') : ''}`);
    check(left.length === 0, `no request left the page${left.length ? ': ' + left.join(', ') : ''}`);
  });
}

// The player: the step button advances the frame counter and moves a body;
// play runs the frames on, pause stops them; an event goes to its frame; the
// traced step's iterations open one at a time.
async function player(page, file) {
  const counter = page.locator('.frame-counter');
  const bodies = () => page.locator('svg.stage g.moving').innerHTML();
  const cursor = () => page.locator('svg.energy line.cursor').getAttribute('x1');
  const c0 = await counter.textContent();
  const b0 = await bodies();
  const x0 = await cursor();
  check(/^frame 1 of \d+/.test(c0), `the counter starts at the first frame (${c0})`);
  for (let i = 0; i < 10; i++) { await page.click('button[aria-label="step"]'); }
  const c1 = await counter.textContent();
  check(/^frame 11 of /.test(c1), `ten steps advance the frame counter (${c1})`);
  check(await bodies() !== b0, 'stepping moves a body');
  check(await cursor() !== x0, `the energy chart's cursor moves (${x0} → ${await cursor()})`);
  await page.click('button[aria-label="step back"]');
  check(/^frame 10 of /.test(await counter.textContent()), 'step back goes back one frame');
  // A quarter of real time: the run goes on well after the frame moves.
  await page.selectOption('select[aria-label="speed"]', '0.25');
  await page.click('button[aria-label="play"]');
  await page.waitForFunction(() => !/^frame 10 of/.test(document.querySelector('.frame-counter').textContent));
  await page.click('button[aria-label="pause"]');
  const paused = await counter.textContent();
  const n = (t) => Number(/^frame (\d+)/.exec(t)[1]);
  check(n(paused) > 10, `play runs the frames on (${paused})`);
  await page.waitForTimeout(400);
  check(await counter.textContent() === paused, 'pause holds the frame');
  await page.locator('input[aria-label="frame"]').fill('0');
  check(/^frame 1 of /.test(await counter.textContent()), 'the scrub bar goes to a frame');
  const link = page.locator('ol.events a[data-frame]').last();
  const to = Number(await link.getAttribute('data-frame'));
  await link.click();
  check(n(await counter.textContent()) === to + 1, `an event goes to its frame (${to + 1})`);
  await page.click('button[aria-label="open iterations"]');
  const open = await page.locator('#trace').evaluate((d) => d.open);
  const shown = await page.locator('#trace [data-step]').evaluateAll((s) => s.filter((x) => x.getBoundingClientRect().height > 0).length);
  check(open && shown === 1, `the traced step's iterations open, one shown (${shown})`);
  await page.click('#trace button[aria-label="next iteration"]');
  check(await page.locator('#trace .it-where').textContent().then((t) => / \(2 of \d+\)$/.test(t)), 'next iteration shows the second');
  await page.screenshot({ path: file.replace(/\.html$/, '-iterations.png'), fullPage: false });
  await page.locator('#player').scrollIntoViewIfNeeded();
}

// The study: a column heading sorts its table, again reverses it.
async function study(page) {
  const column = async (k) => page.locator('table.sortable').first().locator('tbody tr')
    .evaluateAll((rows, k) => rows.map((r) => Number(r.cells[k].getAttribute('data-sort'))), k);
  const heads = await page.locator('table.sortable').first().locator('thead th').allTextContents();
  const k = heads.indexOf('work/s');
  check(k >= 0, `a work/s column (${heads.join(' | ')})`);
  await page.locator('table.sortable').first().locator('th button.sort').nth(k).click();
  const up = await column(k);
  check(up.every((x, i) => i === 0 || up[i - 1] <= x), `work/s sorts ascending (${up.join(', ')})`);
  await page.locator('table.sortable').first().locator('th button.sort').nth(k).click();
  const down = await column(k);
  check(down.every((x, i) => i === 0 || down[i - 1] >= x), 'again: descending');
  const tips = await page.locator('svg.figure g.tip title').count();
  check(tips > 0, `the chart's marks carry hover details (${tips})`);
}

// A step-at-a-time page: → and ← and the Next button; then what the kind adds.
async function stepping(page, kind, file) {
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
    } else if (kind === 'toi') {
      // A test: its time line shows; the result: the pair's picture.
      const line = page.locator('[data-step].current svg.timeline');
      check(await line.count() === 1 && await line.isVisible(), 'a test shows its time line');
      await page.goto(page.url().replace(/#.*$/, '') + '#p0-result');
      await page.reload();
      const picture = page.locator('[data-step].current svg.figure');
      check(await picture.count() === 1 && await picture.isVisible(), "the pair's result shows its picture");
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
}

console.log(failures ? `${failures} check(s) failed` : 'every check passed');
process.exit(failures ? 1 : 0);
