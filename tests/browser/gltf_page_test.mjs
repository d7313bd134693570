// Browser test of a .glb or .gltf opened straight in the page (issue 13; Debian's Chromium,
// headless, SwiftShader):
//
//   node tests/browser/gltf_page_test.mjs [--web build/web] [--native build/native/pathtracer] [--out build/browser-test]
//
// No XML: the page renders a glTF file as the CLI does (`pathtracer render model.glb`:
// scene/gltf_scene.h, the default environment assets/env/afternoon.hdr, the framing camera
// or the file's own, path mode). Checked:
//   - by URL: ?scene=gltf/torus-instances.glb (relative to /scenes, the gallery's glTF
//     scene) loads, and its mean radiance at kSpp samples and kW x kH matches the native
//     render of the same file (tolerance as page_test.mjs: max(1%, 4 sqrt 2 SE));
//   - the gallery (the panel's scene list: window.ptScenes) lists it;
//   - by drop: the same .glb's bytes in a DataTransfer drop event load as /drop/N/..., the
//     same mean as native; then a .gltf with its .bin and two .png files as loose files
//     (assets/gltf/maps-quad.*), the same mean as its native render;
//   - a malformed .gltf dropped: the error names the file and the JSON pointer of the bad
//     element, and the previous scene keeps rendering (its samples go on);
//   - no console or page errors.
// 'ok - NAME' / 'not ok - NAME: why', then a summary. Screenshots gltf-*.png in the out folder.
import { mkdirSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { check, checkWebBuild, launcher, meanStdError, nativeMean, repo, run, startServer, stats, until } from "./app_lib.mjs";

const opt = { web: "build/web", native: "build/native/pathtracer", out: "build/browser-test" };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, "");
  if (!(key in opt) || i + 1 >= process.argv.length) {
    console.error("usage: node gltf_page_test.mjs [--web DIR] [--native BIN] [--out DIR]");
    process.exit(2);
  }
  opt[key] = process.argv[i + 1];
}
const webDir = resolve(repo, opt.web), nativeBin = resolve(repo, opt.native), outDir = resolve(repo, opt.out);
const shot = (page, name) => page.screenshot({ path: join(outDir, `gltf-${name}.png`) });

const kW = 96, kH = 64, kSpp = 16;
const kMeanRelFloor = 0.01;  // as page_test.mjs
const kMeanSigmas = 4 * Math.SQRT2;
const kGlb = "scenes/gltf/torus-instances.glb";
const kGltf = ["maps-quad.gltf", "maps-quad.bin", "maps-quad-base.png", "maps-quad-normal.png"];  // under assets/gltf/
// tests/cli_gltf.cmake's malformed file: POSITION names an accessor that does not exist.
const kBad = '{"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":5}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}';

// The page's mean at the sample limit against the native render of the same file.
async function compareMean(page, name, nativePath) {
  await until(page, (n) => window.ptLoadStatus().samples >= n, kSpp, 120000).catch(() => {});
  const s = await stats(page);
  const se = meanStdError(await page.evaluate(() => window.ptRadiance()), s.samples);
  const native = nativeMean(nativeBin, nativePath, kW, kH, kSpp, join(outDir, `gltf-native-${name}.png`));
  if (native.error) return check(`${name}: the mean matches the native render`, false, native.error);
  const rel = s.mean.map((v, k) => (v - native.mean[k]) / native.mean[k]);
  const worst = Math.max(...rel.map(Math.abs));
  const tol = Math.max(kMeanRelFloor, kMeanSigmas * se);
  console.log(`# ${name}: page ${s.scene} ${s.samples} spp ${s.width}x${s.height} mean ${s.mean.map((v) => v.toFixed(5)).join(" ")}; ` +
              `native ${native.mean.map((v) => v.toFixed(5)).join(" ")}; difference ${rel.map((r) => (100 * r).toFixed(2) + "%").join(" ")} ` +
              `(tolerance ${(100 * tol).toFixed(2)}%)`);
  check(`${name}: the mean matches the native render`, !s.error && s.samples === kSpp && s.width === kW && s.height === kH && worst <= tol,
        `error ${s.error}, ${s.samples} spp at ${s.width}x${s.height}, worst ${(100 * worst).toFixed(2)}% > ${(100 * tol).toFixed(2)}%`);
  return s;
}

