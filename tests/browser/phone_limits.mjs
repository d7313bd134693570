// The limits group of phone_test.mjs (issue 16): the mobile GPU's limits, each hidden from
// the page by a test-only init script (limitScript, installed with page.addInitScript
// before the page loads), and what the page must do about each (README "The page").
import { check, stats, until } from "./app_lib.mjs";

// The test-only init script: hides extensions, lowers parameters, lowers highp.
export function limitScript({ hide = [], params = {}, highp = null }) {
  const P = WebGL2RenderingContext.prototype;
  const getExtension = P.getExtension, supported = P.getSupportedExtensions, getParameter = P.getParameter;
  const precision = P.getShaderPrecisionFormat;
  P.getExtension = function (name) { return hide.includes(name) ? null : getExtension.call(this, name); };
  P.getSupportedExtensions = function () { return (supported.call(this) || []).filter((n) => !hide.includes(n)); };
  P.getParameter = function (p) { return String(p) in params ? params[p] : getParameter.call(this, p); };
  if (highp !== null) {
    P.getShaderPrecisionFormat = function (shader, type) {
      const r = precision.call(this, shader, type);
      return shader === this.FRAGMENT_SHADER && type === this.HIGH_FLOAT ? { rangeMin: 15, rangeMax: 15, precision: highp } : r;
    };
  }
}

// A Radiance HDR, flat (not run-length) scan lines: w x 1 grey texels.
export function flatHdr(w) {
  const head = Buffer.from(`#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X ${w}\n`);
  const px = Buffer.alloc(w * 4);
  for (let i = 0; i < w; i++) px.set([128, 128, 128, 129], i * 4);
  return Buffer.concat([head, px]);
}

