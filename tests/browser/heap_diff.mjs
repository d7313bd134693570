// What a page's JS heap gained between two heap snapshots (V8's .heapsnapshot JSON, as
// DevTools or endurance_test.mjs --snapshots DIR writes them):
//   node tests/browser/heap_diff.mjs BEFORE.heapsnapshot AFTER.heapsnapshot [--most 25] [--paths 3] [--js 1]
// Objects whose snapshot id is in AFTER but not in BEFORE (V8 keeps an object's id across
// snapshots of one page) are the new ones; they are grouped by type and name (a constructor,
// a string's first characters, a closure's name), the groups with most bytes first, and for
// the largest groups the shortest retainer path of a few of their objects from the
// snapshot's root is printed (weak edges not followed), as DevTools' Comparison view and
// Retainers pane would show them. --js 1: only the kinds endurance_test.mjs counts as JS
// objects (objects, closures, arrays, strings, numbers, and the native nodes of external
// strings' characters and ArrayBuffers' backing stores, which it counts too, apart). Then the new bytes by type, and the
// snapshot's total by type against BEFORE's. A tool for finding what the page keeps, not a test.
import { readFileSync } from "node:fs";

const files = [], opt = { most: 25, paths: 3, js: 0 };
const kJsTypes = new Set(["object", "closure", "array", "string", "concatenated string", "sliced string", "heap number", "regexp", "bigint"]);
const kOutside = new Set(["system / ExternalStringData", "system / JSArrayBufferData"]);  // as endurance_test.mjs
for (let i = 2; i < process.argv.length; ++i) {
  const a = process.argv[i];
  if (a.startsWith("--")) opt[a.slice(2)] = Number(process.argv[++i]);
  else files.push(a);
}
if (files.length !== 2) {
  console.error("usage: node heap_diff.mjs BEFORE.heapsnapshot AFTER.heapsnapshot [--most N] [--paths N]");
  process.exit(2);
}

function load(path) {
  const s = JSON.parse(readFileSync(path, "utf8"));
  const m = s.snapshot.meta;
  const nf = m.node_fields, ef = m.edge_fields;
  return {
    nodes: s.nodes, edges: s.edges, strings: s.strings, nodeTypes: m.node_types[0], edgeTypes: m.edge_types[0],
    nn: nf.length, ne: ef.length, type: nf.indexOf("type"), name: nf.indexOf("name"), id: nf.indexOf("id"),
    size: nf.indexOf("self_size"), count: nf.indexOf("edge_count"),
    etype: ef.indexOf("type"), ename: ef.indexOf("name_or_index"), eto: ef.indexOf("to_node"),
  };
}

const before = load(files[0]), after = load(files[1]);
const oldIds = new Set();
for (let i = 0; i < before.nodes.length; i += before.nn) oldIds.add(before.nodes[i + before.id]);

const S = after, N = S.nodes.length / S.nn;
const typeOf = (n) => S.nodeTypes[S.nodes[n * S.nn + S.type]];
const nameOf = (n) => S.strings[S.nodes[n * S.nn + S.name]];
const label = (n) => {
  const t = typeOf(n), name = nameOf(n);
  const short = JSON.stringify(name.length > 60 ? name.slice(0, 60) + "…" : name);
  return `${t} ${short}`;
};

// Edges: the first edge of each node, and the reverse (retainer) lists.
const firstEdge = new Uint32Array(N + 1);
for (let n = 0, e = 0; n < N; ++n) { firstEdge[n] = e; e += S.nodes[n * S.nn + S.count] * S.ne; }
firstEdge[N] = S.edges.length;
const edgeName = (e) => {
  const t = S.edgeTypes[S.edges[e + S.etype]], v = S.edges[e + S.ename];
  return t === "element" || t === "hidden" ? `[${v}]` : S.strings[v];
};
const retainers = Array.from({ length: N }, () => []);
for (let n = 0; n < N; ++n)
  for (let e = firstEdge[n]; e < firstEdge[n + 1]; e += S.ne) {
    if (S.edgeTypes[S.edges[e + S.etype]] === "weak") continue;
    retainers[S.edges[e + S.eto] / S.nn].push([n, e]);
  }
// Distances from the root (node 0), breadth first over strong edges.
const dist = new Int32Array(N).fill(-1);
dist[0] = 0;
for (let q = [0], h = 0; h < q.length; ++h) {
  const n = q[h];
  for (let e = firstEdge[n]; e < firstEdge[n + 1]; e += S.ne) {
    if (S.edgeTypes[S.edges[e + S.etype]] === "weak") continue;
    const to = S.edges[e + S.eto] / S.nn;
    if (dist[to] < 0) { dist[to] = dist[n] + 1; q.push(to); }
  }
}
function path(n) {
  const out = [label(n)];
  for (let guard = 0; n !== 0 && guard < 40; ++guard) {
    const best = retainers[n].filter(([r]) => dist[r] >= 0).sort((a, b) => dist[a[0]] - dist[b[0]])[0];
    if (!best) { out.push("(unreachable)"); break; }
    out.push(`.${edgeName(best[1])} of ${label(best[0])}`);
    n = best[0];
  }
  return out.join("\n      ");
}

const groups = new Map();
let newBytes = 0, newCount = 0, allBytes = 0;
const byType = new Map(), beforeByType = new Map();
for (let i = 0; i < before.nodes.length; i += before.nn) {
  const t = before.nodeTypes[before.nodes[i + before.type]];
  beforeByType.set(t, (beforeByType.get(t) ?? 0) + before.nodes[i + before.size]);
}
for (let n = 0; n < N; ++n) {
  const size = S.nodes[n * S.nn + S.size];
  allBytes += size;
  const t = typeOf(n);
  if (opt.js && !kJsTypes.has(t) && !(t === "native" && kOutside.has(nameOf(n)))) continue;
  byType.set(t, (byType.get(t) ?? 0) + size);
  if (oldIds.has(S.nodes[n * S.nn + S.id])) continue;
  const key = t === "string" || t === "concatenated string" || t === "sliced string" ? `${t} ${JSON.stringify(nameOf(n).slice(0, 40))}` : `${t} ${nameOf(n)}`;
  const g = groups.get(key) ?? { bytes: 0, count: 0, nodes: [] };
  g.bytes += size;
  g.count++;
  if (g.nodes.length < opt.paths) g.nodes.push(n);
  groups.set(key, g);
  newBytes += size;
  newCount++;
}
console.log(`${files[1]}: ${N} nodes, ${allBytes} bytes; ${newCount} objects (${newBytes} bytes) not in ${files[0]}`);
const sorted = [...groups.entries()].sort((a, b) => b[1].bytes - a[1].bytes).slice(0, opt.most);
for (const [key, g] of sorted) {
  console.log(`${String(g.bytes).padStart(9)} B ${String(g.count).padStart(6)} x ${key.slice(0, 100)}`);
  if (sorted.indexOf(sorted.find(([k]) => k === key)) < 10)
    for (const n of g.nodes) console.log(`    ${path(n)}`);
}
console.log("by type, the whole snapshot: BEFORE -> AFTER bytes");
for (const [t, b] of [...byType.entries()].sort((a, b) => b[1] - a[1]))
  console.log(`  ${t}: ${beforeByType.get(t) ?? 0} -> ${b} (${b - (beforeByType.get(t) ?? 0) >= 0 ? "+" : ""}${b - (beforeByType.get(t) ?? 0)})`);