// Files dropped on the canvas as a real drop event (DataTransfer of Files).
const drop = (page, files) => page.evaluate((list) => {
  const dt = new DataTransfer();
  for (const { name, bytes } of list) dt.items.add(new File([new Uint8Array(bytes)], name));
  document.getElementById("canvas").dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true, cancelable: true }));
}, files.map(({ name, bytes }) => ({ name, bytes: [...bytes] })));

async function main() {
  mkdirSync(outDir, { recursive: true });
  checkWebBuild(webDir);
  const server = await startServer([webDir, "0"]);
  const userDir = mkdtempSync(join(tmpdir(), "pt-chromium-"));
  const launch = launcher(userDir);
  const errors = [];
  try {
    const context = await launch({ viewport: { width: 480, height: 320 } });
    const page = await context.newPage();
    page.on("console", (m) => { if (m.type() === "error") errors.push(`console: ${m.text()}`); });
    page.on("pageerror", (e) => errors.push(`page error: ${e.message}`));

    // By URL, relative to /scenes as an XML scene is.
    await page.goto(`${server.url}?scene=gltf/torus-instances.glb&size=${kW}x${kH}&limit=${kSpp}`);
    await page.waitForFunction(() => { try { return window.ptLoadStatus() !== null; } catch { return false; } }, null,
                               { timeout: 60000, polling: 200 });
    let s = await compareMean(page, "by URL (.glb)", join(repo, kGlb));
    await shot(page, "url");
    check("by URL: the .glb is the scene, with the default environment", s.scene === "/scenes/gltf/torus-instances.glb" &&
          s.files.includes("/assets/env/afternoon.hdr"), JSON.stringify({ scene: s.scene, files: s.files }));
    const scenes = await page.evaluate(() => (window.ptScenes ? window.ptScenes() : null));
    check("the gallery lists the glTF scene", Array.isArray(scenes) && scenes.includes("/scenes/gltf/torus-instances.glb"), JSON.stringify(scenes));

    // By drop: the same .glb.
    await drop(page, [{ name: "torus-instances.glb", bytes: readFileSync(join(repo, kGlb)) }]);
    await until(page, () => window.ptStats().scene === "/drop/1/torus-instances.glb", null, 60000).catch(() => {});
    s = await compareMean(page, "by drop (.glb)", join(repo, kGlb));
    check("by drop: the .glb is the scene", s.scene === "/drop/1/torus-instances.glb", s.scene);

    // By drop: a .gltf with its buffer and images as loose files.
    await drop(page, kGltf.map((name) => ({ name, bytes: readFileSync(join(repo, "assets/gltf", name)) })));
    await until(page, () => window.ptStats().scene === "/drop/2/maps-quad.gltf", null, 60000).catch(() => {});
    s = await compareMean(page, "by drop (.gltf, .bin, .png)", join(repo, "assets/gltf/maps-quad.gltf"));
    await shot(page, "dropped-gltf");
    check("by drop: the .gltf is the scene, its buffer and images loaded", s.scene === "/drop/2/maps-quad.gltf" &&
          kGltf.every((f) => s.files.includes(`/drop/2/${f}`)), JSON.stringify({ scene: s.scene, files: s.files }));

    // A malformed .gltf: its error (the file and the JSON pointer), the previous scene goes on.
    await page.evaluate(() => window.ptSetLimit(0));
    const before = (await stats(page)).samples;
    await drop(page, [{ name: "bad.gltf", bytes: Buffer.from(kBad) }]);
    await until(page, () => !!window.ptStats().error, null, 30000).catch(() => {});
    await until(page, (n) => window.ptLoadStatus().samples > n + 2, before, 30000).catch(() => {});
    s = await stats(page);
    await shot(page, "malformed");
    check("a malformed .gltf shows its error with the JSON pointer, the previous scene keeps rendering",
          /bad\.gltf: \/meshes\/0\/primitives\/0\/attributes\/POSITION/.test(s.error ?? "") && s.scene === "/drop/2/maps-quad.gltf" &&
          s.samples > before, JSON.stringify({ error: s.error, scene: s.scene, samples: s.samples, before }));
    await context.close();
    check("no console or page errors", errors.length === 0, errors.join(" | "));
  } finally {
    server.child.kill();
    rmSync(userDir, { recursive: true, force: true });
  }
}

await run(main);
