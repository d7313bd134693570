// The browser's console buffer is bounded (docs/reliability.md "Hours of use in the page"):
//   node tests/browser/console_bound.mjs
// A blank page prints 3,000 lines of ~210 characters with Playwright listening (as the
// browser tests do); after each step, the bytes of JS objects in a heap snapshot (after a
// forced collection) above the blank page's. V8's inspector keeps each console message's
// arguments (V8ConsoleMessageStorage: at most 1,000 messages, 10 MB) while a DevTools
// client has Runtime enabled, so the JS heap grows with what a page prints until the
// 1,000th message and is flat after it; Runtime.discardConsoleEntries empties it. An
// experiment that prints its figures, not a test.
import { chromium } from "playwright-core";
import { chromeArgs } from "./app_lib.mjs";
const kJsTypes = new Set(["object", "closure", "array", "string", "concatenated string", "sliced string", "heap number", "regexp", "bigint"]);
async function bytes(cdp) {
  const chunks = []; const take = (e) => chunks.push(e.chunk);
  cdp.on("HeapProfiler.addHeapSnapshotChunk", take);
  await cdp.send("HeapProfiler.collectGarbage");
  await cdp.send("HeapProfiler.takeHeapSnapshot", { reportProgress: false });
  cdp.off("HeapProfiler.addHeapSnapshotChunk", take);
  const snap = JSON.parse(chunks.join("")); const f = snap.snapshot.meta.node_fields, t = snap.snapshot.meta.node_types[0];
  let b = 0; for (let i = 0; i < snap.nodes.length; i += f.length) if (kJsTypes.has(t[snap.nodes[i + f.indexOf("type")]])) b += snap.nodes[i + f.indexOf("self_size")];
  return b;
}
const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", headless: true, args: chromeArgs });
const page = await browser.newPage();
page.on("console", () => {});
await page.setContent("<p>x</p>");
const cdp = await page.context().newCDPSession(page);
let n = 0;
const base = await bytes(cdp);
for (const upto of [250, 500, 750, 1000, 1250, 1500, 2000, 3000]) {
  await page.evaluate(([a, b]) => { for (let i = a; i < b; ++i) console.log(`line ${i} ` + "x".repeat(200)); }, [n, upto]);
  n = upto;
  console.log(`${upto} messages: JS objects +${(await bytes(cdp)) - base} B`);
}
await cdp.send("Runtime.discardConsoleEntries");
console.log(`after Runtime.discardConsoleEntries: +${(await bytes(cdp)) - base} B`);
await browser.close();
