// Browser test of the page's estimated error (issue 14; Debian's Chromium, headless,
// SwiftShader):
//
//   node tests/browser/error_test.mjs [--web build/web] [--out build/browser-test]
//
// Serves the web build (tools/serve.mjs) and checks, on scene2 (the Cornell box) at
// 128x128: the panel's estimated relMSE appears and falls as samples grow (at 4x the
// samples, well below the earlier value: it falls about as 1/n); with &target=X set to a
// value the first page reached, the sample count stops growing with the estimate at or
// below X, and the address keeps &target=; no console errors. Prints the cost of one
// estimate (read-backs and sums) at 128x128 and at 960x640 (the canvas, the closed room). Screenshots go
// to the out folder. 'ok - NAME' / 'not ok - NAME: why', then a summary.
import { mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { check, launcher, options, run, startServer } from "./app_lib.mjs";

const { webDir, outDir } = options("error_test.mjs", []);
mkdirSync(outDir, { recursive: true });
const shot = (page, name) => page.screenshot({ path: join(outDir, `error-${name}.png`) });

async function openPage(context, url, errors) {
  const page = await context.newPage();
  page.on("console", (m) => { if (m.type() === "error") errors.push(`console: ${m.text()}`); });
  page.on("pageerror", (e) => errors.push(`page error: ${e.message}`));
  await page.goto(url);
  await page.waitForFunction(() => { try { return window.ptLoadStatus() !== null; } catch { return false; } }, null,
                             { timeout: 60000, polling: 200 });
  return page;
}
// ptLoadStatus: the estimate's fields without reading the image back (ptStats does).
const status = (page) => page.evaluate(() => window.ptLoadStatus());
const until = (page, fn, arg, timeout = 120000) => page.waitForFunction(fn, arg, { timeout, polling: 100 });
const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];

const scene = "reference/scene2.xml";

// The readout appears and falls; returns a value the page reached (the next test's target).
async function readout(context, url) {
  const errors = [];
  const page = await openPage(context, `${url}?scene=${scene}&size=128x128`, errors);
  await until(page, () => { const s = window.ptLoadStatus(); return s.relMSE !== null && s.relMSESamples >= 4; });
  const first = await status(page);
  await until(page, (n) => window.ptLoadStatus().relMSESamples >= 4 * n, first.relMSESamples);
  const later = await status(page);
  await shot(page, "readout");
  const h = later.errorHistory;
  console.log(`# estimated relMSE at 128x128: ${h.map(([t, e, n]) => `${n} spp ${e.toPrecision(3)} (${t.toFixed(1)} s)`).join(", ")}`);
  console.log(`# one estimate at 128x128: ${later.estimateMs.toFixed(1)} ms (the last of ${later.estimates})`);
  check("the estimated relMSE appears once there are samples", first.relMSE > 0 && Number.isFinite(first.relMSE),
        JSON.stringify({ relMSE: first.relMSE, samples: first.relMSESamples }));
  // The error of a mean falls as 1/n: at 4x the samples about a quarter; 0.6 leaves room
  // for the estimate's own noise and still fails an estimate that does not fall.
  check("the estimate falls as samples grow", later.relMSE < 0.6 * first.relMSE,
        `${first.relMSE} at ${first.relMSESamples} spp, ${later.relMSE} at ${later.relMSESamples} spp`);
  const falling = h.every((p, i) => i === 0 || p[0] >= h[i - 1][0]) && h[h.length - 1][1] < h[0][1];
  check("the plotted history runs forward in time and ends lower", falling, JSON.stringify(h));
  check("no console errors (readout)", errors.length === 0, errors.join("; "));
  await page.close();
  return later.relMSE;
}

// With &target=X, rendering stops once the estimate is at or below X.
async function target(context, url, x) {
  const errors = [];
  const page = await openPage(context, `${url}?scene=${scene}&size=128x128&target=${x.toPrecision(4)}`, errors);
  const t = Number(x.toPrecision(4));
  let reached = true;
  await until(page, () => window.ptLoadStatus().targetReachedAt > 0, null, 180000).catch(() => { reached = false; });
  const at = await status(page);
  await sleep(3000);
  const after = await status(page);
  await shot(page, "target");
  const search = await page.evaluate(() => location.search);
  console.log(`# target ${t}: reached at ${at.targetReachedAt} spp with ${at.relMSE}; ${after.samples} spp 3 s later`);
  check("the target is read from the address", at.targetRelMSE === t || Math.abs(at.targetRelMSE / t - 1) < 1e-6,
        `targetRelMSE ${at.targetRelMSE}, asked ${t}`);
  check("with a reachable target the samples stop growing", reached && after.samples === at.samples &&
        after.samples === at.targetReachedAt, JSON.stringify({ reached, at: at.samples, after: after.samples, stop: at.targetReachedAt }));
  check("the estimate where it stopped is at or below the target", reached && after.relMSE <= t, `${after.relMSE} > ${t}`);
  check("the address keeps the target", /[?&]target=/.test(search), search);
  check("no console errors (target)", errors.length === 0, errors.join("; "));
  await page.close();
}

// The cost at the canvas's size: the median of the estimates the page made. The cost is
// the image's size, not the scene's: the closed room at one bounce samples fast enough.
async function cost(context, url) {
  const errors = [];
  const page = await openPage(context, `${url}?scene=analytic/closed-room.xml&bounces=1&size=960x640`, errors);
  const costs = [];
  let seen = 0;
  const t0 = Date.now();
  while (costs.length < 5 && Date.now() - t0 < 90000) {
    const s = await status(page);
    if (s.estimates > seen) {
      seen = s.estimates;
      costs.push(s.estimateMs);
    }
    await sleep(100);
  }
  const s = await status(page);
  console.log(`# one estimate at 960x640: median ${costs.length ? median(costs).toFixed(1) : "?"} ms of ${costs.length} ` +
              `(${costs.map((c) => c.toFixed(1)).join(", ")}), at ${s.samples} spp`);
  await shot(page, "960x640");
  check("estimates at 960x640 (their cost printed)", costs.length >= 2, `${costs.length} estimates in 90 s`);
  check("no console errors (960x640)", errors.length === 0, errors.join("; "));
  await page.close();
}

async function main() {
  const server = await startServer([webDir, "0"]);
  const userDir = mkdtempSync(join(tmpdir(), "pt-chromium-"));
  try {
    const context = await launcher(userDir)({ viewport: { width: 960, height: 640 } });
    const reached = await readout(context, server.url);
    await target(context, server.url, reached * 1.5);
    await cost(context, server.url);
    await context.close();
  } finally {
    server.child.kill();
    rmSync(userDir, { recursive: true, force: true });
  }
}

await run(main);