// open(context, url, errors, limits): phone_test's page opener; shot(page, name).
export async function limitChecks(context, url, open, shot) {
  const t0 = Date.now(), at = (what) => console.log(`# limits: ${what} at ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  const meanOf = async (scene, limits) => {
    const errors = [];
    const page = await open(context, `${url}?scene=${scene}&size=32x32&limit=4`, errors, limits);
    // (or a message in place of the canvas: no app, no stats)
    await until(page, () => !document.getElementById("error").hidden || (window.ptLoadStatus()?.samples >= 4 && window.ptLimits() !== null));
    const s = (await stats(page)) ?? { mean: [NaN, NaN, NaN], samples: 0, accumFormat: null, scene: null, error: "no app" };
    const notes = (await page.evaluate(() => window.ptLimits())) ?? [];
    const box = await page.evaluate(() => (document.getElementById("limits").hidden ? "" : document.getElementById("limits").textContent));
    return { page, s, notes, box, errors };
  };
  const relDiff = (a, b) => Math.max(...a.map((v, k) => Math.abs(v - b[k]) / Math.max(Math.abs(b[k]), 1e-6)));

  // Nothing hidden: the reference image (an environment map and image maps), no notes.
  const base = await meanOf("tex.xml", null);
  check("a desktop GPU: 32-bit float accumulation, no notes (an environment map and image maps)", base.s.accumFormat === "rgba32f" &&
        base.notes.length === 0 && base.box === "" && base.s.scene === "/scenes/tex.xml" && !base.s.error,
        JSON.stringify({ format: base.s.accumFormat, notes: base.notes, scene: base.s.scene, error: base.s.error }));
  // The context lost while the page is in the background (a phone's hidden tab).
  {
    const page = base.page;
    const setVisibility = (state) => page.evaluate((v) => {
      Object.defineProperty(document, "visibilityState", { value: v, configurable: true });
      Object.defineProperty(document, "hidden", { value: v === "hidden", configurable: true });
      document.dispatchEvent(new Event("visibilitychange"));
    }, state);
    await setVisibility("hidden");
    await page.evaluate(() => { window.ptLose = document.getElementById("canvas").getContext("webgl2").getExtension("WEBGL_lose_context"); window.ptLose.loseContext(); });
    await setVisibility("visible");
    await until(page, () => /reload the page/.test(document.getElementById("status").textContent), null, 10000).catch(() => {});
    const status = await page.evaluate(() => (document.getElementById("status").hidden ? "" : document.getElementById("status").textContent));
    await shot(page, "context-lost-background");
    check("a context lost in the background and not restored: a message to reload", /reload the page/.test(status), `status '${status}'`);
    await page.evaluate(() => window.ptLose.restoreContext());
    await until(page, () => window.ptStats().contextRestores === 1 && window.ptStats().samples >= 4, null, 60000).catch(() => {});
    const s = await stats(page);
    const shown = await page.evaluate(() => !document.getElementById("status").hidden);
    check("then restored: the render resumes, the message goes", s.contextRestores === 1 && relDiff(s.mean, base.s.mean) < 1e-3 && !shown,
          `restores ${s.contextRestores}, mean ${base.s.mean} -> ${s.mean}, status shown ${shown}`);
    check("no console or page errors (reference, context loss)", base.errors.length === 0, base.errors.join(" | "));
    await page.close();
  }
  at("reference and context loss");

  // No EXT_color_buffer_float: half floats, said so; the same image within their error.
  const half = await meanOf("tex.xml", { hide: ["EXT_color_buffer_float"] });
  await shot(half.page, "limits-half-float");
  await half.page.close();
  const dHalf = relDiff(half.s.mean, base.s.mean);
  console.log(`# half-float accumulation: mean ${half.s.mean.map((v) => v.toFixed(5))} vs ${base.s.mean.map((v) => v.toFixed(5))} (rel ${dHalf.toExponential(2)})`);
  check("no EXT_color_buffer_float: accumulates in half floats, says so, the same image", half.s.accumFormat === "rgba16f" &&
        /half floats/.test(half.box) && dHalf < 5e-3 && half.errors.length === 0,
        JSON.stringify({ format: half.s.accumFormat, box: half.box, dHalf, errors: half.errors }));
  at("half floats");
  // Neither: a message in place of the canvas, not a black page.
  {
    const errors = [];
    const page = await open(context, `${url}?scene=live.xml&size=32x32&limit=4`, errors, { hide: ["EXT_color_buffer_float", "EXT_color_buffer_half_float"] });
    const text = await page.evaluate(() => (document.getElementById("error").hidden ? "" : document.getElementById("error").textContent));
    await shot(page, "limits-no-float");
    check("no float render targets at all: a message instead of a black canvas", /floating-point/.test(text), `error box: '${text}'`);
    await page.close();
  }
  // A phone's GPU in one page: no OES_texture_float_linear, MAX_TEXTURE_SIZE 4096, 16-bit
  // highp in fragment shaders: each noted; the same image (nothing filters 32-bit float
  // textures, every texture fits, the precision is only reported); a 4097-texel-wide map
  // fails naming the scene and the map while the last scene keeps rendering.
  const phone = await meanOf("tex.xml", { hide: ["OES_texture_float_linear"], params: { 3379: 4096 }, highp: 16 });
  const dPhone = relDiff(phone.s.mean, base.s.mean);
  await phone.page.evaluate(() => window.ptOpenScene("/scenes/wide-env.xml"));  // fetched, then loaded
  await until(phone.page, () => window.ptLoadStatus().error !== null, null, 30000).catch(() => {});
  const after = await stats(phone.page);
  await shot(phone.page, "limits-phone-gpu");
  await phone.page.close();
  const notes = phone.notes.join(" ");
  check("no OES_texture_float_linear: says so, the same image (an environment map, image maps)", dPhone === 0 &&
        /OES_texture_float_linear/.test(notes), JSON.stringify({ notes, dPhone }));
  check("fragment highp below 24 bits: says so, renders anyway", /16-bit highp/.test(notes) && phone.s.samples >= 4, JSON.stringify({ notes }));
  check("MAX_TEXTURE_SIZE 4096: the scene renders as before, no note about it", dPhone === 0 && !/MAX_TEXTURE_SIZE/.test(notes), notes);
  check("MAX_TEXTURE_SIZE 4096: a 4097-texel map fails naming the scene and the map; the last scene keeps rendering",
        /wide-env\.xml/.test(after.error ?? "") && /environment map/.test(after.error ?? "") && /4096/.test(after.error ?? "") &&
        after.scene === "/scenes/tex.xml" && after.samples >= 4,
        JSON.stringify({ error: after.error, scene: after.scene, samples: after.samples }));
  check("no console or page errors (a phone's GPU)", phone.errors.length === 0, phone.errors.join(" | "));
  at("a phone's GPU");
  // MAX_TEXTURE_SIZE 2048 (the least WebGL 2 allows): the scene data cannot fit: a message.
  {
    const errors = [];
    const page = await open(context, `${url}?scene=live.xml&size=32x32&limit=4`, errors, { params: { 3379: 2048 } });
    await until(page, () => window.ptLimits() !== null, null, 30000).catch(() => {});
    const box = await page.evaluate(() => document.getElementById("limits").textContent);
    const s = await page.evaluate(() => window.ptLoadStatus());
    await shot(page, "limits-2048");
    check("MAX_TEXTURE_SIZE 2048: says that no scene fits, and why", /MAX_TEXTURE_SIZE is 2048/.test(box) && /GL_MAX_TEXTURE_SIZE/.test(s.error ?? ""),
          JSON.stringify({ box, error: s.error }));
    await page.close();
  }
  at("2048");
}
