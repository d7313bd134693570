// Browser test of the page as an application (Debian's Chromium, headless, SwiftShader):
//
//   node tests/browser/app_test.mjs [--web build/web] [--out build/browser-test] [--only dev,view]
// (the loading, pacing and site checks: load_test.mjs; shared helpers: app_lib.mjs)
//
// Serves the web build with the dev server (tools/serve.mjs --dev) over a temporary scenes/
// folder and checks: the served scene loads; clicking an object selects it (and the sky
// clears it); dragging a value of the selection re-renders without compiling a program;
// an edit of the scene file, and of a mesh it references, re-renders within a second and
// keeps the camera; a broken edit shows file:line and the last scene keeps rendering, its
// accumulation going on from where it was;
// keys move the camera only with the canvas focused and no modifier held; a scene dropped
// on the page (synthetic drop with a DataTransfer) and one chosen with the file picker
// load; the resolution-scale slider changes the render size; the camera moving renders
// at reduced size and refines at full size; losing and restoring the WebGL context
// (WEBGL_lose_context) resumes the same image; the device pixel ratio sizes the canvas.
// Screenshots go to the out folder. 'ok - NAME' / 'not ok - NAME: why', then a summary.
import { mkdirSync } from "node:fs";
import { join } from "node:path";
import { camOf, check, checkWebBuild, liveScene, openPage, options, put, quad, run, shot as shotIn, stats, until, withLiveServer } from "./app_lib.mjs";

const { groups, webDir, outDir } = options("app_test.mjs", ["dev", "view"]);
const shot = (page, name) => shotIn(page, name, outDir);

