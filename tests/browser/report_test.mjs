// Opens a Catena HTML report in headless Debian Chromium (driven by playwright-core from
// web/node_modules) as a person would: no console errors, no failed requests (the report must
// be self-contained), every chart rendered as a non-empty SVG, every drawing present; saves a
// full-page screenshot.
//
// usage: node report_test.mjs REPORT.html SCREENSHOT.png WEB_DIR [EXPECTED_SECTIONS]
import {createRequire} from 'node:module';
import {mkdtempSync, rmSync} from 'node:fs';
import {tmpdir} from 'node:os';
import path from 'node:path';
import {pathToFileURL} from 'node:url';

const [report, screenshot, webDir, expectedSections] = process.argv.slice(2);
if (!report || !screenshot || !webDir) {
  console.error('usage: node report_test.mjs REPORT.html SCREENSHOT.png WEB_DIR [SECTIONS]');
  process.exit(2);
}
const require = createRequire(path.join(path.resolve(webDir), 'package.json'));
const {chromium} = require('playwright-core');

const failures = [];
const profile = mkdtempSync(path.join(tmpdir(), 'catena-chromium-'));
let browser;
try {
  // a fresh profile directory (playwright passes it as --user-data-dir)
  browser = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CATENA_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run'],
    viewport: {width: 1280, height: 900},
  });
  const page = browser.pages()[0] || await browser.newPage();
  page.on('console', (m) => { if (m.type() === 'error') failures.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => failures.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => failures.push(`request failed: ${r.url()}`));
  page.on('request', (r) => {
    if (!r.url().startsWith('file:') && !r.url().startsWith('data:'))
      failures.push(`network request (the report must be self-contained): ${r.url()}`);
  });
  await page.goto(pathToFileURL(path.resolve(report)).href, {waitUntil: 'load'});

  const charts = await page.$$eval('div.chart', (divs) => divs.map((d) => ({
    id: d.id,
    svgs: d.querySelectorAll('svg.main-svg').length,
    traces: d.querySelectorAll('g.trace').length,
    width: d.getBoundingClientRect().width,
    height: d.getBoundingClientRect().height,
  })));
  if (charts.length === 0) failures.push('no charts in the report');
  for (const c of charts) {
    if (c.svgs === 0 || c.traces === 0 || c.width < 100 || c.height < 100)
      failures.push(`chart ${c.id} did not render: ${JSON.stringify(c)}`);
  }
  const sections = await page.$$eval('section.analysis', (s) => s.map((e) => e.id));
  if (expectedSections) {
    for (const id of expectedSections.split(',')) {
      if (!sections.includes(id)) failures.push(`section '${id}' missing (have ${sections})`);
    }
  }
  const drawings = await page.$$eval('div.drawing svg', (s) => s.map(
      (e) => e.getBoundingClientRect().width * e.getBoundingClientRect().height));
  for (const area of drawings) if (!(area > 0)) failures.push('a drawing has no area');
  const hash = await page.textContent('#case-hash');
  if (!/^[0-9a-f]{64}$/.test(hash || '')) failures.push(`case hash missing: '${hash}'`);

  await page.screenshot({path: screenshot, fullPage: true});
  console.log(`report ${report}: ${sections.length} analyses, ${charts.length} charts, ` +
              `${drawings.length} drawings; screenshot ${screenshot}`);
} catch (e) {
  failures.push(`browser: ${e.message}`);
} finally {
  if (browser) await browser.close();
  rmSync(profile, {recursive: true, force: true});
}
if (failures.length) {
  for (const f of failures) console.error(f);
  process.exit(1);
}
