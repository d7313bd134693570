// Hours of use in one page (Debian's Chromium, headless, SwiftShader):
//   node tests/browser/endurance_test.mjs [--web build/web] [--native build/native/pathtracer]
//                                         [--out build/browser-test] [--scale 1]
//                                         [--snapshots DIR]
// In one page: loads the shipped scenes in turn (every scenes/**/*.xml but the
// 1.3-million-triangle bench scene, which load_test.mjs loads), loses and restores the
// WebGL context, makes selection edits (the sphere's radius dragged in the Selection panel)
// and reloads of an edited scene (the dev server's reload loop). --scale 1 is the full run:
// 200 loads, 20 context losses, 100 edits, 50 reloads, by hand; tools/test.sh runs
// --scale 0.2 (40 loads, 4 losses, 20 edits, 10 reloads: the first round, then 3 measured
// rounds of each; docs/reliability.md "Hours of use in the page" has the times). After a
// first round of each (every scene once, one loss, five edits, two reloads), the wasm heap
// in use (dlmalloc's count), the live GL objects of the program's GL wrappers (ptStats().glObjects), the WebGL objects the page holds (counted by
// wrapping WebGL2RenderingContext's create and delete calls in an init script) and the JS
// heap (after a forced collection, CDP) are recorded; after everything they must be within
// 5% of those values (GL objects: equal counts; a count below 20 may differ by at most one;
// the JS heap: its objects, see jsObjectBytes).
// No console errors, and the Cornell box's image at the end matches the native render.
import { mkdirSync, readdirSync, statSync, writeFileSync } from "node:fs";
import { join, relative } from "node:path";
import { check, checkWebBuild, liveScene, meanStdError, nativeMean, openPage, put, repo, run, stats, withLiveServer } from "./app_lib.mjs";

const opt = { web: "build/web", native: "build/native/pathtracer", out: "build/browser-test", scale: "1", snapshots: "" };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, "");
  if (!(key in opt) || i + 1 >= process.argv.length) {
    console.error("usage: node endurance_test.mjs [--web DIR] [--native BINARY] [--out DIR] [--scale S] [--snapshots DIR]");
    process.exit(2);
  }
  opt[key] = process.argv[i + 1];
}
const scale = Number(opt.scale);
const full = { loads: 200, losses: 20, edits: 100, reloads: 50 };
const total = Object.fromEntries(Object.entries(full).map(([k, v]) => [k, Math.max(2, Math.round(v * scale))]));
const webDir = join(repo, opt.web), nativeBin = join(repo, opt.native), outDir = join(repo, opt.out);
const kTolerance = 0.05;
const kSize = [64, 40];  // the render size of every load (fast in SwiftShader)

// Waits in the page for fn(arg) to hold (a plain promise: Playwright's waitForFunction
// leaves closures behind for each wait, which the heap check would count).
const until = (page, fn, arg, timeout = 60000) => page.evaluate(([src, a, ms]) => new Promise((ok, fail) => {
  const f = new Function("return " + src)(), t0 = performance.now();
  const poll = () => { if (f(a)) ok(); else if (performance.now() - t0 > ms) fail(new Error("timed out: " + src)); else setTimeout(poll, 50); };
  poll();
}), [fn.toString(), arg, timeout]);

// Counts of live WebGL objects, by wrapping the context's create and delete calls. A lost
// context takes its objects with it: the counts start again from zero.
const countGlObjects = () => {
  const live = {};
  let generation = 0;
  window.ptWebglLive = live;
  const kinds = ["Buffer", "Framebuffer", "Program", "Renderbuffer", "Shader", "Texture", "VertexArray", "Query", "Sampler"];
  const proto = WebGL2RenderingContext.prototype;
  for (const kind of kinds) {
    live[kind] = 0;
    const create = proto["create" + kind], del = proto["delete" + kind];
    proto["create" + kind] = function (...a) { const o = create.apply(this, a); if (o) { live[kind]++; o.__ptGen = generation; } return o; };
    proto["delete" + kind] = function (o) {
      if (o && !o.__ptDeleted && o.__ptGen === generation) { o.__ptDeleted = true; live[kind]--; }
      return del.call(this, o);
    };
  }
  addEventListener("webglcontextlost", () => { generation++; for (const k of kinds) live[k] = 0; }, true);
};

