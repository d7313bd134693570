// What the page's JS-objects count sees of text decoded by TextDecoder (docs/reliability.md
// "Hours of use in the page"):   node tests/browser/external_strings.mjs
// A blank page keeps 100 decoded strings of 1,507 characters, then 100 Uint8Array(1507),
// then 100 identical decoded strings; after each, the bytes of JS objects above the blank
// page's counted two ways: V8's heap types alone (the old count, blind to external
// strings' characters and ArrayBuffers' stores) and with the snapshot's native nodes
// "system / ExternalStringData" and "system / JSArrayBufferData" (endurance_test.mjs adds
// the first to its JS objects and checks the second apart). An experiment, not a test.
import { chromium } from "playwright-core";
import { chromeArgs } from "./app_lib.mjs";
const kJsTypes = new Set(["object", "closure", "array", "string", "concatenated string", "sliced string", "heap number", "regexp", "bigint"]);
const kOutside = new Set(["system / ExternalStringData", "system / JSArrayBufferData"]);
async function count(cdp) {
  const chunks = []; const take = (e) => chunks.push(e.chunk);
  cdp.on("HeapProfiler.addHeapSnapshotChunk", take);
  await cdp.send("HeapProfiler.collectGarbage");
  await cdp.send("HeapProfiler.takeHeapSnapshot", { reportProgress: false });
  cdp.off("HeapProfiler.addHeapSnapshotChunk", take);
  const s = JSON.parse(chunks.join("")); const f = s.snapshot.meta.node_fields, t = s.snapshot.meta.node_types[0], N = f.length;
  let js = 0, out = 0;
  for (let i = 0; i < s.nodes.length; i += N) {
    const ty = t[s.nodes[i + f.indexOf("type")]], b = s.nodes[i + f.indexOf("self_size")];
    if (kJsTypes.has(ty)) js += b; else if (ty === "native" && kOutside.has(s.strings[s.nodes[i + f.indexOf("name")]])) out += b;
  }
  return [js, js + out];
}
const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", headless: true, args: chromeArgs });
const page = await browser.newPage();
await page.setContent("<p>x</p>");
const cdp = await page.context().newCDPSession(page);
const base = await count(cdp);
await page.evaluate(() => { const td = new TextDecoder(); window.k = []; for (let i = 0; i < 100; ++i) window.k.push(td.decode(new TextEncoder().encode(String(i).padStart(4, "0") + "x".repeat(1503)))); });
const a = await count(cdp);
console.log(`100 TextDecoder strings of 1,507 characters: old count +${a[0] - base[0]} B, new count +${a[1] - base[1]} B`);
await page.evaluate(() => { window.k = null; window.b = []; for (let i = 0; i < 100; ++i) window.b.push(new Uint8Array(1507)); });
const b = await count(cdp);
console.log(`100 Uint8Array(1507) instead: old count +${b[0] - base[0]} B, new count +${b[1] - base[1]} B`);
await page.evaluate(() => { window.b = null; const td = new TextDecoder(); window.s = []; for (let i = 0; i < 100; ++i) window.s.push(td.decode(new TextEncoder().encode("x".repeat(1507)))); });
const c = await count(cdp);
console.log(`100 identical TextDecoder strings instead (Chromium shares their characters): old count +${c[0] - base[0]} B, new count +${c[1] - base[1]} B`);
await browser.close();