async function devChecks(context, url, dir) {
  const errors = [];
  const page = await openPage(context, `${url}?scene=live.xml&size=96x64&limit=4`, errors);
  await until(page, () => window.ptStats().samples >= 4);
  let s = await stats(page);
  check("the dev server's scene loads (fetched from the served folder)", s.scene === "/scenes/live.xml" && !s.error &&
        s.files.length === 2 && s.files[1] === "/scenes/quad.obj", JSON.stringify({ scene: s.scene, error: s.error, files: s.files }));

  // Picking: the canvas (960x640) shows the 96x64 image scaled 10x; its centre is the sphere.
  await page.mouse.click(480, 320);
  await until(page, () => window.ptStats().selected >= 0, null, 10000).catch(() => {});
  s = await stats(page);
  await shot(page, "picked");
  check("clicking an object selects it", s.selectedKind === "Sphere" && s.selectedLine === 5,
        `selected ${s.selected} ${s.selectedKind} line ${s.selectedLine}`);
  const camBefore = camOf(s);

  await page.mouse.click(480, 20);  // the sky
  await until(page, () => window.ptStats().selected < 0, null, 10000).catch(() => {});
  check("clicking the sky clears the selection", (await stats(page)).selected === -1);
  await page.mouse.click(480, 320);
  await until(page, () => window.ptStats().selected >= 0, null, 10000).catch(() => {});

  // Its radius, dragged in the selection panel (top right): a new image, no new program.
  await until(page, () => window.ptStats().samples >= 4);
  const before = await stats(page);
  await page.mouse.move(730, 103);
  await page.mouse.down();
  for (let x = 740; x <= 900; x += 10) await page.mouse.move(x, 103);
  await page.mouse.up();
  await until(page, (m) => { const t = window.ptStats(); return t.samples >= 4 && t.mean[0] !== m; }, before.mean[0]);
  s = await stats(page);
  await shot(page, "edited");
  console.log(`# radius dragged: mean ${before.mean[0].toFixed(4)} -> ${s.mean[0].toFixed(4)}, programs ${before.programsCompiled} -> ${s.programsCompiled}`);
  check("editing the selection re-renders without compiling", Math.abs(s.mean[0] / before.mean[0] - 1) > 0.02 &&
        s.programsCompiled === before.programsCompiled && s.loads === before.loads && camOf(s) === camBefore,
        `mean ${before.mean[0]} -> ${s.mean[0]}, programs ${before.programsCompiled} -> ${s.programsCompiled}, view ${camBefore} -> ${camOf(s)}`);


  // The reload loop: the scene file edited (a red sky; its own camera moved, which the
  // reload must not apply) re-renders within a second, keeping the view.
  await until(page, () => window.ptStats().samples >= 4);
  s = await stats(page);
  const view = camOf(s);
  let t0 = Date.now();
  put(join(dir, "live.xml"), liveScene("1 0 0", "0 0 9"));
  await until(page, (n) => window.ptStats().loads > n, s.loads, 10000).catch(() => {});
  const reloadMs = Date.now() - t0;
  await until(page, () => window.ptStats().samples >= 1, null, 10000).catch(() => {});
  const firstImageMs = Date.now() - t0;
  await until(page, () => window.ptStats().samples >= 4);
  const red = await stats(page);
  await shot(page, "reloaded");
  console.log(`# scene edit -> reloaded in ${reloadMs} ms, first samples on screen after ${firstImageMs} ms; mean ${red.mean.map((v) => v.toFixed(3)).join(" ")}`);
  check("an edited scene re-renders within a second, keeping the camera",
        reloadMs < 1000 && red.mean[0] > 2 * red.mean[1] && camOf(red) === view && !red.error,
        `reload ${reloadMs} ms, first samples ${firstImageMs} ms, mean ${red.mean}, view ${view} -> ${camOf(red)}, error ${red.error}`);

  // A referenced file edited: the quad grows, hiding sky.
  t0 = Date.now();
  put(join(dir, "quad.obj"), quad(2));
  await until(page, (n) => window.ptStats().loads > n, red.loads, 10000).catch(() => {});
  const meshMs = Date.now() - t0;
  await until(page, () => window.ptStats().samples >= 4);
  const bigger = await stats(page);
  check("an edited mesh re-renders the scene", meshMs < 1000 && bigger.mean[0] < red.mean[0] * 0.95,
        `reload ${meshMs} ms, red ${red.mean[0]} -> ${bigger.mean[0]}`);

  // A broken edit: the error with file and line; the last scene keeps rendering and keeps
  // its samples (the accumulation goes on from where it was, not restarted), and its image
  // changes only by converging. The broken file also turns the sky green, which would show
  // if any of it were applied.
  await page.evaluate(() => window.ptSetLimit(0));
  await until(page, () => window.ptLoadStatus().samples >= 12);
  const kept = await stats(page);
  put(join(dir, "live.xml"), liveScene("0 1 0").replace('radius="1.5"', 'radius="-1"'));
  await until(page, () => typeof window.ptLoadStatus().error === "string", null, 10000).catch(() => {});
  const atError = await page.evaluate(() => window.ptLoadStatus());
  await until(page, (n) => window.ptLoadStatus().samples >= n, atError.samples + 12, 60000).catch(() => {});
  const broken = await stats(page);
  await page.evaluate(() => window.ptSetLimit(8));
  await shot(page, "broken-edit");
  const drift = Math.max(...broken.mean.map((v, k) => Math.abs(v - kept.mean[k]) / Math.max(kept.mean[k], 1e-3)));
  console.log(`# broken edit: samples ${kept.samples} before, ${atError.samples} when the error showed, ${broken.samples} after; ` +
              `mean ${kept.mean.map((v) => v.toFixed(4)).join(" ")} -> ${broken.mean.map((v) => v.toFixed(4)).join(" ")}`);
  check("a broken edit shows file:line and keeps the last scene",
        /live\.xml:5: <Sphere>/.test(broken.error ?? "") && broken.loads === bigger.loads && broken.scene === "/scenes/live.xml",
        `error ${broken.error}, loads ${bigger.loads} -> ${broken.loads}, scene ${broken.scene}`);
  check("a failed reload keeps the accumulation: samples go on from where they were, the image only converges",
        atError.samples >= kept.samples && broken.samples >= atError.samples + 12 && drift < 0.05 && broken.mean[1] < 2 * kept.mean[1] + 0.01,
        `samples ${kept.samples} -> ${atError.samples} (error) -> ${broken.samples}, mean ${kept.mean} -> ${broken.mean} (drift ${drift.toFixed(3)})`);
  put(join(dir, "live.xml"), liveScene("0.5 0.5 0.5"));
  await until(page, (n) => window.ptStats().loads > n && !window.ptStats().error, broken.loads, 10000).catch(() => {});
  check("fixing the edit loads it again", (await stats(page)).error === null);

  // Keys (after the reload checks, which need the scene's view): only with the canvas focused and no modifier held.
  const hold = async (key, ms = 400) => { await page.keyboard.down(key); await page.waitForTimeout(ms); await page.keyboard.up(key); };
  await page.focus("#open");
  const c0 = camOf(await stats(page));
  await hold("KeyW");
  const c1 = camOf(await stats(page));
  await page.focus("#canvas");
  await page.keyboard.down("Control");
  await hold("KeyW");
  await page.keyboard.up("Control");
  const c2 = camOf(await stats(page));
  await hold("KeyW");
  const c3 = camOf(await stats(page));
  check("keys move the camera only with canvas focus and no modifier", c0 === c1 && c1 === c2 && c3 !== c2,
        `cam: unfocused ${c0} -> ${c1}, ctrl ${c2}, focused ${c3}`);

  // Drag and drop: a scene and its mesh as loose files, dispatched as a real drop event.
  await page.evaluate(({ xml, obj }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([xml], "dropped.xml", { type: "application/xml" }));
    dt.items.add(new File([obj], "quad.obj"));
    document.getElementById("canvas").dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, { xml: liveScene("0 1 0"), obj: quad(1) });
  const dropped0 = Date.now();
  // Its first samples, read in the same call as its size: the new scene starts at full
  // size, not at the motion size of the last view's key hold above (which a restart
  // would then throw away).
  const first = await until(page, () => {
    const f = window.ptStats();
    return f.scene.startsWith("/drop/") && f.samples >= 1 && { samples: f.samples, size: [f.width, f.height] };
  }, null, 30000).then((h) => h.jsonValue(), () => null);
  const waited = await until(page, () => window.ptStats().scene.startsWith("/drop/") && window.ptStats().samples >= 2, null, 30000)
    .then(() => "", () => "timed out; ");
  s = await stats(page);
  check("a dropped scene renders at once at its size, not at the last view's motion size",
        first !== null && first.size[0] === s.width && first.size[1] === s.height && s.width === 96,
        `first samples ${JSON.stringify(first)}, then ${s.width}x${s.height}`);
  await shot(page, "dropped");
  check("a dropped scene with its mesh loads", s.scene === "/drop/1/dropped.xml" && !s.error && s.mean[1] > 2 * s.mean[0] &&
        s.files.includes("/drop/1/quad.obj"), `${waited}after ${Date.now() - dropped0} ms: ` +
        JSON.stringify({ scene: s.scene, error: s.error, mean: s.mean, samples: s.samples, loads: s.loads, size: [s.width, s.height] }));

  // The file picker: the same through <input type=file>.
  await page.setInputFiles("#picker", [{ name: "picked.xml", mimeType: "application/xml", buffer: Buffer.from(liveScene("0 0 1")) },
                                       { name: "quad.obj", mimeType: "text/plain", buffer: Buffer.from(quad(1)) }]);
  await until(page, () => window.ptStats().scene.endsWith("picked.xml") && window.ptStats().samples >= 2, null, 30000).catch(() => {});
  s = await stats(page);
  check("a scene chosen with the file picker loads", s.scene === "/drop/2/picked.xml" && !s.error && s.mean[2] > 2 * s.mean[0],
        JSON.stringify({ scene: s.scene, error: s.error, mean: s.mean }));

  // A dropped folder: the browser hands directory entries (FileSystemDirectoryEntry),
  // which a synthetic DataTransfer cannot hold, so the drop event carries stand-ins with
  // the same interface: a folder with the scene at its top, its mesh in a subfolder
  // (the scene's src says meshes/quad.obj), an older scene deeper down, and a directory
  // reader that answers in two batches before the empty one.
  await page.evaluate(({ xml, old, obj }) => {
    const file = (name, text) => ({ isFile: true, isDirectory: false, name, file: (ok) => ok(new File([text], name)) });
    const dir = (name, children) => ({
      isFile: false, isDirectory: true, name,
      createReader: () => {
        const batches = [children.slice(0, 1), children.slice(1), []];
        return { readEntries: (ok) => ok(batches.shift()) };
      },
    });
    const root = dir("myscene", [dir("old", [file("backup.xml", old)]), file("scene.xml", xml), dir("meshes", [file("quad.obj", obj)])]);
    const dt = { files: [], items: [{ webkitGetAsEntry: () => root }] };
    const ev = new Event("drop", { bubbles: true, cancelable: true });
    Object.defineProperty(ev, "dataTransfer", { value: dt });
    document.getElementById("canvas").dispatchEvent(ev);
  }, { xml: liveScene("1 0.5 0").replace('src="quad.obj"', 'src="meshes/quad.obj"'), old: liveScene("0 0 0"), obj: quad(1) });
  await until(page, () => window.ptStats().scene.endsWith("/myscene/scene.xml") && window.ptStats().samples >= 2, null, 30000).catch(() => {});
  s = await stats(page);
  check("a dropped folder loads its top scene with the files in its subfolders",
        s.scene === "/drop/3/myscene/scene.xml" && !s.error && s.mean[0] > 1.5 * s.mean[2] && s.files.includes("/drop/3/myscene/meshes/quad.obj"),
        JSON.stringify({ scene: s.scene, error: s.error, mean: s.mean, files: s.files }));

  // Context loss and restore: rendering stops, then resumes with the same image.
  await page.evaluate(() => window.ptLoadScene("/scenes/live.xml"));
  await page.evaluate(() => window.ptSetLimit(4));
  await until(page, () => window.ptStats().scene === "/scenes/live.xml" && window.ptStats().samples >= 4);
  const good = await stats(page);
  await page.evaluate(() => { window.ptLose = document.getElementById("canvas").getContext("webgl2").getExtension("WEBGL_lose_context"); window.ptLose.loseContext(); });
  await page.waitForTimeout(500);
  await shot(page, "context-lost");
  await page.evaluate(() => window.ptLose.restoreContext());
  await until(page, () => window.ptStats().contextRestores === 1 && window.ptStats().samples >= 4, null, 60000).catch(() => {});
  s = await stats(page);
  await shot(page, "context-restored");
  const rel = Math.max(...s.mean.map((v, k) => Math.abs(v - good.mean[k]) / good.mean[k]));
  check("a lost and restored WebGL context resumes the render", s.contextRestores === 1 && s.samples >= 4 && rel < 1e-3 &&
        s.view === good.view, `restores ${s.contextRestores}, samples ${s.samples}, mean ${good.mean} -> ${s.mean}`);

  check("no console or page errors (dev page)", errors.length === 0, errors.join(" | "));
  await page.close();
}

