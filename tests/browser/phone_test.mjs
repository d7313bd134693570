// Browser test of the page on phones (issue 16; Debian's Chromium, headless, SwiftShader):
//
//   node tests/browser/phone_test.mjs [--web build/web] [--out build/browser-test] [--only phone,limits]
//
// phone: Playwright's device emulation of an iPhone-sized (390x844) and an Android-sized
//   (412x915) screen, hasTouch, isMobile, device pixel ratio 3, with real touch events
//   (CDP Input.dispatchTouchEvent). Both: the panel starts collapsed to its bar and a tap
//   expands it (to rows of 40-52 CSS px), a tap on the panel leaves the camera alone, one
//   finger's drag changes the view (the app's, then the address follows), a tap on the sphere selects it, no
//   console errors. The iPhone also: a double tap resets the view to the scene's, a pinch
//   moves the camera (fingers together: back), a two-finger pan strafes, the panel's button
//   collapses it, turning the phone resizes the canvas and keeps the view and the bar; and
//   it opens on a ?cam= link, which a desktop page then opens too: the same camera and the
//   same image (mean).
// limits (phone_limits.mjs): the mobile GPU's limits, each hidden from the page by a
//   test-only init script that wraps getExtension / getSupportedExtensions / getParameter /
//   getShaderPrecisionFormat: no EXT_color_buffer_float (half-float accumulation, a note,
//   the same image within the half floats' error); neither float nor half-float targets
//   (a message instead of a black canvas); no OES_texture_float_linear (a note, the same
//   image: nothing filters 32-bit float textures); MAX_TEXTURE_SIZE 4096 (the scenes
//   render; a scene with a 4097-texel-wide map fails naming the scene and the map, the
//   previous scene keeps rendering); MAX_TEXTURE_SIZE 2048 (a message); fragment highp
//   of 16 bits (a note; rendering goes on); a context lost in the background (visibility
//   hidden), not restored (a message to reload), then restored (the render resumes).
// Screenshots (phone-*.png) go to the out folder. 'ok - NAME' / 'not ok - NAME: why', then
// a summary.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { camOf, check, checkWebBuild, launcher, liveScene, options, quad, run, startServer, stats, until } from "./app_lib.mjs";
import { flatHdr, limitChecks, limitScript } from "./phone_limits.mjs";

const { groups, webDir, outDir } = options("phone_test.mjs", ["phone", "limits"]);
const shot = (page, name) => page.screenshot({ path: join(outDir, `phone-${name}.png`) });
const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));
const camNumbers = (cam) => decodeURIComponent(cam).split(",").map(Number);
const addressCam = (page) => page.evaluate(() => new URLSearchParams(location.search).get("cam"));
// The app's own view now (the address follows it only every 500 ms).
const appCam = async (page) => camOf(await stats(page));

const phones = [
  { name: "iphone", viewport: { width: 390, height: 844 }, size: "39x84" },
  { name: "android", viewport: { width: 412, height: 915 }, size: "41x91" },
];
const phoneContext = (p) => ({ viewport: p.viewport, deviceScaleFactor: 3, isMobile: true, hasTouch: true });

async function open(context, url, errors, limits = null) {
  const page = await context.newPage();
  page.on("console", (m) => { if (m.type() === "error") errors.push(`console: ${m.text()}`); });
  page.on("pageerror", (e) => errors.push(`page error: ${e.message}`));
  if (limits) await page.addInitScript(limitScript, limits);
  await page.goto(url);
  await page.waitForFunction(() => { try { return window.ptUi() !== null || !document.getElementById("error").hidden; } catch { return false; } },
                             null, { timeout: 60000, polling: 200 });
  return page;
}

// Real touch events: each step lists the fingers down (CSS pixels); [] lifts them all.
function toucher(cdp) {
  const send = (type, pts) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: pts.map(([x, y], i) => ({ x, y, id: i })) });
  return {
    async gesture(from, to, steps = 8) {
      await send("touchStart", from);
      for (let k = 1; k <= steps; k++) {
        await send("touchMove", from.map(([x, y], i) => [x + (to[i][0] - x) * k / steps, y + (to[i][1] - y) * k / steps]));
        await sleep(30);
      }
      await send("touchEnd", []);
    },
    // The events of a tap are sent together: each waits for the page's main thread to
    // take it (the listener is not passive), which SwiftShader keeps busy for hundreds of
    // milliseconds a frame at this canvas size, and the touch's time is when it was sent.
    async tap(x, y, times = 1) {
      const events = [];
      for (let k = 0; k < times; k++) events.push(send("touchStart", [[x, y]]), send("touchEnd", []));
      await Promise.all(events);
    },
  };
}
// The app's view once the page has drawn a frame after the gesture (every touch event is
// in the recogniser once CDP's dispatch returns; the next frame applies what is left of
// it): read from the app itself (pt_view_query, cheap), not the address, which follows
// it only every 500 ms and lags most on a loaded machine.
const viewCam = (page) => page.evaluate(() => decodeURIComponent(/cam=([^&]+)/.exec(Module.UTF8ToString(Module._pt_view_query()))[1]));
const settled = async (page) => {
  await page.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
  return viewCam(page);
};
// The address catches up with the app's view (within 10 s, however loaded the machine).
const addressFollows = async (page) => {
  const cam = await viewCam(page);
  await until(page, (c) => new URLSearchParams(location.search).get("cam") === c, cam, 10000).catch(() => {});
  return { cam, address: await addressCam(page) };
};