function shippedScenes() {
  const out = [];
  const walk = (dir) => {
    for (const name of readdirSync(dir).sort()) {
      const p = join(dir, name);
      if (statSync(p).isDirectory()) walk(p);
      else if (name.endsWith(".xml")) out.push("/" + relative(repo, p));
    }
  };
  walk(join(repo, "scenes"));
  return out.filter((p) => p !== "/scenes/bench/million.xml");
}

// The bytes of the page's JavaScript objects, from a heap snapshot after a collection:
// objects, closures, arrays, strings and numbers, and the characters of external strings,
// which live outside V8's heap: TextDecoder's strings (so every UTF8ToString and
// FS.readFile as text) get their header's size (~60 bytes) and their characters a native
// node "system / ExternalStringData" (identical texts decoded twice share one). Apart,
// the backing stores of ArrayBuffers ("system / JSArrayBufferData", not the wasm memory's,
// whose use heapUsed measures: skipped by its byte length); apart because they are mostly
// the page's package data (6.6 MB, constant), which would drown the objects' 5%.
// Not counted: V8's compiled code (it tiers up for minutes) and other native objects, which
// hold the browser's bounded buffers (console messages for DevTools, performance entries,
// DevTools' network log). The console messages' arguments are JS strings, though, kept by
// V8's inspector for a DevTools client (Playwright has Runtime enabled) up to its cap of
// 1,000 messages (tests/browser/console_bound.mjs shows the cap): measure() counts the heap
// with them and, checked, without them (Runtime.discardConsoleEntries empties that buffer).
const kJsTypes = new Set(["object", "closure", "array", "string", "concatenated string", "sliced string", "heap number", "regexp", "bigint"]);
async function jsObjectBytes(cdp, wasmBytes, saveAs) {
  const chunks = [];
  const take = (e) => chunks.push(e.chunk);
  cdp.on("HeapProfiler.addHeapSnapshotChunk", take);
  await cdp.send("HeapProfiler.takeHeapSnapshot", { reportProgress: false });
  cdp.off("HeapProfiler.addHeapSnapshotChunk", take);
  if (saveAs) writeFileSync(saveAs, chunks.join(""));
  const snap = JSON.parse(chunks.join(""));
  const fields = snap.snapshot.meta.node_fields, types = snap.snapshot.meta.node_types[0];
  const n = fields.length, type = fields.indexOf("type"), size = fields.indexOf("self_size"), name = fields.indexOf("name");
  let bytes = 0, chars = 0, buffers = 0;
  for (let i = 0; i < snap.nodes.length; i += n) {
    const t = types[snap.nodes[i + type]], b = snap.nodes[i + size];
    if (kJsTypes.has(t)) bytes += b;
    else if (t !== "native") continue;
    else if (snap.strings[snap.nodes[i + name]] === "system / ExternalStringData") chars += b;
    else if (snap.strings[snap.nodes[i + name]] === "system / JSArrayBufferData" && b !== wasmBytes) buffers += b;
  }
  return { bytes: bytes + chars, chars, buffers };
}

