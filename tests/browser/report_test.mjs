// Opens a Catena HTML report in headless Debian Chromium (driven by playwright-core from
// web/node_modules) as a person would: no console errors, no failed requests (the report must
// be self-contained), every chart rendered as a non-empty SVG, every drawing present; saves a
// full-page screenshot.
//
// usage: node report_test.mjs REPORT.html SCREENSHOT.png WEB_DIR [EXPECTED_SECTIONS] [TRACES]
// TRACES: 'section=name|name;…' — a chart of that section draws a curve of each name (legend)
import {createRequire} from 'node:module';
import {mkdtempSync, rmSync, statSync} from 'node:fs';
import {tmpdir} from 'node:os';
import path from 'node:path';
import {pathToFileURL} from 'node:url';

const [report, screenshot, webDir, expectedSections, expectedTraces] = process.argv.slice(2);
if (!report || !screenshot || !webDir) {
  console.error('usage: node report_test.mjs REPORT.html SCREENSHOT.png WEB_DIR [SECTIONS]');
  process.exit(2);
}
const require = createRequire(path.join(path.resolve(webDir), 'package.json'));
const {chromium} = require('playwright-core');

const failures = [];
// the embedded chart library is Plotly's partial bundle (scatter, bar, pie: ~1.1 MB), not the
// full one with maps and 3-D (4.6 MB)
const bytes = statSync(report).size;
if (bytes > 2_000_000) failures.push(`report is ${bytes} bytes: is the full Plotly bundle embedded?`);
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
  for (const spec of (expectedTraces || '').split(';').filter((x) => x)) {
    const [id, names] = spec.split('=');
    // the legend entries Plotly drew in the section's charts
    const drawn = await page.$$eval(`section[id="${id}"] div.chart`, (divs) => divs.map((d) => ({
      traces: d.querySelectorAll('g.trace').length,
      legend: Array.from(d.querySelectorAll('g.legend text.legendtext')).map((t) => t.textContent),
    })));
    const wanted = names.split('|');
    const found = drawn.some((c) => wanted.every((n) => c.legend.includes(n)) &&
                                   c.traces >= wanted.length);
    if (!found)
      failures.push(`section '${id}': no chart draws ${wanted.join(', ')} (have ${JSON.stringify(drawn)})`);
  }
  const drawings = await page.$$eval('div.drawing svg', (s) => s.map(
      (e) => e.getBoundingClientRect().width * e.getBoundingClientRect().height));
  for (const area of drawings) if (!(area > 0)) failures.push('a drawing has no area');
  // a wide table scrolls inside its card instead of running out of it
  const overflowing = await page.$$eval('main section', (s) => s.filter(
      (e) => e.scrollWidth > e.clientWidth + 1).map((e) => e.id));
  for (const id of overflowing) failures.push(`section '${id}' is wider than its card`);
  // the findings card lists what it counts, each with a link to a section that exists
  const findings = await page.$$eval('#summary ul.findings li a', (as) => as.map(
      (a) => a.getAttribute('href')));
  for (const href of findings) {
    if (!(await page.$(href))) failures.push(`finding links to ${href}, which is not in the page`);
  }
  const hash = await page.textContent('#case-hash');
  if (!/^[0-9a-f]{64}$/.test(hash || '')) failures.push(`case hash missing: '${hash}'`);

  await page.screenshot({path: screenshot, fullPage: true});
  console.log(`report ${report} (${bytes} bytes): ${sections.length} analyses, ` +
              `${charts.length} charts, ${drawings.length} drawings, ${findings.length} ` +
              `findings; screenshot ${screenshot}`);
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
