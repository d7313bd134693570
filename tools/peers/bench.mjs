#!/usr/bin/env node
// The side-by-side peer benchmark (issue 17; README "The peer benchmark"; results in
// docs/benchmarks.md). A tool a person runs, not a CI test. Usually through run.sh:
//
//   node tools/peers/bench.mjs [run] [--tracers ours,three-gpu-pt] [--cycles 3] [--windows 30,120]
//        [--size 512x512] [--bounces 8] [--out build/peers] [--extra-NAME QUERY] [--our-build DIR]
//   node tools/peers/bench.mjs reference --tracer NAME --seconds S     (a long run of that tracer)
//   node tools/peers/bench.mjs reference --tracer ours --native --seconds S   (build/native/pathtracer)
//   node tools/peers/bench.mjs reference --tracer NAME --import FILE.pfm --spp N --how TEXT  (rendered elsewhere)
//   node tools/peers/bench.mjs report --results build/peers/results-STAMP.json  (the table again)
//
// `run` opens each tracer's page in a fresh headless Chromium (Debian's /usr/bin/chromium,
// SwiftShader; a fresh profile each time, so no shader cache), interleaved A B A B over the
// cycles. Per run: the time from navigation to the first complete image (every pixel one
// sample), the shader compile time, then from that moment on the windows (seconds of
// rendering): at each window's end the image is taken as it was then (linear RGB floats) with
// the paths traced so far. paths/s is over the longest window. relMSE at each window is
// against the tracer's own converged reference (build/peers/ref-NAME-WxH-bB.pfm, made by
// `reference`), as core/metrics.h defines it: mean over pixels and RGB channels of
// (x - r)^2 / (r^2 + 0.01), on linear radiance (see README for why linear).
import { spawnSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { startServer } from "./server.mjs";

const peersDir = dirname(fileURLToPath(import.meta.url));
const repo = resolve(peersDir, "../..");
const adapterNames = ["ours", "three-gpu-pt"];  // adapters/NAME.mjs; add a tracer: one more file and name

// ---- options
const argv = process.argv.slice(2);
const command = argv[0] && !argv[0].startsWith("--") ? argv.shift() : "run";
const opt = { tracers: adapterNames.join(","), cycles: "3", windows: "30,120", size: "512x512", bounces: "8",
              out: "build/peers", tracer: "", seconds: "", native: false, "our-build": "", results: "", import: "", how: "", spp: "", extra: {}, chromium: "/usr/bin/chromium" };
for (let i = 0; i < argv.length; i++) {
  const key = argv[i].replace(/^--/, "");
  if (key === "native") { opt.native = true; continue; }
  if (key.startsWith("extra-")) { opt.extra[key.slice(6)] = argv[++i]; continue; }
  if (!(key in opt) || i + 1 >= argv.length) {
    console.error(`unknown or incomplete option ${argv[i]} (see the comment at the top of ${fileURLToPath(import.meta.url)})`);
    process.exit(2);
  }
  opt[key] = argv[++i];
}
const [width, height] = opt.size.split("x").map(Number);
const bounces = Number(opt.bounces);
const outDir = resolve(repo, opt.out);
mkdirSync(outDir, { recursive: true });
const ctxFor = (name) => ({ repo, peersDir, width, height, bounces, extra: opt.extra[name] ?? "", ourBuild: opt["our-build"] || undefined });
const refPath = (name) => join(outDir, `ref-${name}-${width}x${height}-b${bounces}.pfm`);

// ---- images: RGB float32, rows bottom to top (as GL reads them and PFM stores them)
function writePfm(path, w, h, rgb) {
  const head = Buffer.from(`PF\n${w} ${h}\n-1.0\n`);
  writeFileSync(path, Buffer.concat([head, Buffer.from(rgb.buffer, rgb.byteOffset, rgb.byteLength)]));
}
function readPfm(path) {
  const b = readFileSync(path);
  let pos = 0;
  const line = () => { const e = b.indexOf(10, pos); const s = b.subarray(pos, e).toString(); pos = e + 1; return s; };
  if (line() !== "PF") throw new Error(`${path}: not a colour PFM`);
  const [w, h] = line().trim().split(/\s+/).map(Number);
  const scale = Number(line());
  const data = new Float32Array(w * h * 3);
  for (let i = 0; i < data.length; i++) data[i] = scale < 0 ? b.readFloatLE(pos + 4 * i) : b.readFloatBE(pos + 4 * i);
  return { w, h, rgb: data };
}
// core/metrics.h's relMSE: mean over pixels and channels of (x - r)^2 / (r^2 + 0.01).
function relMse(x, ref) {
  let s = 0;
  for (let i = 0; i < ref.length; i++) { const d = x[i] - ref[i]; s += (d * d) / (ref[i] * ref[i] + 0.01); }
  return s / ref.length;
}
function meanRgb(x) {
  const m = [0, 0, 0];
  for (let i = 0; i < x.length; i += 3) for (let k = 0; k < 3; k++) m[k] += x[i + k];
  return m.map((v) => v / (x.length / 3));
}
const lum = (m) => 0.2126 * m[0] + 0.7152 * m[1] + 0.0722 * m[2];
const median = (a) => { const s = a.slice().sort((p, q) => p - q); return s.length ? (s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2) : NaN; };
const fromB64 = (s) => { const u8 = Buffer.from(s, "base64"); return new Float32Array(u8.buffer, u8.byteOffset, u8.byteLength / 4); };

// ---- one run of one tracer: a fresh browser, its page, the first image, the windows
const chromeArgs = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-vsync",
                    "--disable-frame-rate-limit", "--disable-background-networking", "--disable-component-update",
                    "--no-first-run", "--disable-sync", "--disable-background-timer-throttling",
                    "--disable-renderer-backgrounding", "--disable-backgrounding-occluded-windows"];
