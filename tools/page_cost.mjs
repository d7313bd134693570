#!/usr/bin/env node
// The page's per-frame cost (issue 17; docs/benchmarks.md "The page's per-frame cost"): a
// measurement a person runs, not a CI test (its figures follow the machine's load).
//
//   node tools/page_cost.mjs [--builds build/web-base,build/web] [--cycles 3] [--seconds 30]
//        [--raw-build build/web] [--size 512x512] [--bounces 8] [--json FILE]
//
// Per cycle, interleaved: the raw pass once (the page with ?raw=1, a test-only mode: whole
// image draws back to back, each waited for, no display, no panel; App::raw_frame), then
// each build's page as users run it. Each run is a fresh headless Chromium (SwiftShader),
// the peer benchmark's flags and page (tools/peers/adapters/ours.mjs: scene2, 640x640
// viewport). Timing starts at the first complete image; over `seconds` it counts:
// - paths/s: the page's own count of paths (pixel samples) issued (ptLoadStatus().paths);
//   the raw pass between its first and last whole draw within the window (each draw is
//   waited for with a 1-pixel read-back, so the count is of finished paths; its window is
//   twice as long: a whole draw of scene2 at 512x512 takes 10-20 s here);
// - UI frames/s: requestAnimationFrame callbacks per second (a counter of its own);
// - the page's frame statistics where the build has them (ptLoadStatus().frameStats:
//   frames run, presents, CPU ms in the frame's parts).
import { spawnSync } from "node:child_process";
import { writeFileSync } from "node:fs";
import { dirname, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "../tests/browser/node_modules/playwright-core/index.mjs";
import * as ours from "./peers/adapters/ours.mjs";
import { startServer } from "./peers/server.mjs";

const repo = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const opt = { builds: "build/web", cycles: "3", seconds: "30", "raw-build": "", size: "512x512", bounces: "8", json: "" };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, "");
  if (!(key in opt) || i + 1 >= process.argv.length) {
    console.error("usage: see the comment at the top of tools/page_cost.mjs");
    process.exit(2);
  }
  opt[key] = process.argv[i + 1];
}
const builds = opt.builds.split(",");
const rawBuild = opt["raw-build"] || builds[builds.length - 1];
const [width, height] = opt.size.split("x").map(Number);
const seconds = Number(opt.seconds);
// The peer benchmark's Chromium flags (tools/peers/bench.mjs).
const chromeArgs = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-vsync",
                    "--disable-frame-rate-limit", "--disable-background-networking", "--disable-component-update",
                    "--no-first-run", "--disable-sync", "--disable-background-timer-throttling",
                    "--disable-renderer-backgrounding", "--disable-backgrounding-occluded-windows"];

