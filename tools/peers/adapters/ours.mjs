// Our page (web/index.html; the site build, tools/site.sh -> build/site, or build/web with
// the source tree's scenes/ and assets/). window.peerBench is added by an init script that
// reads the page's own hooks (window.ptLoadStatus, Module._pt_radiance): the page itself
// is benchmarked as users run it (its tiles, its panel, the denoiser on by default).
import { existsSync } from "node:fs";
import { join } from "node:path";

export const name = "ours";
export const title = "our page (WebGL 2 fragment pass)";

export function mounts(ctx) {
  const site = join(ctx.repo, "build/site");
  if (!ctx.ourBuild && existsSync(join(site, "pathtracer.wasm"))) return [["/ours/", site]];
  const web = join(ctx.repo, ctx.ourBuild ?? "build/web");
  if (!existsSync(join(web, "pathtracer.wasm")))
    throw new Error(`our page is not built: no ${web}/pathtracer.wasm (bash tools/site.sh, or cmake --build --preset web)`);
  return [["/ours/scenes/", join(ctx.repo, "scenes")], ["/ours/assets/", join(ctx.repo, "assets")], ["/ours/", web]];
}

export function url(ctx) {
  const q = new URLSearchParams(`scene=reference/scene2.xml&size=${ctx.width}x${ctx.height}&bounces=${ctx.bounces}`);
  for (const [k, v] of new URLSearchParams(ctx.extra ?? "")) q.set(k, v);
  return `/ours/index.html?${q.toString().replace(/%2F/g, "/")}`;
}

// The contract over the page's hooks. Runs in the page before its scripts.
function shim() {
  const bench = { state: "loading", error: null, info: {}, records: [], timers: [] };
  const status = () => (window.ptLoadStatus ? window.ptLoadStatus() : null);
  // RGB floats of the running mean, rows bottom to top (Module._pt_radiance reads it back).
  function readImage() {
    const M = window.Module, countPtr = M._malloc(4);
    const ptr = M._pt_radiance(countPtr);
    const count = M.HEAP32[countPtr >> 2];
    M._free(countPtr);
    const src = M.HEAPF32.subarray(ptr >> 2, (ptr >> 2) + count), rgb = new Float32Array((count / 4) * 3);
    for (let i = 0, j = 0; i < count; i += 4, j += 3) { rgb[j] = src[i]; rgb[j + 1] = src[i + 1]; rgb[j + 2] = src[i + 2]; }
    return rgb;
  }
  function b64(floats) {
    const u8 = new Uint8Array(floats.buffer, floats.byteOffset, floats.byteLength);
    let s = "";
    for (let i = 0; i < u8.length; i += 0x8000) s += String.fromCharCode.apply(null, u8.subarray(i, i + 0x8000));
    return btoa(s);
  }
  // The first complete image: polled every 20 ms (the page's frames are ~40 ms).
  const poll = setInterval(() => {
    let s = null;
    try { s = status(); } catch (e) { return; }
    if (!s) return;
    if (s.error) { bench.error = s.error; bench.state = "error"; clearInterval(poll); return; }
    if (bench.state === "loading" && !s.loading && s.loads > 0) bench.state = "compiling";
    if (s.samples >= 1) {
      bench.info.firstImageMs = performance.now();  // since navigation start
      bench.info.compileMs = s.compileMs;
      bench.info.lastLoadMs = s.lastLoad && s.lastLoad.ms;
      bench.info.accel = s.accel;  // the traversal the page chose (flat or bvh; the URL's accel=)
      try { const st = window.ptStats(); bench.info.renderer = st.renderer; bench.info.width = st.width; bench.info.height = st.height; } catch (e) {}
      bench.state = "rendering";
      clearInterval(poll);
    }
  }, 20);
  window.peerBench = {
    state: () => bench.state,
    error: () => bench.error,
    info: () => bench.info,
    start(checkpoints) {
      const t0 = performance.now(), s0 = status();
      bench.state = "timing";
      const sorted = checkpoints.slice().sort((a, b) => a - b);
      for (const cp of sorted)
        bench.timers.push(setTimeout(() => {
          const tMs = performance.now() - t0, s = status();
          const rgb = readImage();
          bench.records.push({ tMs, samples: s.samples - s0.samples, paths: s.paths - s0.paths, rgb, late: tMs > cp + 500,
                               readMs: performance.now() - t0 - tMs });
          if (bench.records.length === sorted.length) bench.state = "done";
        }, cp));
    },
    records: () => bench.records.map((r) => ({ tMs: r.tMs, samples: r.samples, paths: r.paths, late: r.late, readMs: r.readMs })),
    image: (k) => b64(bench.records[k].rgb),
  };
}

export async function prepare(context, _ctx) {
  await context.addInitScript(shim);
}
