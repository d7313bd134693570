// The page loading large scenes while another renders: for each scene (under scenes/,
// comma-separated), the time from the request to the swap, the animation frames meanwhile
// and the five longest gaps between them with the stage shown then, and the page's own
// figures (lastLoad). No screenshots (they cost the page frames). Build the web target first.
//   NODE_PATH=/usr/share/nodejs node tools/probe_load.mjs [bench/million.xml,...]
import { createRequire } from "node:module";
import { spawn } from "node:child_process";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
const repo = join(dirname(fileURLToPath(import.meta.url)), "..");
const require = createRequire(join(repo, "tests/browser/package.json"));
const { chromium } = require("playwright-core");
const srv = spawn(process.execPath, [join(repo, "tools/serve.mjs"), join(repo, "build/web"), "0"], { stdio: ["ignore", "pipe", "inherit"] });
const url = await new Promise((ok) => srv.stdout.on("data", (d) => { const m = String(d).match(/http:\/\/\S+/); if (m) ok(m[0]); }));
const b = await chromium.launch({ executablePath: "/usr/bin/chromium", headless: true, args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-vsync"] });
try {
  for (const scene of (process.argv[2] || "bench/million.xml").split(",")) {
    const page = await b.newPage({ viewport: { width: 960, height: 640 } });
    await page.goto(`${url.replace(/\/$/, "")}/?scene=reference/scene2.xml&size=96x64&limit=0`);
    await page.waitForFunction(() => ((window.ptLoadStatus && window.ptLoadStatus()) || {}).samples >= 2, null, { timeout: 60000 });
    const r = await page.evaluate((sc) => new Promise((done) => {
      const gaps = []; let last = performance.now(), swap = -1; const t0 = last;
      window.ptLoadScene("/scenes/" + sc);
      const tick = () => {
        const now = performance.now(); const s = window.ptLoadStatus();
        if (swap < 0) gaps.push({ ms: now - last, stage: s.loading ? s.loading.stage : "-" });
        last = now;
        if (swap < 0 && s.scene.endsWith(sc)) swap = now - t0;
        if ((swap >= 0 && s.samples >= 1) || (s.error && !s.loading) || now - t0 > 120000) done({ swap, gaps, s });
        else requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
    }), scene);
    r.gaps.sort((a, b) => b.ms - a.ms);
    const n = r.gaps.length, med = r.gaps[Math.floor(n / 2)].ms;
    console.log(`${scene}: shown ${r.swap.toFixed(0)} ms after the request; ${n} animation frames, median gap ${med.toFixed(0)} ms; longest: ` +
      r.gaps.slice(0, 5).map((g) => `${g.ms.toFixed(0)} (${g.stage})`).join(", ") + `; error ${r.s.error}; lastLoad ${JSON.stringify(r.s.lastLoad)}`);
    await page.close();
  }
} finally { await b.close(); srv.kill(); }