async function runOnce(adapter, server, checkpointsMs, log) {
  const ctx = ctxFor(adapter.name);
  const { chromium } = await import("playwright-core");  // not needed by `reference --native` and `report`
  const browser = await chromium.launch({ executablePath: opt.chromium, headless: true, args: chromeArgs });
  const res = { tracer: adapter.name, url: adapter.url(ctx), browser: browser.version(), startedAt: new Date().toISOString() };
  try {
    const context = await browser.newContext({ viewport: { width: Math.max(width, 640), height: Math.max(height, 640) }, deviceScaleFactor: 1 });
    await adapter.prepare(context, ctx);
    const page = await context.newPage();
    const pageLog = [];
    page.on("console", (m) => pageLog.push(`${m.type()}: ${m.text()}`));
    page.on("pageerror", (e) => pageLog.push(`pageerror: ${e.message}`));
    page.setDefaultTimeout(900e3);  // a loaded machine: a page of many modules loads slowly
    await page.goto(server.url + adapter.url(ctx), { waitUntil: "load", timeout: 900e3 });
    const started = Date.now();
    const waitFor = async (states, limitMs) => {
      while (true) {
        const s = await page.evaluate(() => (window.peerBench ? window.peerBench.state() : "loading"));
        if (s === "error") throw new Error(`${adapter.name}: ${await page.evaluate(() => window.peerBench.error())}`);
        if (states.includes(s)) return s;
        if (Date.now() - started > limitMs) throw new Error(`${adapter.name}: still '${s}' after ${limitMs / 1000} s; page log:\n${pageLog.slice(-10).join("\n")}`);
        await new Promise((r) => setTimeout(r, 100));
      }
    };
    await waitFor(["rendering"], 900e3);
    res.info = await page.evaluate(() => window.peerBench.info());
    { const c = compileMs(res); log(`  ${adapter.name}: first image at ${(res.info.firstImageMs / 1e3).toFixed(1)} s, compile ${(c.ms / 1e3).toFixed(1)} s${c.estimated ? " (est.)" : ""}`); }
    await page.evaluate((cps) => window.peerBench.start(cps), checkpointsMs);
    await waitFor(["done"], 900e3 + checkpointsMs[checkpointsMs.length - 1] * 3);
    res.records = await page.evaluate(() => window.peerBench.records());
    res.images = [];
    for (let k = 0; k < res.records.length; k++) res.images.push(fromB64(await page.evaluate((i) => window.peerBench.image(i), k)));
    res.pageLog = pageLog.filter((l) => !/deprecated/i.test(l)).slice(-20);
  } finally {
    await browser.close();
  }
  return res;
}

// compileMs where the page cannot time its compile apart (three-gpu-pathtracer compiles
// inside its first renderSample): the first image's time less one sample's, the median of
// the later ones. Marked "est." in the table.
function compileMs(r) {
  if (r.info.compileMs !== undefined && r.info.compileMs !== null) return { ms: r.info.compileMs, estimated: false };
  if (r.info.compileAndFirstSampleMs !== undefined && r.info.sampleMsFirst?.length)
    return { ms: r.info.compileAndFirstSampleMs - median(r.info.sampleMsFirst), estimated: true };
  return { ms: NaN, estimated: true };
}