async function viewChecks(context, url) {
  const errors = [];
  const page = await openPage(context, `${url}?scene=live.xml&limit=1`, errors);
  // A 1280x800 sweep: with SwiftShader the pacing gives it up to ~1000 frames at ~30/s.
  await until(page, () => window.ptStats().samples >= 1, null, 180000);
  const canvas = await page.evaluate(() => [document.getElementById("canvas").width, devicePixelRatio]);
  let s = await stats(page);
  check("the canvas and render follow the device pixel ratio", canvas[1] === 2 && canvas[0] === 2 * 640 && s.width === canvas[0],
        `canvas ${canvas[0]} at dpr ${canvas[1]}, render ${s.width}x${s.height}`);
  // The resolution-scale slider (main panel, under "resolution"), clicked near its left end.
  await page.mouse.click(20, 321);  // (no Light section in this scene; below the mode combo)
  await until(page, () => window.ptStats().renderScale < 0.5, null, 10000).catch(() => {});
  await until(page, () => window.ptStats().samples >= 1, null, 30000).catch(() => {});
  s = await stats(page);
  await shot(page, "resolution-scale");
  check("the resolution-scale slider changes the render size", s.renderScale < 0.5 && Math.abs(s.width - Math.round(canvas[0] * s.renderScale)) <= 1,
        `scale ${s.renderScale}, render ${s.width}x${s.height}`);
  // Moving: half the size while a key is held, full size once it stops.
  const full = s.width;
  await page.focus("#canvas");
  await page.keyboard.down("KeyA");
  await page.waitForTimeout(300);
  const moving = (await stats(page)).width;
  await page.keyboard.up("KeyA");
  await page.waitForTimeout(600);
  const settled = (await stats(page)).width;
  check("moving renders at reduced size, then refines at full size", moving === Math.round(full * 0.5) && settled === full,
        `full ${full}, moving ${moving}, settled ${settled}`);
  check("no console or page errors (view page)", errors.length === 0, errors.join(" | "));
  await page.close();
}

async function main() {
  mkdirSync(outDir, { recursive: true });
  checkWebBuild(webDir);
  await withLiveServer(webDir, "pt-app-test-", async ({ url, sceneDir, launch }) => {
    if (groups.has("dev")) {
      const context = await launch({ viewport: { width: 960, height: 640 } });
      await devChecks(context, url, sceneDir);
      await context.close();
    }
    if (groups.has("view")) {
      const context = await launch({ viewport: { width: 640, height: 400 }, deviceScaleFactor: 2 });
      await viewChecks(context, url);
      await context.close();
    }
  });
}

await run(main);