// --snapshots DIR keeps each measurement's heap snapshot (DIR/round-N.heapsnapshot) for
// tests/browser/heap_diff.mjs.
let round = 1;
async function measure(page, cdp) {
  await page.evaluate(() => performance.clearResourceTimings());
  await cdp.send("HeapProfiler.collectGarbage");
  const js = await cdp.send("Runtime.getHeapUsage");
  const wasmBytes = await page.evaluate(() => (window.Module?.HEAP8 ?? window.HEAP8)?.buffer.byteLength ?? -1);
  const jsWithConsole = (await jsObjectBytes(cdp, wasmBytes)).bytes;
  await cdp.send("Runtime.discardConsoleEntries");
  await cdp.send("HeapProfiler.collectGarbage");
  const { bytes: jsObjects, chars, buffers } = await jsObjectBytes(cdp, wasmBytes, opt.snapshots && join(opt.snapshots, `round-${round++}.heapsnapshot`));
  const s = await stats(page);
  const webgl = await page.evaluate(() => ({ ...window.ptWebglLive }));
  // The lengths of Emscripten's tables from GL names to WebGL objects (printed, not checked:
  // what they hold is in jsObjects).
  const tables = await page.evaluate(() => Object.fromEntries(["textures", "framebuffers", "programs", "shaders", "vaos", "buffers"]
    .map((k) => [k, GL[k] ? GL[k].length : -1])));
  return { heapUsed: s.heapUsed, glObjects: s.glObjects, webgl, jsObjects, chars, buffers, jsWithConsole, jsHeap: js.usedSize, tables,
           pending: s.pendingPrograms };
}

function within(name, first, last) {
  const lines = [];
  let ok = true;
  const cmp = (what, a, b, counts) => {
    const okOne = counts ? (a < 20 ? Math.abs(b - a) <= 1 : b === a) : Math.abs(b - a) <= kTolerance * Math.max(a, 1);
    ok &&= okOne;
    lines.push(`${what} ${a} -> ${b}${okOne ? "" : " (!)"}`);
  };
  cmp("wasm heap in use", first.heapUsed, last.heapUsed, false);
  cmp("JS objects", first.jsObjects, last.jsObjects, false);
  lines.push(`of which external strings' characters ${first.chars} -> ${last.chars}`);
  cmp("ArrayBuffers' stores (not the wasm memory)", first.buffers, last.buffers, false);
  lines.push(`JS objects with the console buffer (not checked: bounded by the browser) ${first.jsWithConsole} -> ${last.jsWithConsole}`);
  lines.push(`V8 heap in use (not checked: compiled code and the browser's buffers too) ${first.jsHeap} -> ${last.jsHeap}`);
  for (const k of Object.keys(first.glObjects)) cmp(`gl ${k}`, first.glObjects[k], last.glObjects[k], true);
  for (const k of Object.keys(first.webgl)) cmp(`webgl ${k}`, first.webgl[k], last.webgl[k], true);
  console.log(`# ${name}: ${lines.join(", ")}`);
  return ok;
}