async function loadAdapters(names) {
  const out = [];
  for (const n of names) {
    if (!adapterNames.includes(n)) throw new Error(`no adapter '${n}' (adapters/: ${adapterNames.join(", ")})`);
    out.push(await import(`./adapters/${n}.mjs`));
  }
  return out;
}

const fmt = (v, d = 0) => (Number.isFinite(v) ? v.toLocaleString("en-US", { maximumFractionDigits: d, minimumFractionDigits: d }) : "n/a");
const fmtE = (v) => (Number.isFinite(v) ? v.toExponential(2) : "n/a");

async function commandRun() {
  const adapters = await loadAdapters(opt.tracers.split(","));
  const windows = opt.windows.split(",").map(Number).sort((a, b) => a - b);
  const cps = windows.map((s) => s * 1e3);
  const server = await startServer(adapters.flatMap((a) => a.mounts(ctxFor(a.name))));
  const log = (s) => console.log(s);
  log(`peers: ${adapters.map((a) => a.name).join(" ")}, ${opt.cycles} cycles, windows ${windows.join(", ")} s, ${width}x${height}, ${bounces} bounces; ${server.url}`);
  const runs = [], failed = [];
  try {
    for (let c = 0; c < Number(opt.cycles); c++) {
      log(`cycle ${c + 1}`);
      for (const a of adapters) {
        let r;
        try {
          r = await runOnce(a, server, cps, log);
        } catch (e) {  // one failed run is reported, the others go on
          log(`  ${a.name}: FAILED: ${e.message ?? e}`);
          failed.push({ tracer: a.name, cycle: c + 1, error: String(e.message ?? e) });
          continue;
        }
        r.cycle = c + 1;
        runs.push(r);
        const last = r.records[r.records.length - 1];
        log(`  ${a.name}: ${fmt(last.paths / (last.tMs / 1e3))} paths/s over ${fmt(last.tMs / 1e3, 1)} s (${last.samples} spp)`);
      }
    }
  } finally {
    server.close();
  }
  const stamp = new Date().toISOString().replace(/[:.]/g, "-");
  const result = { stamp, date: new Date().toISOString(), browser: runs[0]?.browser, renderer: runs[0]?.info?.renderer, size: opt.size, bounces,
                   cycles: Number(opt.cycles), windows, tracers: adapters.map((a) => ({ name: a.name, title: a.title })), machine: machine(),
                   runs: runs.map(({ images, ...r }) => r), failed };
  // Every window's image, so that `report` can score the runs against references made later.
  runs.forEach((r, i) => r.images.forEach((img, k) => {
    result.runs[i].imageFiles = result.runs[i].imageFiles ?? [];
    const file = `run-${stamp}-${r.tracer}-c${r.cycle}-w${windows[k]}.pfm`;
    writePfm(join(outDir, file), width, height, img);
    result.runs[i].imageFiles.push(file);
  }));
  writeFileSync(join(outDir, `results-${stamp}.json`), JSON.stringify(result, null, 2));
  report(result, runs.map((r) => r.images));
}