const kLink = "cam=0.4,0.3,5.5,97,-4";
const kSceneCam = "0,0,6,90,0";  // live.xml's camera, as the address writes it

// The iPhone gets every gesture and opens on a link (the link check's phone half); the
// Android phone a tap, a drag and the panel (SwiftShader draws a 1236x2745 canvas slowly:
// the whole test stays near two minutes).
async function phoneChecks(context, url, phone, full) {
  const errors = [];
  const t0 = Date.now(), at = (what) => console.log(`# ${phone.name}: ${what} at ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  const page = await open(context, `${url}?scene=live.xml&size=${phone.size}&limit=4${full ? "&" + kLink : ""}`, errors);
  const cdp = await page.context().newCDPSession(page);
  const touch = toucher(cdp);
  const { width: W, height: H } = phone.viewport;
  await until(page, () => window.ptLoadStatus().samples >= 4, null, 240000);  // a loaded machine: the first frames are slow
  let s = await stats(page);
  const linked = { cam: camOf(s), mean: s.mean };
  let ui = await page.evaluate(() => window.ptUi());
  const dpr = ui.pixelsPerCss;
  await shot(page, `${phone.name}-collapsed`);
  at("opened");
  check(`${phone.name}: the panel starts collapsed to its bar on a touch screen`, ui.compact && ui.panelCollapsed && ui.touchScreen &&
        dpr === 3 && ui.bar[2] > 0 && ui.panel[2] === 0, JSON.stringify(ui));
  const camStart = await settled(page);

  if (!full) {  // the view is the scene's: its centre is the sphere
    await touch.tap(W * 0.5, H * 0.5);
    await until(page, () => window.ptStats().selected >= 0, null, 10000).catch(() => {});
    s = await stats(page);
    check(`${phone.name}: a tap selects the object under it`, s.selectedKind === "Sphere" && s.selectedLine === 5 && camOf(s) === kSceneCam,
          `selected ${s.selected} ${s.selectedKind} line ${s.selectedLine}, cam ${camOf(s)}`);
  }

  // One finger drags (above the Selection panel, at the bottom once something is
  // selected): the view turns; the address follows.
  await touch.gesture([[W * 0.5, H * 0.3]], [[W * 0.5 + 80, H * 0.3 - 30]]);
  const camDragged = await settled(page);
  const [, , , yaw0, pitch0] = camNumbers(camStart), [, , , yaw1, pitch1] = camNumbers(camDragged);
  check(`${phone.name}: a one-finger drag turns the view`, yaw1 > yaw0 + 5 && pitch1 > pitch0 + 1,
        `cam ${camStart} -> ${camDragged}`);
  const follows = await addressFollows(page);
  check(`${phone.name}: the address follows the view`, follows.address === follows.cam, `address ${follows.address}, view ${follows.cam}`);
  at("dragged");

  // A double tap: the scene's view (not the link's).
  let camReset = camDragged;
  if (full) {
    await touch.tap(W * 0.5, H * 0.8, 2);
    camReset = await settled(page);
    check(`${phone.name}: a double tap resets the view to the scene's camera`, camReset === kSceneCam, `cam ${camDragged} -> ${camReset}, scene ${kSceneCam}`);
    await sleep(400);  // not a third tap of the double tap
  }

  // Two fingers pinched together: back (+z here, the camera looks down -z).
  let camPinched = camReset;
  if (full) {
    await touch.gesture([[W * 0.5 - 110, H * 0.6], [W * 0.5 + 110, H * 0.6]], [[W * 0.5 - 40, H * 0.6], [W * 0.5 + 40, H * 0.6]]);
    camPinched = await settled(page);
    const p0 = camNumbers(camReset), p1 = camNumbers(camPinched);
    check(`${phone.name}: a pinch moves the camera (together: back)`, p1[2] > p0[2] + 0.5 && Math.abs(p1[0] - p0[0]) < 0.2 && p1[3] === p0[3],
          `cam ${camReset} -> ${camPinched}`);
    at("pinched");
  }
  if (full) {
    await until(page, () => window.ptLoadStatus().samples >= 1);  // an image to look at (SwiftShader is slow at this canvas)
    await shot(page, `${phone.name}-pinched`);
    // Two fingers moved together to the right: the camera strafes left (the image follows).
    await touch.gesture([[W * 0.5 - 60, H * 0.6], [W * 0.5 + 60, H * 0.6]], [[W * 0.5 + 40, H * 0.6], [W * 0.5 + 160, H * 0.6]]);
    const camPanned = await settled(page);
    const p1 = camNumbers(camPinched), p2 = camNumbers(camPanned);
    check(`${phone.name}: a two-finger pan strafes (the image follows the fingers)`, p2[0] < p1[0] - 0.3 && Math.abs(p2[2] - p1[2]) < 0.1 &&
          p2[3] === p1[3], `cam ${camPinched} -> ${camPanned}`);
    // The scene's view again, and a tap on the sphere (the image's centre) selects it.
    await touch.tap(W * 0.5, H * 0.9, 2);
    await settled(page);
    await sleep(400);
    await touch.tap(W * 0.5, H * 0.5);
    await until(page, () => window.ptStats().selected >= 0, null, 10000).catch(() => {});
    await until(page, () => window.ptLoadStatus().samples >= 1);
    s = await stats(page);
    await shot(page, `${phone.name}-tapped`);
    check(`${phone.name}: a tap selects the object under it`, s.selectedKind === "Sphere" && s.selectedLine === 5 && camOf(s) === kSceneCam,
          `selected ${s.selected} ${s.selectedKind} line ${s.selectedLine}, cam ${camOf(s)}`);
    at("tapped");
  }

  // The bar, tapped: the panel; its button: the bar again.
  const camBefore = await appCam(page);
  const bar = ui.bar, tapBar = () => touch.tap((bar[0] + bar[2] * 0.5) / dpr, (bar[1] + bar[3] * 0.5) / dpr);
  await tapBar();
  await until(page, () => !window.ptUi().panelCollapsed && window.ptUi().panel[3] > 0, null, 10000).catch(() => {});
  await page.waitForTimeout(300);
  ui = await page.evaluate(() => window.ptUi());
  await shot(page, `${phone.name}-expanded`);
  const rowCss = ui.rowPixels / dpr;
  check(`${phone.name}: a tap on the bar expands the panel, with rows a finger hits`, !ui.panelCollapsed && ui.panel[3] > 0 &&
        rowCss >= 40 && rowCss <= 52 && ui.fontPixels === 45, JSON.stringify(ui));
  const camAfterTap = await appCam(page), selectedAfterTap = (await stats(page)).selected;
  check(`${phone.name}: a tap on the panel is the panel's, not the camera's`, camAfterTap === camBefore && selectedAfterTap >= 0,
        `cam ${camBefore} -> ${camAfterTap}, selected ${selectedAfterTap}`);
  at("expanded");
  if (full) {
    await touch.tap((ui.hide[0] + ui.hide[2] * 0.5) / dpr, (ui.hide[1] + ui.hide[3] * 0.5) / dpr);  // the first row's button
    await until(page, () => window.ptUi().panelCollapsed, null, 10000).catch(() => {});
    check(`${phone.name}: the panel's button collapses it again`, (await page.evaluate(() => window.ptUi())).panelCollapsed);
    // Expanded again: a drag up on the panel's background scrolls it, and is not the
    // camera's either.
    await tapBar();
    await until(page, () => !window.ptUi().panelCollapsed && window.ptUi().panel[3] > 0, null, 10000).catch(() => {});
    let panel = null;  // as drawn once its size has settled (auto-resized over a frame or two)
    for (let k = 0; k < 20; k++) {
      await page.waitForTimeout(200);
      const now = (await page.evaluate(() => window.ptUi())).panel;
      if (panel && now.join() === panel.join()) break;
      panel = now;
    }
    // The background right of the denoise checkbox (on its own row on a phone, above the
    // save buttons, which now sit where the old left-hand point near the bottom was; the
    // scroll bar is the panel's last 22 CSS px).
    const x = (panel[0] + panel[2]) / dpr - 120, y = (panel[1] + panel[3]) / dpr - 25 - 1.5 * rowCss;
    await touch.gesture([[x, y]], [[x, y - 200]]);
    await until(page, () => window.ptUi().panelScroll > 0, null, 10000).catch(() => {});
    const scrolled = await page.evaluate(() => window.ptUi());
    const camAfterScroll = await appCam(page);
    check(`${phone.name}: a drag on the panel's background scrolls it`, scrolled.panelScroll > 100 && camAfterScroll === camBefore,
          `scroll ${scrolled.panelScroll}, cam ${camAfterScroll} (was ${camBefore})`);
    // Turned sideways: the canvas follows, the view stays.
    await page.setViewportSize({ width: H, height: W });
    await until(page, (w) => document.getElementById("canvas").width === w, H * 3, 10000).catch(() => {});
    await until(page, () => window.ptLoadStatus().samples >= 1);
    s = await stats(page);
    const canvas = await page.evaluate(() => [document.getElementById("canvas").width, document.getElementById("canvas").height]);
    ui = await page.evaluate(() => window.ptUi());
    check(`${phone.name}: turning the phone resizes the canvas, keeps the view and the (expanded) compact panel`, canvas[0] === H * 3 &&
          canvas[1] === W * 3 && camOf(s) === kSceneCam && ui.compact && !ui.panelCollapsed, `canvas ${canvas}, cam ${camOf(s)} (was ${kSceneCam}), ui ${JSON.stringify(ui)}`);
    await shot(page, `${phone.name}-landscape`);
    at("turned");
  }
  check(`${phone.name}: no console or page errors`, errors.length === 0, errors.join(" | "));
  await page.close();
  return linked;
}

