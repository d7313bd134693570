// What a software GPU does with a large texture allocation: a bare WebGL 2 page in headless
// Chromium (SwiftShader) allocates the record textures of a million-triangle scene
// (texStorage2D, RGBA32F, 4096 wide: about 140 MB) at frame 30 and prints the longest gap
// between animation frames before, and the gaps after. The call returns at once; the GPU
// process allocates afterwards, and the page's next frame waits for it (docs/benchmarks.md).
//   NODE_PATH=/usr/share/nodejs node tools/probe_texture_alloc.mjs
import { createRequire } from "node:module";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
const require = createRequire(join(dirname(fileURLToPath(import.meta.url)), "../tests/browser/package.json"));
const { chromium } = require("playwright-core");
const b = await chromium.launch({ executablePath: "/usr/bin/chromium", headless: true, args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-vsync"] });
const page = await b.newPage();
await page.setContent("<canvas id=c width=96 height=64></canvas>");
const r = await page.evaluate(() => new Promise((done) => {
  const gl = document.getElementById("c").getContext("webgl2");
  const gaps = []; let last = performance.now(), frame = 0; const out = {};
  const tick = () => {
    const now = performance.now(); gaps.push(now - last); last = now; frame++;
    gl.clearColor(frame % 2, 0, 0, 1); gl.clear(gl.COLOR_BUFFER_BIT);
    if (frame === 30) {  // the record textures of a million triangles: 84 + 48 + small MB
      const t0 = performance.now();
      for (const rows of [5120, 3000, 640, 10]) { const t = gl.createTexture(); gl.bindTexture(gl.TEXTURE_2D, t); gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, 4096, rows); }
      out.callMs = performance.now() - t0; out.at = gaps.length;
    }
    if (frame < 90) requestAnimationFrame(tick); else done({ out, before: Math.max(...gaps.slice(2, 29)), after: gaps.slice(30, 40).map((g) => g.toFixed(0)) });
  };
  requestAnimationFrame(tick);
}));
console.log(JSON.stringify(r));
await b.close();
