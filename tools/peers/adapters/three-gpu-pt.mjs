// three-gpu-pathtracer 0.0.26 (three 0.187.0, three-mesh-bvh 0.9.17, from npm: package.json)
// on pages/three-gpu-pt/index.html, which rebuilds scene2 in three.js and implements
// window.peerBench itself (the contract: tools/peers/README.md).
import { join } from "node:path";

export const name = "three-gpu-pt";
export const title = "three-gpu-pathtracer 0.0.26 (three 0.187.0)";

// What the benchmark's server must serve for this page: URL prefix -> folder.
export function mounts(ctx) {
  return [["/peers/three-gpu-pt/", join(ctx.peersDir, "pages/three-gpu-pt")], ["/node_modules/", join(ctx.peersDir, "node_modules")]];
}

// The page's address for the size and bounces (ctx.extra: more query text, e.g. "ei=8").
export function url(ctx) {
  // ei=69: scene2's emitter (<Emit><Absorb intensity="69">), so that the two images agree
  // in scale (the page's own default, 8, is the notes' first run: 8/69 of ours, measured).
  const q = new URLSearchParams(`size=${ctx.width}x${ctx.height}&bounces=${ctx.bounces}&ei=69`);
  for (const [k, v] of new URLSearchParams(ctx.extra ?? "")) q.set(k, v);
  return `/peers/three-gpu-pt/index.html?${q}`;
}

// Nothing to add: the page is ours and carries window.peerBench.
export async function prepare(_context, _ctx) {}
