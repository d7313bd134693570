#!/usr/bin/env node
// A tiny static file server for the web build (no dependencies):
//   node tools/serve.mjs [FOLDER] [PORT] [--dev] [--scenes DIR] [--assets DIR] [--base /PATH/]
// FOLDER defaults to build/web; PORT to $PORT or 8000 (0 picks a free port; the line
// "Serving http://..." says which). Listens on 127.0.0.1 only.
//   --dev      the scene author's server (README command 1): /scenes/ and /assets/ come from
//              the source tree (or --scenes / --assets), and /events pushes the path of every
//              file that changes under them (Server-Sent Events), so the open page reloads
//              the scene it shows. Responses carry "x-pathtracer-dev: 1" so the page knows.
//   --base P   serve FOLDER under the sub-path P (as GitHub Pages serves a project site);
//              anything outside it is 404.
import { createServer } from "node:http";
import { createReadStream } from "node:fs";
import { readdir, stat } from "node:fs/promises";
import { dirname, extname, join, normalize, resolve, sep } from "node:path";
import { fileURLToPath } from "node:url";

const repo = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const positional = [], flags = { dev: false, scenes: join(repo, "scenes"), assets: join(repo, "assets"), base: "/" };
for (let i = 2; i < process.argv.length; i++) {
  const a = process.argv[i];
  if (a === "--dev") flags.dev = true;
  else if (a === "--scenes" || a === "--assets" || a === "--base") flags[a.slice(2)] = process.argv[++i];
  else positional.push(a);
}
const root = resolve(positional[0] ?? "build/web");
const port = Number(positional[1] ?? process.env.PORT ?? 8000);
const base = ("/" + flags.base + "/").replace(/\/+/g, "/");
// URL prefix -> folder. The dev server's scenes/ and assets/ are the source tree's.
const mounts = flags.dev ? [["scenes/", resolve(flags.scenes)], ["assets/", resolve(flags.assets)]] : [];

const types = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".mjs": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".wasm": "application/wasm",
  ".data": "application/octet-stream",
  ".json": "application/json",
  ".xml": "application/xml",
  ".png": "image/png",
  ".jpg": "image/jpeg",
  ".hdr": "application/octet-stream",
  ".exr": "application/octet-stream",
  ".txt": "text/plain; charset=utf-8",
};

// --dev: every change under the mounted folders goes to every open page. Modification
// times are polled (portable, and an editor's save-by-rename is just a change).
const clients = new Set();
async function snapshot() {
  const files = new Map();
  async function walk(dir, prefix) {
    let entries = [];
    try { entries = await readdir(dir, { withFileTypes: true }); } catch { return; }
    for (const e of entries) {
      const p = join(dir, e.name);
      if (e.isDirectory()) await walk(p, `${prefix}${e.name}/`);
      else try { const s = await stat(p); files.set(prefix + e.name, `${s.mtimeMs}:${s.size}`); } catch {}
    }
  }
  for (const [prefix, dir] of mounts) await walk(dir, prefix);
  return files;
}
if (flags.dev) {
  let known = await snapshot();
  setInterval(async () => {
    const now = await snapshot();
    for (const [path, v] of now) if (known.get(path) !== v) for (const c of clients) c.write(`data: ${path}\n\n`);
    for (const path of known.keys()) if (!now.has(path)) for (const c of clients) c.write(`data: ${path}\n\n`);
    known = now;
  }, 100);
}

const server = createServer(async (req, res) => {
  const send = (code, text) => {
    res.writeHead(code, { "Content-Type": "text/plain; charset=utf-8" });
    res.end(text);
  };
  if (req.method !== "GET" && req.method !== "HEAD") return send(405, "method not allowed\n");
  let path;
  try {
    path = decodeURIComponent(new URL(req.url, "http://localhost").pathname);
  } catch {
    return send(400, "bad request\n");
  }
  if (path + "/" === base) {  // "/pathtracer" -> "/pathtracer/": relative URLs need the slash
    res.writeHead(301, { Location: base });
    return res.end();
  }
  if (!path.startsWith(base)) return send(404, "not found\n");
  const rel = path.slice(base.length);
  if (flags.dev && rel === "events") {
    res.writeHead(200, { "Content-Type": "text/event-stream", "Cache-Control": "no-cache", Connection: "keep-alive" });
    res.write(": connected\n\n");
    clients.add(res);
    req.on("close", () => clients.delete(res));
    return;
  }
  let folder = root, inside = rel;
  for (const [prefix, dir] of mounts) if (rel.startsWith(prefix)) [folder, inside] = [dir, rel.slice(prefix.length)];
  let file = normalize(join(folder, inside));
  if (file !== folder && !file.startsWith(folder + sep)) return send(403, "forbidden\n");
  try {
    let info = await stat(file);
    if (info.isDirectory()) {
      file = join(file, "index.html");
      info = await stat(file);
    }
    res.writeHead(200, {
      "Content-Type": types[extname(file).toLowerCase()] ?? "application/octet-stream",
      "Content-Length": info.size,
      "Cache-Control": "no-cache",
      ...(flags.dev ? { "x-pathtracer-dev": "1" } : {}),
    });
    if (req.method === "HEAD") return res.end();
    createReadStream(file).on("error", () => res.destroy()).pipe(res);
  } catch {
    send(404, "not found\n");
  }
});

server.listen(port, "127.0.0.1", () => {
  console.log(`Serving http://127.0.0.1:${server.address().port}${base}${flags.dev ? " (dev: scenes/ and assets/ from the source tree, live reload)" : ""}`);
});