// The same link on a desktop: the phone's camera and image (its mean).
async function linkCheck(context, url, phone) {
  const errors = [];
  const page = await open(context, `${url}?scene=live.xml&size=${phones[0].size}&limit=4&${kLink}`, errors);
  await until(page, () => window.ptStats().samples >= 4);
  const s = await stats(page);
  await page.close();
  const rel = Math.max(...s.mean.map((v, k) => Math.abs(v - phone.mean[k]) / Math.max(phone.mean[k], 1e-6)));
  console.log(`# the same link: phone cam ${phone.cam} mean ${phone.mean.map((v) => v.toFixed(5))}, desktop cam ${camOf(s)} mean ${s.mean.map((v) => v.toFixed(5))}`);
  check("the same ?cam= link shows the same view on a phone and on a desktop", phone.cam === camOf(s) && phone.cam.startsWith("0.4,0.3,5.5") && rel < 1e-4,
        `cams ${phone.cam} / ${camOf(s)}, means ${phone.mean} / ${s.mean} (rel ${rel})`);
  check("no console or page errors (desktop link)", errors.length === 0, errors.join(" | "));
}

async function main() {
  mkdirSync(outDir, { recursive: true });
  checkWebBuild(webDir);
  const tmp = mkdtempSync(join(tmpdir(), "pt-phone-test-"));
  const scenes = join(tmp, "scenes");
  mkdirSync(scenes);
  writeFileSync(join(scenes, "live.xml"), liveScene("0.5 0.5 0.5"));
  writeFileSync(join(scenes, "quad.obj"), quad(1));
  // An environment map and image maps (the shipped ones, through the dev server's /assets).
  writeFileSync(join(scenes, "tex.xml"), `<SceneLevel>
  <Camera position="0 0 6" yaw="90" pitch="-10"/>
  <Environment map="../assets/env/afternoon.hdr"/>
  <Objects>
    <Sphere center="0 0 0" radius="1.5"><Attenuate color="0.8 0.8 0.8"><Diffuse/></Attenuate></Sphere>
    <Plane normal="0 1 0" d="-1.5"><Textured diffuse="../assets/textures/wood_diffuse.png" specular="../assets/textures/wood_specular.png"
      normal="../assets/textures/wood_normal.png" n="80" uvScale="0.5 0.5"/></Plane>
  </Objects>
</SceneLevel>
`);
  writeFileSync(join(scenes, "wide.hdr"), flatHdr(4097));
  writeFileSync(join(scenes, "wide-env.xml"), liveScene("0.5 0.5 0.5").replace(/<Environment[^>]*>/, '<Environment map="wide.hdr"/>'));
  const server = await startServer([webDir, "0", "--dev", "--scenes", scenes]);
  const userDir = mkdtempSync(join(tmpdir(), "pt-chromium-"));
  const launch = launcher(userDir);
  const t0 = Date.now();
  try {
    if (groups.has("phone")) {
      let linked = null;
      for (const [k, p] of phones.entries()) {
        const context = await launch(phoneContext(p));
        const seen = await phoneChecks(context, server.url, p, k === 0);
        if (k === 0) linked = seen;
        await context.close();
      }
      const context = await launch({ viewport: { width: 480, height: 320 } });
      await linkCheck(context, server.url, linked);
      await context.close();
    }
    if (groups.has("limits")) {
      const context = await launch({ viewport: { width: 480, height: 320 } });
      await limitChecks(context, server.url, open, shot);
      await context.close();
    }
  } finally {
    console.log(`# phone test: ${((Date.now() - t0) / 1000).toFixed(0)} s`);
    server.child.kill();
    rmSync(userDir, { recursive: true, force: true });
    rmSync(tmp, { recursive: true, force: true });
  }
}

await run(main);