// Counts animation frames from the page's start (its own callback chain, beside the page's).
function rafCounter() {
  window.ptRafCount = 0;
  const tick = () => { window.ptRafCount++; requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
}

async function runOnce(build, mount, raw) {
  const ctx = { repo, width, height, bounces: Number(opt.bounces), extra: raw ? "raw=1&coarse=0" : "" };
  const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", headless: true, args: chromeArgs });
  try {
    const context = await browser.newContext({ viewport: { width: Math.max(width, 640), height: Math.max(height, 640) }, deviceScaleFactor: 1 });
    await context.addInitScript(rafCounter);
    const page = await context.newPage();
    page.setDefaultTimeout(600e3);
    await page.goto(`${mount.url}/${build}${ours.url(ctx).replace("/ours", "")}`, { waitUntil: "load" });
    await page.waitForFunction(() => { try { const s = window.ptLoadStatus(); return s && s.samples >= 1; } catch { return false; } },
                               null, { timeout: 600e3, polling: 50 });
    // Samples through the page's status, polled here every 50 ms: (time, paths) at each change.
    const result = await page.evaluate(async (ms) => {
      const points = [];
      const t0 = performance.now(), r0 = window.ptRafCount, s0 = window.ptLoadStatus();
      let last = s0.paths;
      points.push([0, s0.paths]);
      while (performance.now() - t0 < ms) {
        await new Promise((r) => setTimeout(r, 50));
        const s = window.ptLoadStatus();
        if (s.paths !== last) points.push([performance.now() - t0, s.paths]);
        last = s.paths;
      }
      const t1 = performance.now() - t0, s1 = window.ptLoadStatus();
      return { points, tMs: t1, rafs: window.ptRafCount - r0, s0: s0.frameStats ?? null, s1: s1.frameStats ?? null, samples: s1.samples };
    }, (raw ? 2 : 1) * seconds * 1e3);
    const p = result.points;
    let pathsPerS;
    if (raw) {  // between the first and the last finished draw seen in the window
      const a = p[1] ?? p[0], b = p[p.length - 1];
      pathsPerS = b[0] > a[0] ? (b[1] - a[1]) / ((b[0] - a[0]) / 1e3) : NaN;
    } else {
      pathsPerS = (p[p.length - 1][1] - p[0][1]) / (result.tMs / 1e3);
    }
    const fps = result.rafs / (result.tMs / 1e3);
    let frame = null;
    if (result.s0 && result.s1) {
      const d = (k) => result.s1[k] - result.s0[k];
      frame = { frames: d("frames"), presents: d("presents"), drawFrames: d("drawFrames") };
      for (const k of Object.keys(result.s1.cpuMs)) frame[`${k}Ms`] = (result.s1.cpuMs[k] - result.s0.cpuMs[k]) / Math.max(1, d("frames"));
    }
    return { build, raw, pathsPerS, fps, samples: result.samples, draws: p.length - 1, frame };
  } finally {
    await browser.close();
  }
}

const load = () => spawnSync("cat", ["/proc/loadavg"], { encoding: "utf8" }).stdout.trim().split(" ").slice(0, 3).join(" ");
const server = await startServer([...new Set([...builds, rawBuild])].map((b) => [`/${b}/`, resolve(repo, b)])
  .concat([...new Set([...builds, rawBuild])].flatMap((b) => [[`/${b}/scenes/`, resolve(repo, "scenes")], [`/${b}/assets/`, resolve(repo, "assets")]])));
const mount = { url: server.url.replace(/\/$/, "") };
const runs = [];
try {
  for (let c = 1; c <= Number(opt.cycles); c++) {
    for (const [build, raw] of [[rawBuild, true], ...builds.map((b) => [b, false])]) {
      const before = load();
      const r = await runOnce(build, mount, raw);
      r.cycle = c;
      r.load = `${before} -> ${load()}`;
      runs.push(r);
      const f = r.frame ? `, ${r.frame.presents} presents / ${r.frame.frames} frames (${r.frame.drawFrames} drew), cpu/frame ` +
                          Object.entries(r.frame).filter(([k]) => k.endsWith("Ms")).map(([k, v]) => `${k} ${v.toFixed(2)}`).join(" ") : "";
      console.log(`cycle ${c} ${raw ? "raw " : "page"} ${build}: ${Math.round(r.pathsPerS)} paths/s, ${r.fps.toFixed(1)} rAF/s, ` +
                  `${r.samples} spp, ${r.draws} count changes${f}; load ${r.load}`);
    }
  }
} finally {
  server.close();
}
const median = (a) => { const s = a.slice().sort((x, y) => x - y); return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2; };
const raws = runs.filter((r) => r.raw).map((r) => r.pathsPerS);
console.log(`raw pass (${rawBuild}): median ${Math.round(median(raws))} paths/s (${raws.map(Math.round).join(", ")})`);
for (const b of builds) {
  const rs = runs.filter((r) => !r.raw && r.build === b);
  // Each page run against the raw run of its own cycle (the load drifts between cycles).
  const ratios = rs.map((r) => r.pathsPerS / runs.find((q) => q.raw && q.cycle === r.cycle).pathsPerS);
  console.log(`page ${b}: median ${Math.round(median(rs.map((r) => r.pathsPerS)))} paths/s (${rs.map((r) => Math.round(r.pathsPerS)).join(", ")}), ` +
              `${median(rs.map((r) => r.fps)).toFixed(1)} rAF/s, page/raw median ${median(ratios).toFixed(2)} (${ratios.map((x) => x.toFixed(2)).join(", ")})`);
}
if (opt.json) writeFileSync(resolve(repo, opt.json), JSON.stringify(runs, null, 2));
