// The benchmark's static server: URL prefixes mounted on folders (each adapter's mounts()),
// the longest prefix first, on 127.0.0.1 and a free port. No dependencies.
import { createServer } from "node:http";
import { createReadStream } from "node:fs";
import { stat } from "node:fs/promises";
import { extname, join, normalize, resolve, sep } from "node:path";

const types = { ".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8", ".mjs": "text/javascript; charset=utf-8",
                ".css": "text/css; charset=utf-8", ".wasm": "application/wasm", ".json": "application/json", ".xml": "application/xml",
                ".png": "image/png", ".jpg": "image/jpeg" };

export function startServer(mounts) {
  const table = mounts.map(([p, d]) => [p, resolve(d)]).sort((a, b) => b[0].length - a[0].length);
  const server = createServer(async (req, res) => {
    const fail = (code) => { res.writeHead(code, { "Content-Type": "text/plain" }); res.end(`${code}\n`); };
    let path;
    try { path = decodeURIComponent(new URL(req.url, "http://localhost").pathname); } catch { return fail(400); }
    const m = table.find(([p]) => path.startsWith(p));
    if (!m) return fail(404);
    let file = normalize(join(m[1], path.slice(m[0].length)));
    if (file !== m[1] && !file.startsWith(m[1] + sep)) return fail(403);
    try {
      let info = await stat(file);
      if (info.isDirectory()) { file = join(file, "index.html"); info = await stat(file); }
      res.writeHead(200, { "Content-Type": types[extname(file).toLowerCase()] ?? "application/octet-stream", "Content-Length": info.size, "Cache-Control": "no-cache" });
      createReadStream(file).on("error", () => res.destroy()).pipe(res);
    } catch {
      fail(404);
    }
  });
  return new Promise((ok) => server.listen(0, "127.0.0.1", () => ok({ url: `http://127.0.0.1:${server.address().port}`, close: () => server.close() })));
}
