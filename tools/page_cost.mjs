// What the page's frames cost its throughput (issue 17, "the page's per-frame cost"): the
// page as users run it against the raw pass (&raw=ROWS: one draw of ROWS whole rows per
// frame, no pacing, no panel, the image shown once a second), interleaved A B A B, in
// headless Chromium (SwiftShader here; a GPU elsewhere). A measurement a person runs, not a
// CI test.
//
//   NODE_PATH=/usr/share/nodejs node tools/page_cost.mjs [--web build/web] [--scene reference/scene2.xml]
//        [--viewport 960x640] [--bounces 8] [--raw-rows 32] [--cycles 2] [--warmup 8] [--seconds 30]
//        [--denoise on|off]   (off: the denoiser toggled off in both, as the panel's checkbox does)
//        (--raw-rows 0: the page alone)
//
// Per run: paths/s from the page's own count (ptLoadStatus().paths, every pixel sample of
// every draw) over --seconds after --warmup, and the UI frame rate over the same window
// (animation frames; in the raw pass one frame is one draw). Prints each run, the medians
// and page / raw. Both without the coarse first image (&coarse=0), both unlimited.
// Over the same window, the CPU time of every thread of the browser's processes (Linux
// /proc: utime + stime), summed by process type and thread name, in ms per second of wall
// time: where a frame's time goes (SwiftShader draws on its worker threads in the GPU
// process; wasm, ImGui and WebGL calls on the renderer's main thread).
import { mkdtempSync, readdirSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { checkWebBuild, launcher, median, openPage, repo, startServer } from "../tests/browser/app_lib.mjs";

const opt = { web: "build/web", scene: "reference/scene2.xml", viewport: "960x640", bounces: "8", "raw-rows": "32",
              cycles: "2", warmup: "8", seconds: "30", denoise: "on" };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, "");
  if (!(key in opt) || i + 1 >= process.argv.length) {
    console.error(`usage: node tools/page_cost.mjs ${Object.keys(opt).map((k) => `[--${k} ${opt[k]}]`).join(" ")}`);
    process.exit(2);
  }
  opt[key] = process.argv[i + 1];
}
const [vw, vh] = opt.viewport.split("x").map(Number);
const webDir = resolve(repo, opt.web);

// CPU ticks of every thread of every process started with this profile, keyed
// "process type / thread name" (a thread name's digits dropped: workers of one pool add up).
function cpuSnapshot(userDir) {
  const procs = new Map();  // pid -> { parent, cmd }
  for (const pid of readdirSync("/proc").filter((d) => /^\d+$/.test(d))) {
    try {
      const stat = readFileSync(`/proc/${pid}/stat`, "utf8");
      procs.set(pid, { parent: stat.slice(stat.lastIndexOf(")") + 2).split(" ")[1],
                       cmd: readFileSync(`/proc/${pid}/cmdline`, "utf8") });
    } catch { /* ended */ }
  }
  const ours = (pid, depth = 0) => {  // started with this profile, or a descendant of such a process
    const p = procs.get(pid);
    return !!p && depth < 8 && (p.cmd.includes(userDir) || ours(p.parent, depth + 1));
  };
  const ticks = new Map();
  for (const [pid, { cmd }] of procs) {
    if (!ours(pid)) continue;
    const type = (cmd.match(/--type=([a-z-]+)/) || [, "browser"])[1];
    try {
      for (const tid of readdirSync(`/proc/${pid}/task`)) {
        const stat = readFileSync(`/proc/${pid}/task/${tid}/stat`, "utf8");
        const name = stat.slice(stat.indexOf("(") + 1, stat.lastIndexOf(")")).replace(/[0-9]+/g, "#");
        const f = stat.slice(stat.lastIndexOf(")") + 2).split(" ");
        const key = `${type} / ${name}`;
        ticks.set(key, (ticks.get(key) || 0) + Number(f[11]) + Number(f[12]));  // utime, stime
      }
    } catch { /* a process or thread that ended */ }
  }
  return ticks;
}
const kTicksPerSecond = 100;  // USER_HZ on Linux

let userDir = "";  // the browser profile of this run (main): its processes are the ones counted

