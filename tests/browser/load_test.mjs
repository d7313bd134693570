// Browser test of the page's loading and pacing (Debian's Chromium, headless, SwiftShader):
//   node tests/browser/load_test.mjs [--web build/web] [--site build/site] [--out build/browser-test]
//                                    [--only responsiveness,large,site]
// (PT_DUMP_INTERVALS=1: also print every frame interval of the responsiveness window)
// Checks: frames slower than 30/s while rendering shrink the draws below a band of 4 rows
// (and prints the UI frame rate with the sample limit reached and while rendering, the
// draw size the pacing settled on, samples/s, and the GPU time per frame where
// EXT_disjoint_timer_query_webgl2 exists); loading a 1.3-million-triangle scene keeps the
// animation frames coming (its longest gap is bounded) and shows its progress while the
// previous scene keeps rendering; build/site (tools/site.sh) served from a sub-path
// renders. 'ok - NAME' / 'not ok - NAME: why', then a summary. Helpers: app_lib.mjs.
import { existsSync, mkdirSync, mkdtempSync, renameSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { camOf, check, checkWebBuild, launcher, liveScene, openPage, options, put, quad, run, shot as shotIn, startServer, stats, until } from "./app_lib.mjs";

const { groups, webDir, siteDir, outDir } = options("load_test.mjs", ["responsiveness", "large", "site"]);
const shot = (page, name) => shotIn(page, name, outDir);
// Loading scenes/bench/million.xml: the longest gap between animation frames (every step
// of the load is sliced, the mesh's generation included; what remains is a slice, a drawn
// frame and the machine's other jobs: docs/benchmarks.md; the blocking build gave 11.8 s),
// and the whole load (9-37 s on the shared 2-core machine).
const kLargeLoadGapMs = 2500;
const kLargeLoadMs = 60000;

// UI frames per second over `ms` (animation frames), the longest frame and, with
// EXT_disjoint_timer_query_webgl2, the GPU time of the frames (a query around everything
// the page draws between two animation frames).
function uiFrames(page, ms) {
  return page.evaluate((ms) => new Promise((done) => {
    const gl = document.getElementById("canvas").getContext("webgl2");
    const ext = gl.getExtension("EXT_disjoint_timer_query_webgl2");
    const queries = [], gpu = [];
    let frames = 0, worst = 0, last = performance.now();
    const t0 = last, intervals = [], draws = [];
    const tick = () => {
      const now = performance.now();
      draws.push(window.ptLoadStatus().drawPixels);  // the pacer's draw this frame (the page's callback ran first)
      worst = Math.max(worst, now - last);
      intervals.push(now - last);
      last = now;
      frames++;
      if (ext) {  // end the previous frame's query, start this one's (rAF callbacks run before the page's)
        if (queries.length && queries[queries.length - 1].open) { gl.endQuery(ext.TIME_ELAPSED_EXT); queries[queries.length - 1].open = false; }
        const q = gl.createQuery();
        gl.beginQuery(ext.TIME_ELAPSED_EXT, q);
        queries.push({ q, open: true });
        for (const x of queries) if (!x.done && !x.open && gl.getQueryParameter(x.q, gl.QUERY_RESULT_AVAILABLE)) {
          x.done = true;
          if (!gl.getParameter(ext.GPU_DISJOINT_EXT)) gpu.push(gl.getQueryParameter(x.q, gl.QUERY_RESULT) / 1e6);
        }
      }
      if (now - t0 < ms) requestAnimationFrame(tick);
      else {
        if (ext && queries[queries.length - 1].open) gl.endQuery(ext.TIME_ELAPSED_EXT);
        const gpuMs = gpu.length ? gpu.reduce((a, b) => a + b, 0) / gpu.length : NaN;
        done({ fps: frames * 1000 / (now - t0), worst, gpuMs, queries: gpu.length, timer: !!ext, intervals, draws });
      }
    };
    requestAnimationFrame(tick);
  }), ms);
}
const gpuText = (r) => r.timer ? `GPU time per frame ${r.gpuMs.toFixed(1)} ms (${r.queries} timer queries)` : "no timer query extension";

// The page at the viewport's size with scene2: the UI frame rate once the sample limit is
// reached (nothing but the panel and the image's display: the fixed cost of a frame; one
// bounce, so that the first sample comes sooner), then while rendering without limit,
// with the draw size the pacing settled on.
async function responsiveness(context, url) {
  const errors = [];
  let page = await openPage(context, `${url}?scene=reference/scene2.xml&bounces=1&limit=1`, errors);
  await until(page, () => window.ptLoadStatus().samples >= 1, null, 180000);
  await page.waitForTimeout(1000);
  const idle = await uiFrames(page, 3000);
  await page.close();
  page = await openPage(context, `${url}?scene=reference/scene2.xml&limit=0`, errors);
  await page.waitForTimeout(5000);
  const r = await uiFrames(page, 4000);
  const s = await stats(page);
  if (process.env.PT_DUMP_INTERVALS) console.log("# intervals " + r.intervals.map((x) => x.toFixed(0)).join(" "));
  const draw = s.bandRows ? `${s.bandRows} row(s)` + (s.bandColumns ? ` x ${s.bandColumns} columns` : "") : `${s.height} rows`;
  console.log(`# chromium scene2 ${s.width}x${s.height}, sample limit reached: ${idle.fps.toFixed(1)} UI frames/s ` +
              `(worst frame ${idle.worst.toFixed(0)} ms), ${gpuText(idle)}`);
  console.log(`# chromium scene2 ${s.width}x${s.height}, rendering: ${r.fps.toFixed(1)} UI frames/s (worst frame ${r.worst.toFixed(0)} ms), ` +
              `${s.samplesPerSecond.toFixed(2)} spp/s, ${s.passesPerFrame} draw(s) per frame of ${draw}; ${gpuText(r)}`);
  // Not a frame-rate bound (a loaded machine would fail it), but what the pacing must do
  // about slow frames: no draw of a band of 4 rows or more (the previous pacing stopped
  // there, at 10-15 frames/s on this machine) is kept through six frames whose mean
  // interval is over the pacer's line. That is the pacer's own rule (render/pacing.cpp: the
  // mean of kJudgeFrames = 6 intervals at one draw size, the first after a change not
  // counted), checked on every such window of the 4 s, from each frame's interval and
  // draw. (The window's frame rate against the draw at its end was checked until
  // 2026-12-07; at a mean near the line the pacer shrinks and grows again, and that check
  // failed CI at 29.3 UI frames/s with 8-row draws at the end.) The one
  // exception is the pacer's floor (render/pacing.cpp, judge_shrink): when frames stay
  // slow at the smallest draw, the frame's fixed cost is what makes them slow and the draw
  // goes back up; that needs frames without any draw (the idle page above) to be slow too.
  const fixedCostSlow = idle.fps < 30;
  if (!r.draws.every((d) => d > 0 && d <= s.width * s.height)) check("the page reports its draw size (ptLoadStatus().drawPixels)", false, `${r.draws.slice(0, 5)}`);
  const band = 4 * s.width;
  let held = null, windows = 0, worstMean = 0;
  for (let a = 0; a < r.draws.length;) {
    let b = a;
    while (b + 1 < r.draws.length && r.draws[b + 1] === r.draws[a]) ++b;
    // Frames a..b drew r.draws[a]; interval k ends frame k. The pacer judged at frame k
    // the six intervals up to it and kept the draw; skip the first two after the change.
    for (let k = a + 7; k <= b && r.draws[a] >= band; ++k) {
      const mean = r.intervals.slice(k - 5, k + 1).reduce((x, y) => x + y, 0) / 6;
      ++windows;
      worstMean = Math.max(worstMean, mean);
      if (mean > s.slowFrameMs && !held) held = { draw: r.draws[a], mean };
    }
    a = b + 1;
  }
  const drawsSeen = [...new Set(r.draws)].sort((x, y) => x - y);
  console.log(`# pacing: ${windows} windows of six frames at a draw of a band or more, the slowest ${worstMean.toFixed(1)} ms ` +
              `(line ${s.slowFrameMs} ms); draws of ${drawsSeen.join(", ")} pixels`);
  if (fixedCostSlow && held)
    console.log(`# the idle page itself is under 30 UI frames/s (${idle.fps.toFixed(1)}): the pacer's floor may keep the draws large`);
  // The pacer's line, as the page reports it: a mean frame over slowFrameMs (33.5 ms,
  // render/pacing.h), just under 30/s, so that frames of two 60 Hz intervals keep their draw.
  if (!(s.slowFrameMs > 30 && s.slowFrameMs < 40)) check("the page reports the pacer's line (slowFrameMs)", false, `${s.slowFrameMs}`);
  check("no draw of a band of 4 rows or more is kept through six frames over the pacer's line",
        !held || fixedCostSlow,
        `${held ? `a draw of ${held.draw} pixels kept through six frames of ${held.mean.toFixed(1)} ms on average; ` : ""}` +
        `${r.fps.toFixed(1)} UI frames/s, draws of ${drawsSeen.join(", ")} pixels, ${windows} windows of a band or more judged ` +
        `(idle page: ${idle.fps.toFixed(1)} UI frames/s)`);
  await shot(page, "responsiveness");
  if (errors.length) check("no console or page errors (responsiveness page)", false, errors.join(" | "));
  await page.close();
}

// Loading a large scene (scenes/bench/million.xml: 1,310,720 triangles, its BVH built in
// slices across frames) while another one renders: the animation frames keep coming (the
// longest gap between two is bounded), the stage and progress are shown, the previous
// scene keeps accumulating until the new one is ready, and the new one renders.
async function largeLoad(context, url) {
  const errors = [];
  const page = await openPage(context, `${url}?scene=reference/scene2.xml&size=96x64&limit=0`, errors);
  await until(page, () => window.ptLoadStatus().samples >= 2 && !window.ptLoadStatus().loading);
  const result = page.evaluate(() => new Promise((done) => {
    const seen = [];  // per frame while loading: stage, progress, the shown scene and its samples
    let worst = 0, frames = 0, last = performance.now(), swapMs = -1, worstAfter = 0;
    const t0 = last;
    const before = window.ptLoadStatus();
    window.ptLoadScene("/scenes/bench/million.xml");
    const tick = () => {
      const now = performance.now();
      // Up to the swap (this frame included): the load; after it, the new scene's first
      // draws, which a software GPU makes slow (reported, not bounded here).
      if (swapMs < 0) worst = Math.max(worst, now - last);
      else worstAfter = Math.max(worstAfter, now - last);
      last = now;
      frames++;
      const s = window.ptLoadStatus();
      if (s.loading) seen.push({ stage: s.loading.stage, progress: s.loading.progress, scene: s.scene, samples: s.samples });
      if (swapMs < 0 && s.scene.endsWith("million.xml")) swapMs = now - t0;
      if ((s.scene.endsWith("million.xml") && s.samples >= 1) || (s.error && !s.loading) || now - t0 > 120000)
        done({ worst, worstAfter, frames, ms: now - t0, swapMs, seen, before, after: s });
      else requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }));
  // The panel while the BVH is being built (the screenshot itself costs the page a frame).
  await until(page, () => { const l = window.ptLoadStatus().loading; return l && l.progress > 0.4; }, null, 120000).catch(() => {});
  await shot(page, "large-loading");
  const r = await result;
  const s = await stats(page);
  await shot(page, "large-loaded");
  const building = r.seen.filter((x) => x.stage === "building the BVH");
  const generating = r.seen.filter((x) => x.stage === "generating the mesh");
  const increasing = r.seen.every((x, i) => i === 0 || x.progress >= r.seen[i - 1].progress);
  const oldSamples = r.seen.filter((x) => x.scene === r.before.scene).reduce((m, x) => Math.max(m, x.samples), -1);
  console.log(`# million.xml shown ${r.swapMs.toFixed(0)} ms after the request (the longest gap between animation frames ${r.worst.toFixed(0)} ms), ` +
              `its first samples after ${r.ms.toFixed(0)} ms (${r.frames} animation frames; the longest gap after the swap ${r.worstAfter.toFixed(0)} ms); ` +
              `mesh generated in ${s.lastLoad.readSlices} slices (${s.lastLoad.readWorkMs.toFixed(0)} ms of work, ${generating.length} frames); ` +
              `packed in ${s.lastLoad.slices} slices, ${s.lastLoad.packWorkMs.toFixed(0)} ms of work, the longest slice ` +
              `${s.lastLoad.longestSliceMs.toFixed(0)} ms (${s.lastLoad.longestSliceStage}); BVH ${s.lastLoad.bvhBuildMs.toFixed(0)} ms of work; ready ${s.lastLoad.ms.toFixed(0)} ms ` +
              `after the request; scene2 went from ${r.before.samples} to ${oldSamples} samples meanwhile`);
  check("loading 1.3 M triangles keeps the animation frames coming", r.worst < kLargeLoadGapMs,
        `longest gap between animation frames ${r.worst.toFixed(0)} ms (bound ${kLargeLoadGapMs})`);
  check("the loading stage and progress are shown", building.length >= 5 && building.some((x) => x.progress > 0.2 && x.progress < 0.8) &&
        generating.length >= 3 && s.lastLoad.readSlices >= 10 && increasing,
        `${r.seen.length} frames while loading, ${generating.length} of them generating the mesh (${s.lastLoad.readSlices} slices), ` +
        `${building.length} building the BVH; increasing ${increasing}`);
  check("the previous scene keeps rendering while the new one loads", oldSamples > r.before.samples,
        `scene2 samples ${r.before.samples} -> ${oldSamples}`);
  check("the large scene renders once loaded", s.scene === "/scenes/bench/million.xml" && !s.error && s.samples >= 1 &&
        s.mean[0] > 0 && s.lastLoad.primitives === 1310721 && r.ms < kLargeLoadMs,
        JSON.stringify({ scene: s.scene, error: s.error, samples: s.samples, mean: s.mean, lastLoad: s.lastLoad, ms: r.ms }));
  if (errors.length) check("no console or page errors (large load page)", false, errors.join(" | "));
  await page.close();
}

async function siteChecks(context) {
  if (!existsSync(join(siteDir, "index.html"))) return check("the site renders from a sub-path", false, `${siteDir} missing: run 'bash tools/site.sh'`);
  const server = await startServer([siteDir, "0", "--base", "/pathtracer/"]);
  const errors = [], outside = [];
  try {
    const page = await context.newPage();
    page.on("request", (r) => { if (!new URL(r.url()).pathname.startsWith("/pathtracer/")) outside.push(r.url()); });
    page.on("console", (m) => { if (m.type() === "error") errors.push(`console: ${m.text()}`); });
    page.on("pageerror", (e) => errors.push(`page error: ${e.message}`));
    await page.goto(`${server.url}?scene=reference/scene0.xml&size=64x48&limit=2`);
    await until(page, () => { try { return window.ptStats().samples >= 2; } catch { return false; } }, null, 60000).catch(() => {});
    const s = await page.evaluate(() => { try { return window.ptStats(); } catch { return null; } });
    await shot(page, "site-subpath");
    check("the site renders from a sub-path with relative URLs only", s && s.samples >= 2 && s.mean[0] > 0 && !s.error &&
          outside.length === 0 && errors.length === 0, JSON.stringify({ samples: s?.samples, error: s?.error, outside, errors }));
    await page.close();
  } finally {
    server.child.kill();
  }
}

async function main() {
  mkdirSync(outDir, { recursive: true });
  checkWebBuild(webDir);
  const userDir = mkdtempSync(join(tmpdir(), "pt-chromium-"));
  const launch = launcher(userDir);
  try {
    const context = await launch({ viewport: { width: 960, height: 640 } });
    if (groups.has("responsiveness") || groups.has("large")) {
      const plain = await startServer([webDir, "0"]);
      try {
        if (groups.has("responsiveness")) await responsiveness(context, plain.url);
        if (groups.has("large")) await largeLoad(context, plain.url);
      } finally {
        plain.child.kill();
      }
    }
    if (groups.has("site")) await siteChecks(context);
    await context.close();
  } finally {
    rmSync(userDir, { recursive: true, force: true });
  }
}

await run(main);