// The table from a run's results: scored against the references in the output folder now.
function report(result, images) {
  const { windows, stamp } = result;
  const refs = {}, table = [];
  for (const a of result.tracers) if (existsSync(refPath(a.name))) refs[a.name] = readPfm(refPath(a.name));
  const runs = result.runs.map((r, i) => ({ ...r, images: images[i] }));
  const oursMean = (() => {
    if (refs.ours) return { mean: meanRgb(refs.ours.rgb), of: "reference" };
    const own = runs.filter((r) => r.tracer === "ours");
    return own.length ? { mean: meanRgb(own.at(-1).images.at(-1)), of: "last image" } : null;
  })();
  for (const a of result.tracers) {
    const own = runs.filter((r) => r.tracer === a.name);
    if (!own.length) { table.push({ tracer: a.name, title: a.title, none: true }); continue; }
    const pps = own.map((r) => { const l = r.records.at(-1); return l.paths / (l.tMs / 1e3); });
    const first = own.map((r) => r.info.firstImageMs / 1e3);
    const comp = own.map(compileMs);
    // The first image less one sample's time at the run's own rate (from the windows, else
    // the page's sample times): what loading, compiling and the driver's first-draw JIT
    // cost, counted the same way for every tracer (SwiftShader compiles a program to
    // machine code at its first draw, after the link that a page can time).
    const overhead = own.map((r, k) => {
      const sampleS = pps[k] > 0 ? (width * height) / pps[k] : median(r.info.sampleMsFirst ?? []) / 1e3;
      return r.info.firstImageMs / 1e3 - sampleS;
    });
    const row = { tracer: a.name, title: a.title, pathsPerSec: { median: median(pps), min: Math.min(...pps), max: Math.max(...pps), each: pps },
                  firstImageS: { median: median(first), min: Math.min(...first), max: Math.max(...first) },
                  compileS: { median: median(comp.map((x) => x.ms / 1e3)), estimated: comp.some((x) => x.estimated) },
                  overheadS: { median: median(overhead), min: Math.min(...overhead), max: Math.max(...overhead) },
                  runSpp: Math.max(...own.map((r) => r.records.at(-1).paths / (width * height))),
                  relMse: {}, reference: null, meanRgb: null, meanVsOurs: null, late: own.some((r) => r.records.some((x) => x.late)) };
    const ref = refs[a.name];
    if (ref) {
      if (ref.w !== width || ref.h !== height) throw new Error(`${refPath(a.name)} is ${ref.w}x${ref.h}`);
      row.reference = JSON.parse(readFileSync(refPath(a.name) + ".json", "utf8"));
      // A reference of the page made with other parameters (e.g. another ei) scores nothing.
      const urls = new Set(own.map((r) => r.url));
      if (row.reference.url && (urls.size !== 1 || !urls.has(row.reference.url)))
        throw new Error(`${refPath(a.name)} was made at ${row.reference.url}, the runs at ${[...urls].join(", ")}: make it again`);
      windows.forEach((s, k) => {
        const v = own.map((r) => relMse(r.images[k], ref.rgb));
        row.relMse[s] = { median: median(v), each: v };
      });
    }
    const m = ref ? meanRgb(ref.rgb) : meanRgb(own.at(-1).images.at(-1));
    row.meanRgb = { rgb: m, of: ref ? "reference" : "last image" };
    if (oursMean) row.meanVsOurs = lum(m) / lum(oursMean.mean);
    table.push(row);
  }
  // The table, as docs/benchmarks.md keeps it.
  const md = [];
  md.push(`${result.date}, ${result.browser}, ${result.renderer}, ${result.machine}; scene2, ${result.size}, ${result.bounces} bounces, ${result.cycles} cycles interleaved, windows ${windows.join(", ")} s of rendering after the first image`);
  md.push("");
  md.push(`| tracer | paths/s, median (range) | first image, s | compile, s | first image less one sample, s | ${windows.map((s) => `relMSE at ${s} s`).join(" | ")} | mean lum. vs ours |`);
  md.push(`|---|---|---|---|---|${windows.map(() => "---|").join("")}---|`);
  for (const r of table.filter((x) => x.none)) md.push(`| ${r.title} | every run failed |${windows.map(() => " |").join("")} | | | |`);
  for (const r of table.filter((x) => !x.none))
    md.push(`| ${r.title} | ${fmt(r.pathsPerSec.median)} (${fmt(r.pathsPerSec.min)}-${fmt(r.pathsPerSec.max)}) | ${fmt(r.firstImageS.median, 1)} (${fmt(r.firstImageS.min, 1)}-${fmt(r.firstImageS.max, 1)}) | ${fmt(r.compileS.median, 1)}${r.compileS.estimated ? " (est.)" : ""} | ${fmt(r.overheadS.median, 1)} (${fmt(r.overheadS.min, 1)}-${fmt(r.overheadS.max, 1)}) | ` +
            windows.map((s) => (r.relMse[s] ? fmtE(r.relMse[s].median) : "no reference")).join(" | ") + ` | ${r.meanVsOurs !== null ? fmt(r.meanVsOurs, 3) : "n/a"} (${r.meanRgb.of}) |`);
  md.push("");
  md.push("compile: as the page times it (ours: until the link status is known, KHR_parallel_shader_compile); (est.): the first sample's time less a later sample's.");
  for (const f of result.failed ?? []) md.push(`FAILED: ${f.tracer}, cycle ${f.cycle}: ${f.error.split("\n")[0]}`);
  for (const r of table) {
    if (!r.reference) continue;
    md.push(`reference of ${r.tracer}: ${r.reference.how}`);
    // relMSE against a reference of N spp reads high by about (run spp)/N: its own noise.
    if (!(r.reference.spp >= 10 * r.runSpp))
      md.push(`note: the reference of ${r.tracer} has ${fmt(r.reference.spp, 1)} spp, under 10x the runs' ${fmt(r.runSpp, 1)}: its own noise is in these relMSE figures (not converged)`);
  }
  for (const r of table) if (r.late) md.push(`note: ${r.tracer} took some window images more than 0.5 s after their time (a long frame, or a sample far slower than the one before)`);
  writeFileSync(join(outDir, `results-${stamp}.md`), md.join("\n") + "\n");
  writeFileSync(join(outDir, `table-${stamp}.json`), JSON.stringify(table, null, 2));
  console.log("\n" + md.join("\n"));
  console.log(`\nwrote ${join(opt.out, `results-${stamp}.{json,md}`)}, table-${stamp}.json and each window's image (run-${stamp}-*.pfm)`);
}

