// Shared by the page's application tests (app_test.mjs, load_test.mjs, endurance_test.mjs...):
// options, the result list, the dev server, Chromium's flags, and helpers to open and poll
// the page.
import { spawn, spawnSync } from "node:child_process";
import { existsSync, mkdirSync, mkdtempSync, renameSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

export const repo = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
// Options of every application test: --web, --site, --out, --only (a comma-separated
// subset of the test's groups).
export function options(script, allGroups) {
  const opt = { web: "build/web", site: "build/site", out: "build/browser-test", only: "" };
  for (let i = 2; i < process.argv.length; i += 2) {
    const key = process.argv[i].replace(/^--/, "");
    if (!(key in opt) || i + 1 >= process.argv.length) {
      console.error(`usage: node ${script} [--web DIR] [--site DIR] [--out DIR] [--only ${allGroups.join(",")}]`);
      process.exit(2);
    }
    opt[key] = process.argv[i + 1];
  }
  return { groups: new Set(opt.only ? opt.only.split(",") : allGroups), webDir: resolve(repo, opt.web),
           siteDir: resolve(repo, opt.site), outDir: resolve(repo, opt.out) };
}
export const shot = (page, name, outDir) => page.screenshot({ path: join(outDir, `app-${name}.png`) });

const results = [];
export function check(name, ok, why = "") {
  results.push(ok);
  console.log(ok ? `ok - ${name}` : `not ok - ${name}: ${why}`);
}
// Runs main, prints the summary and exits 0 only when every check passed.
export async function run(main) {
  try {
    await main();
  } catch (e) {
    check("test ran to the end", false, e.stack ?? String(e));
  }
  const passed = results.filter(Boolean).length;
  console.log(`${passed} passed, ${results.length - passed} failed`);
  process.exit(results.length > 0 && passed === results.length ? 0 : 1);
}

export const chromeArgs = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-vsync",
                    "--disable-background-networking", "--disable-component-update", "--no-first-run", "--disable-sync"];

export function startServer(args) {
  const child = spawn(process.execPath, [join(repo, "tools/serve.mjs"), ...args], { stdio: ["ignore", "pipe", "inherit"] });
  return new Promise((ok, fail) => {
    let text = "";
    child.stdout.on("data", (d) => {
      text += d;
      const m = /Serving (http:\S+)/.exec(text);
      if (m) ok({ child, url: m[1] });
    });
    child.on("exit", (code) => fail(new Error(`serve.mjs exited with ${code}`)));
  });
}

// An editor's save: the new content appears at once (temporary file + rename).
export function put(path, text) {
  writeFileSync(path + ".tmp", text);
  renameSync(path + ".tmp", path);
}

// The live scene: a sphere in the middle (line 5), a blue quad mesh to its right.
export const liveScene = (sky, cam = "0 0 6") => `<SceneLevel>
  <Camera position="${cam}" yaw="90" pitch="0"/>
  <Environment color="${sky}"/>
  <Objects>
    <Sphere center="0 0 0" radius="1.5"><Attenuate color="0.8 0.8 0.8"><Diffuse/></Attenuate></Sphere>
    <Mesh src="quad.obj" position="2.6 0 0"><Attenuate color="0.2 0.2 0.8"><Diffuse/></Attenuate></Mesh>
  </Objects>
</SceneLevel>
`;
export const quad = (h) => `v -${h} -${h} 0\nv ${h} -${h} 0\nv ${h} ${h} 0\nv -${h} ${h} 0\nf 1 2 3 4\n`;

// The dev server (--dev: the reload loop) over a temporary scenes/ folder holding the live
// scene and its quad.obj, and a fresh Chromium profile: fn({ url, sceneDir, launch }) runs
// with them (launch(options) opens a browser context); then the server stops and both
// folders are removed. tmpPrefix names the temporary folder.
export async function withLiveServer(webDir, tmpPrefix, fn) {
  const tmp = mkdtempSync(join(tmpdir(), tmpPrefix));
  const sceneDir = join(tmp, "scenes"), assets = join(tmp, "assets");
  mkdirSync(sceneDir);
  mkdirSync(assets);
  writeFileSync(join(sceneDir, "live.xml"), liveScene("0.5 0.5 0.5"));
  writeFileSync(join(sceneDir, "quad.obj"), quad(1));
  const server = await startServer([webDir, "0", "--dev", "--scenes", sceneDir, "--assets", assets]);
  const userDir = mkdtempSync(join(tmpdir(), "pt-chromium-"));
  try {
    await fn({ url: server.url, sceneDir, launch: launcher(userDir) });
  } finally {
    server.child.kill();
    rmSync(userDir, { recursive: true, force: true });
    rmSync(tmp, { recursive: true, force: true });
  }
}

export async function openPage(context, url, errors) {
  const page = await context.newPage();
  page.on("console", (m) => { if (m.type() === "error") errors.push(`console: ${m.text()}`); });
  page.on("pageerror", (e) => errors.push(`page error: ${e.message}`));
  await page.goto(url);
  await page.waitForFunction(() => { try { return window.ptStats() !== null; } catch { return false; } }, null,
                             { timeout: 60000, polling: 200 });
  return page;
}
// The median (the mean of the middle two for an even count; NaN for none).
export const median = (a) => { const s = [...a].sort((p, q) => p - q); return s.length ? (s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2) : NaN; };
export const stats = (page) => page.evaluate(() => window.ptStats());
export const until = (page, fn, arg, timeout = 60000) => page.waitForFunction(fn, arg, { timeout, polling: 50 });
export const camOf = (s) => /cam=([^&]+)/.exec(s.view)[1];

export function checkWebBuild(webDir) {
  for (const f of ["index.html", "files.js", "pathtracer.js", "pathtracer.wasm", "pathtracer.data"])
    if (!existsSync(join(webDir, f))) throw new Error(`${join(webDir, f)} is missing: build with 'cmake --preset web && cmake --build --preset web'`);
}
export const launcher = (userDir) => (extra) =>
  chromium.launchPersistentContext(userDir, { executablePath: "/usr/bin/chromium", headless: true, args: chromeArgs, ...extra });

// The native headless render of a scene file (its mean radiance, from the CLI's report).
export function nativeMean(nativeBin, scenePath, w, h, samples, outPng) {
  if (!existsSync(nativeBin))
    return { error: `native binary ${nativeBin} not found: build it with 'cmake --preset native && cmake --build --preset native'` };
  const r = spawnSync(nativeBin, ["render", scenePath, "--spp", String(samples), "--size", `${w}x${h}`,
                                  "--out", outPng], { encoding: "utf8" });
  const m = /mean radiance: ([-+.\deE]+) ([-+.\deE]+) ([-+.\deE]+)/.exec(r.stdout ?? "");
  if (r.status !== 0 || !m) return { error: `native render failed (${r.status}): ${r.stderr || r.stdout}` };
  return { mean: m.slice(1, 4).map(Number) };
}

// The relative standard error of an image's mean luminance from the page's radiance
// read-back (RGBA floats; alpha bounds the variance of each pixel's samples' luminance:
// Accumulator::read_radiance).
export function meanStdError(px, samples) {
  let lum = 0, variance = 0;
  const n = px.length / 4;
  for (let i = 0; i < px.length; i += 4) {
    const l = 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2];
    lum += l;
    variance += px[i + 3];
  }
  return Math.sqrt(variance / samples) / n / (lum / n);
}