// Paths and animation frames over `ms`, after the first full-resolution sample.
async function measure(context, url, mode) {
  const errors = [];
  const page = await openPage(context, url, errors);
  await page.waitForFunction(() => window.ptLoadStatus().samples >= 1 || window.ptLoadStatus().paths > 0, null,
                             { timeout: 300000, polling: 100 });
  if (opt.denoise === "off") await page.evaluate(() => window.ptSetDenoise(false));
  await page.waitForTimeout(Number(opt.warmup) * 1000);
  const cpu0 = cpuSnapshot(userDir);
  const r = await page.evaluate((ms) => new Promise((done) => {
    const s0 = window.ptLoadStatus(), t0 = performance.now();
    let frames = 0, worst = 0, last = t0, prev = s0;
    const log = [];  // per animation frame: the interval, and whether presents / draws happened since the last
    const tick = () => {
      const now = performance.now(), st = window.ptLoadStatus();
      worst = Math.max(worst, now - last);
      log.push([now - last, (st.presents ?? 0) - (prev.presents ?? 0), st.paths - prev.paths]);
      last = now;
      prev = st;
      frames++;
      if (now - t0 < ms) return requestAnimationFrame(tick);
      done({ paths: st.paths - s0.paths, ms: now - t0, frames, worst, samples: st.samples, log });
    };
    requestAnimationFrame(tick);
  }), Number(opt.seconds) * 1000);
  const cpu1 = cpuSnapshot(userDir);
  const threads = [...cpu1].map(([k, t]) => [k, ((t - (cpu0.get(k) || 0)) * 1000) / kTicksPerSecond / (r.ms / 1000)])
    .filter(([, v]) => v >= 5).sort((a, b) => b[1] - a[1]);
  const st = await page.evaluate(() => window.ptStats());
  await page.close();
  const out = { mode, pathsPerSecond: (r.paths * 1000) / r.ms, fps: (r.frames * 1000) / r.ms, worst: r.worst,
                samples: r.samples, width: st.width, height: st.height, draw: st.bandRows ? `${st.bandRows} x ${st.bandColumns || st.width}` : "whole", errors };
  console.log(`# ${mode}: ${out.pathsPerSecond.toFixed(0)} paths/s, ${out.fps.toFixed(1)} UI frames/s (worst frame ${out.worst.toFixed(0)} ms), ` +
              `draws of ${mode === "raw" ? opt["raw-rows"] + " rows" : out.draw}, ${out.width}x${out.height}, ${out.samples} spp at the end` +
              (errors.length ? `; errors: ${errors.join(" | ")}` : ""));
  // The frames by what the page did in them (ptLoadStatus().presents, paths): the interval
  // after a frame is the time its work took the browser and the GPU.
  const kinds = new Map();
  for (let i = 0; i + 2 < r.log.length; ++i) {
    const [, presents, paths] = r.log[i];
    const key = `${presents > 0 ? "present" : "no present"}, ${paths > 0 ? "draw" : "no draw"}`;
    const k = kinds.get(key) || { n: 0, ms: 0, ms2: 0, paths: 0 };
    k.n++;
    k.ms += r.log[i + 1][0];
    k.ms2 += r.log[i + 2][0];
    k.paths += paths;
    kinds.set(key, k);
  }
  console.log(`#   frames: ` + [...kinds].map(([key, k]) => `${key} ${k.n} (next intervals ${(k.ms / k.n).toFixed(1)}, ${(k.ms2 / k.n).toFixed(1)} ms, ` +
              `${(k.paths / k.n).toFixed(0)} paths)`).join("; "));
  // The three longest intervals, with what the two frames before them did.
  const worstFrames = r.log.map((e, i) => [e[0], i]).sort((a, b) => b[0] - a[0]).slice(0, 3);
  console.log(`#   longest: ` + worstFrames.map(([ms, i]) => `${ms.toFixed(0)} ms after ` +
              [r.log[i - 2], r.log[i - 1]].filter(Boolean).map((e) => `[${e[1] > 0 ? "present" : "-"} ${e[2]} paths]`).join(" ")).join("; "));
  console.log(`#   CPU ms per s: total ${threads.reduce((a, [, v]) => a + v, 0).toFixed(0)}; ` +
              threads.map(([k, v]) => `${k} ${v.toFixed(0)}`).join(", "));
  return out;
}

async function main() {
  checkWebBuild(webDir);
  userDir = mkdtempSync(join(tmpdir(), "pt-chromium-"));
  const server = await startServer([webDir, "0"]);
  const runs = { page: [], raw: [] };
  try {
    const context = await launcher(userDir)({ viewport: { width: vw, height: vh } });
    const base = `${server.url}?scene=${opt.scene}&bounces=${opt.bounces}&limit=0&coarse=0`;
    console.log(`# ${new Date().toISOString()}: ${opt.scene}, viewport ${opt.viewport}, ${opt.bounces} bounces, ` +
                `${opt.cycles} cycles of page then raw (${opt["raw-rows"]} rows a draw), ${opt.warmup} s warm-up, ${opt.seconds} s measured`);
    for (let c = 0; c < Number(opt.cycles); ++c) {
      runs.page.push(await measure(context, base, "page"));
      if (Number(opt["raw-rows"]) > 0) runs.raw.push(await measure(context, `${base}&raw=${opt["raw-rows"]}`, "raw"));
    }
    await context.close();
  } finally {
    server.child.kill();
    rmSync(userDir, { recursive: true, force: true });
  }
  const p = median(runs.page.map((r) => r.pathsPerSecond)), fps = median(runs.page.map((r) => r.fps));
  if (!runs.raw.length) return console.log(`page ${p.toFixed(0)} paths/s at ${fps.toFixed(1)} UI frames/s (no raw pass: --raw-rows 0)`);
  const w = median(runs.raw.map((r) => r.pathsPerSecond));
  console.log(`page ${p.toFixed(0)} paths/s at ${fps.toFixed(1)} UI frames/s; raw ${w.toFixed(0)} paths/s ` +
              `(${median(runs.raw.map((r) => r.fps)).toFixed(1)} draws/s); page / raw ${(p / w).toFixed(2)} (goal: at least 0.8 at 30 UI frames/s)`);
}

await main();