// `report --results build/peers/results-STAMP.json`: the table again, e.g. after references.
function commandReport() {
  if (!opt.results) throw new Error("report needs --results FILE");
  const result = JSON.parse(readFileSync(resolve(repo, opt.results), "utf8"));
  if (result.size !== opt.size || result.bounces !== bounces) throw new Error(`the results are ${result.size}, ${result.bounces} bounces: pass --size and --bounces`);
  report(result, result.runs.map((r) => r.imageFiles.map((f) => readPfm(join(outDir, f)).rgb)));
}

function machine() {
  const cpus = spawnSync("nproc", { encoding: "utf8" }).stdout.trim();
  const load = readFileSync("/proc/loadavg", "utf8").split(" ").slice(0, 3).join(" ");
  return `${cpus} cores, load ${load} at the end`;
}

// A converged reference of one tracer's own image: a long run (one window), or for ours
// the native renderer (the same shaders and estimator; faster, e.g. on a GPU).
async function commandReference() {
  const name = opt.tracer, seconds = Number(opt.seconds);
  if (!name || !(seconds > 0 || opt.import)) throw new Error("reference needs --tracer NAME --seconds S (or --import FILE.pfm --spp N --how TEXT)");
  const path = refPath(name);
  let how, rgb, spp, pageUrl = null;
  if (opt.import) {  // a reference rendered elsewhere (e.g. the native renderer on a GPU machine)
    const img = readPfm(resolve(opt.import));
    if (img.w !== width || img.h !== height) throw new Error(`${opt.import} is ${img.w}x${img.h}, not ${width}x${height}`);
    rgb = img.rgb;
    spp = Number(opt.spp);
    how = opt.how || `imported from ${opt.import}`;
    writePfm(path, width, height, rgb);
  } else if (opt.native) {
    if (name !== "ours") throw new Error("--native is for ours only");
    const exe = join(repo, "build/native/pathtracer");
    const args = ["render", join(repo, "scenes/reference/scene2.xml"), "--size", `${width}x${height}`, "--bounces", String(bounces),
                  "--seconds", String(seconds), "--spp", "1000000", "--out", path];
    console.log(`${exe} ${args.join(" ")}`);
    const p = spawnSync(exe, args, { encoding: "utf8", stdio: ["ignore", "pipe", "inherit"] });
    process.stdout.write(p.stdout);
    if (p.status !== 0) throw new Error(`pathtracer exited with ${p.status}`);
    spp = Number(/rendered (\d+) spp/.exec(p.stdout)?.[1] ?? NaN);
    const gl = p.stdout.split("\n").find((l) => l.startsWith("GL:")) ?? "";
    how = `native build/native/pathtracer render (the same shaders and estimator as the page), ${seconds} s, ${spp} spp, ${gl.trim()}`;
    rgb = readPfm(path).rgb;
  } else {
    const [adapter] = await loadAdapters([name]);
    const server = await startServer(adapter.mounts(ctxFor(name)));
    try {
      const r = await runOnce(adapter, server, [seconds * 1e3], console.log);
      const last = r.records.at(-1);
      rgb = r.images.at(-1);
      spp = last.paths / (width * height);
      pageUrl = r.url;
      how = `a ${seconds}-s run of the same page in ${r.browser} (${r.info.renderer}), ${fmt(last.paths / (width * height), 2)} spp`;
    } finally {
      server.close();
    }
    writePfm(path, width, height, rgb);
  }
  const meta = { tracer: name, how, seconds, spp, url: pageUrl, date: new Date().toISOString(), mean: meanRgb(rgb) };
  writeFileSync(path + ".json", JSON.stringify(meta, null, 2));
  console.log(`wrote ${path}: ${how}; mean ${meta.mean.map((v) => v.toFixed(4)).join(" ")}`);
}

try {
  if (command === "run") await commandRun();
  else if (command === "reference") await commandReference();
  else if (command === "report") commandReport();
  else throw new Error(`unknown command '${command}' (run | reference | report)`);
} catch (e) {
  console.error(`peers: ${e.stack ?? e}`);
  process.exit(1);
}