async function main() {
  mkdirSync(outDir, { recursive: true });
  checkWebBuild(webDir);
  const scenes = shippedScenes();
  const t0 = Date.now();
  await withLiveServer(webDir, "pt-endurance-", async ({ url, sceneDir, launch }) => {
    const context = await launch({ viewport: { width: 960, height: 640 } });
    await context.addInitScript(countGlObjects);
    const errors = [];
    const page = await openPage(context, `${url}?scene=live.xml&size=96x64&limit=2`, errors);
    const cdp = await context.newCDPSession(page);
    await until(page, () => window.ptLoadStatus().samples >= 2, null, 120000);
    const done = { loads: 0, losses: 0, edits: 0, reloads: 0 };
    const failures = [];
    const missed = [];  // edits that did not restart the render (printed; see the check below)

    // One shipped scene, loaded from the page's package, rendered to 1 sample.
    const loadNext = async () => {
      const path = scenes[done.loads % scenes.length];
      const before = (await page.evaluate(() => window.ptLoadStatus())).loads;
      await page.evaluate(([p, w, h]) => { window.ptSetSize(w, h); window.ptLoadScene(p); }, [path, ...kSize]);
      await until(page, ([p, n]) => { const s = window.ptLoadStatus(); return s.scene === p && s.loads > n && (s.samples >= 1 || s.error); },
                  [path, before], 180000);
      const s = await page.evaluate(() => window.ptLoadStatus());
      if (s.error) failures.push(`${path}: ${s.error}`);
      done.loads++;
    };
    // The live scene, for edits and reloads (fetched from the dev server).
    const openLive = async () => {
      const before = (await page.evaluate(() => window.ptLoadStatus())).loads;
      await page.evaluate(() => { window.ptSetSize(96, 64); window.ptOpenScene("/scenes/live.xml"); });
      await until(page, (n) => { const s = window.ptLoadStatus(); return s.scene === "/scenes/live.xml" && s.loads > n && s.samples >= 1; }, before);
    };
    const loseAndRestore = async () => {
      const n = (await stats(page)).contextRestores;
      await page.evaluate(() => { const e = document.getElementById("canvas").getContext("webgl2").getExtension("WEBGL_lose_context"); window.ptLose = e; e.loseContext(); });
      await page.waitForTimeout(100);
      await page.evaluate(() => window.ptLose.restoreContext());
      await until(page, (k) => window.ptStats().contextRestores > k && window.ptLoadStatus().samples >= 1, n, 120000);
      // And the restored image's first error estimate: the estimate's GL objects (its
      // targets and programs, made at its first use) then exist in every measured round
      // alike. (Measured without it, whether an estimate had run yet was a race: the page
      // spaces estimates by 20x their last cost, and a first one compiles its programs.
      // A fresh-clone CI run of 6b90453 counted 46 textures after the first round, 53
      // after the others.)
      await until(page, () => window.ptLoadStatus().relMSESamples >= 2, null, 120000);
      done.losses++;
    };
    // Picks the sphere (the canvas's centre) and drags its radius in the Selection panel.
    const edit = async () => {
      if ((await stats(page)).selected < 0) {
        await page.mouse.click(480, 320);
        await until(page, () => window.ptStats().selected >= 0, null, 10000);
      }
      // A restart (its epoch; the sample count alone, held at the page's limit of 2, can be
      // back at 2 before a poll sees it change), then a sample of the edited scene.
      const before = await page.evaluate(() => window.ptLoadStatus().epoch);
      const dir = done.edits % 2 ? -1 : 1;
      await page.mouse.move(800, 103);
      await page.mouse.down();
      for (let k = 1; k <= 3; ++k) await page.mouse.move(800 + dir * 15 * k, 103);
      await page.mouse.up();
      const t = Date.now();
      const took = await until(page, (b) => window.ptLoadStatus().epoch !== b && window.ptLoadStatus().samples >= 1, before, 20000)
        .then(() => true, () => false);
      if (!took) missed.push(`edit ${done.edits + 1}: no new image in ${((Date.now() - t) / 1000).toFixed(0)} s`);
      done.edits++;
    };
    const reload = async () => {
      const before = (await page.evaluate(() => window.ptLoadStatus())).loads;
      const grey = (0.3 + 0.4 * (done.reloads % 2)).toFixed(1);
      put(join(sceneDir, "live.xml"), liveScene(`${grey} ${grey} ${grey}`));
      await until(page, (n) => { const s = window.ptLoadStatus(); return s.loads > n && s.samples >= 1; }, before, 20000);
      done.reloads++;
    };
    const liveWork = async (edits, reloads) => {
      await openLive();
      for (let i = 0; i < edits; ++i) await edit();
      for (let i = 0; i < reloads; ++i) await reload();
    };

    // The first round, then the baseline. Each round ends with a context loss, and the
    // measurement is taken once the live scene is back: a loss empties the program cache,
    // which then holds the live scene's program alone, in every round alike. (The cache
    // keeps each program's generated source, 49-95 KB of text; measured after a
    // round's last load instead, its content, and the heap, depended on the scenes since
    // the last loss: 793 KB after the first round, 875 KB after the second, at --scale 0.2.)
    for (const _ of scenes) await loadNext();
    await liveWork(5, 2);
    await loseAndRestore();
    const first = await measure(page, cdp);
    console.log(`# first round in ${((Date.now() - t0) / 1000).toFixed(0)} s: ${JSON.stringify(done)}; wasm heap ${first.heapUsed}, JS objects ${first.jsObjects} (${first.chars} external strings' characters), ArrayBuffers ${first.buffers}, gl ${JSON.stringify(first.glObjects)}, programs pending ${JSON.stringify(first.pending)}`);

    // The rest, interleaved: scenes, edits and reloads of the live scene, a context loss.
    const rounds = Math.max(total.losses - 1, 1);
    for (let r = 0; r < rounds; ++r) {
      const share = (k) => Math.ceil((total[k] - done[k]) / (rounds - r));
      const loads = share("loads"), edits = share("edits"), reloads = share("reloads");
      for (let i = 0; i < loads; ++i) await loadNext();
      await liveWork(edits, reloads);
      await loseAndRestore();
      const m = await measure(page, cdp);
      console.log(`# round ${r + 2}: ${JSON.stringify(done)}; wasm heap ${m.heapUsed}, JS objects ${m.jsObjects} (${m.chars} external strings' characters; ${m.jsWithConsole} with the console buffer), V8 heap ${m.jsHeap}, gl ${JSON.stringify(m.glObjects)}, Emscripten's GL tables ${JSON.stringify(m.tables)}, programs pending ${JSON.stringify(m.pending)}, ${((Date.now() - t0) / 1000).toFixed(0)} s`);
    }
    const last = await measure(page, cdp);
    const seconds = (Date.now() - t0) / 1000;
    console.log(`# done in ${seconds.toFixed(0)} s: ${JSON.stringify(done)} (asked ${JSON.stringify(total)}), ${scenes.length} scenes in turn`);
    check(`${total.loads} loads, ${total.losses} context losses, ${total.edits} edits and ${total.reloads} reloads ran`,
          done.loads >= total.loads && done.losses >= total.losses && done.edits >= total.edits && done.reloads >= total.reloads,
          JSON.stringify(done));
    check("every shipped scene loaded without an error", failures.length === 0, failures.join(" | "));
    check("every edit restarted the render with a new image within 20 s", missed.length === 0, missed.join("; "));
    check("wasm heap, GL objects and JS heap back within 5% of the first round", within("memory and GL objects", first, last));

    // The Cornell box still renders what the native program renders.
    const spp = 32, [w, h] = [64, 64];
    await page.evaluate(([wd, ht, n]) => { window.ptSetSize(wd, ht); window.ptSetLimit(n); window.ptLoadScene("/scenes/reference/scene2.xml"); }, [w, h, spp]);
    await until(page, (n) => { const s = window.ptLoadStatus(); return s.scene === "/scenes/reference/scene2.xml" && s.samples >= n; }, spp, 120000);
    const s = await stats(page);
    const se = meanStdError(await page.evaluate(() => window.ptRadiance()), spp);
    const native = nativeMean(nativeBin, join(repo, "scenes/reference/scene2.xml"), w, h, spp, join(outDir, "endurance-native.png"));
    const tol = Math.max(0.01, 4 * Math.SQRT2 * se);
    const worst = native.error ? Infinity : Math.max(...s.mean.map((v, k) => Math.abs(v - native.mean[k]) / native.mean[k]));
    await page.screenshot({ path: join(outDir, "endurance-end.png") });
    check("after it, the Cornell box's mean matches the native render", worst <= tol,
          native.error ?? `worst ${(100 * worst).toFixed(2)}% > ${(100 * tol).toFixed(2)}%`);
    check("no console or page errors", errors.length === 0, errors.slice(0, 5).join(" | "));
    await context.close();
  });
}

await run(main);
