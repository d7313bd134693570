"use strict";
// Scene files into the page's file system (Emscripten's MEMFS), from wherever they come.
//
// A file provider is one small interface: { get(path) -> Promise<Uint8Array | null> },
// path relative and '/'-separated. Two providers exist: http(base) (the page's own server:
// the dev server serves scenes/ and assets/ from the source tree, GitHub Pages a copy) and
// local(files) (files dropped on the page or chosen with the file picker). collect() reads
// a scene and every file it references through a provider; write() puts them in MEMFS; the
// C++ loader then reads them from there like any file.
//
// The reload loop: when the dev server (tools/serve.mjs --dev) says a file under scenes/
// or assets/ changed (Server-Sent Events on ./events) and the current scene uses it, the
// scene is fetched again and reloaded, keeping the camera. A broken edit shows its error
// in the panel and the last good scene keeps rendering (the App's load_scene).
const ptFiles = (() => {
  // Attribute values that name files: the loader's references (Mesh src, Environment map,
  // image textures...), found without knowing which elements have them.
  const kReference = /^[^\s<>"|*?]+\.(json|obj|mtl|hdr|pfm|png|jpe?g|gltf|glb|bin|exr)$/i;

  function normalize(path) {  // null when it climbs above the root
    const out = [];
    for (const part of path.split("/")) {
      if (!part || part === ".") continue;
      if (part !== "..") out.push(part);
      else if (!out.length) return null;
      else out.pop();
    }
    return out.join("/");
  }
  const dirname = (p) => p.slice(0, Math.max(0, p.lastIndexOf("/")));
  const join = (dir, rel) => rel.startsWith("/") ? null : normalize((dir ? dir + "/" : "") + rel);

  function references(xmlText) {
    const doc = new DOMParser().parseFromString(xmlText, "application/xml");
    const refs = new Set();
    for (const el of doc.getElementsByTagName("*"))
      for (const a of el.attributes) if (kReference.test(a.value.trim())) refs.add(a.value.trim());
    return [...refs];
  }
  function gltfReferences(bytes) {  // a .gltf names its buffers and images
    try {
      const j = JSON.parse(new TextDecoder().decode(bytes));
      return [...(j.buffers || []), ...(j.images || [])].map((b) => b.uri)
        .filter((u) => u && !u.startsWith("data:")).map(decodeURIComponent);
    } catch { return []; }
  }

  // The scene and the files it references, read through the provider: Map path -> bytes.
  // A missing reference is left out: the loader then reports it with file and line.
  async function collect(provider, scenePath) {
    const files = new Map();
    const xml = await provider.get(scenePath);
    if (!xml) throw new Error(`${scenePath}: cannot read the scene file`);
    files.set(scenePath, xml);
    const fetchOne = async (path) => {
      if (!path || files.has(path)) return;
      const bytes = await provider.get(path);
      if (!bytes) return;
      files.set(path, bytes);
      if (/\.gltf$/i.test(path)) await Promise.all(gltfReferences(bytes).map((r) => fetchOne(join(dirname(path), r))));
    };
    // A .gltf or .glb is a scene of its own (scene/gltf_scene.h): a .gltf's references are
    // its buffers and images, a .glb's are inside it.
    const refs = /\.glb$/i.test(scenePath) ? [] : /\.gltf$/i.test(scenePath) ? gltfReferences(xml)
      : references(new TextDecoder().decode(xml));
    await Promise.all(refs.map((r) => fetchOne(join(dirname(scenePath), r))));
    return files;
  }

  // Writes collected files under root ("" for the file system's root, or "/drop/3").
  function write(files, root) {
    for (const [path, bytes] of files) {
      const full = `${root}/${path}`;
      Module.FS.mkdirTree(dirname(full) || "/");
      Module.FS.writeFile(full, bytes);
    }
  }

  const http = (base) => ({
    async get(path) {
      try {
        const r = await fetch(new URL(path, base), { cache: "no-cache" });
        return r.ok ? new Uint8Array(await r.arrayBuffer()) : null;
      } catch { return null; }
    },
  });

  // Dropped or picked files ({file, path} pairs): matched by their relative path (a
  // dropped folder), else by name, so a scene and its meshes and maps can be dropped
  // together as loose files.
  function local(entries) {
    const byPath = new Map(), byName = new Map();
    for (const { file, path } of entries) {
      byPath.set(normalize(path), file);
      byName.set(file.name, file);
    }
    return {
      async get(path) {
        const f = byPath.get(path) || byName.get(path.slice(path.lastIndexOf("/") + 1));
        return f ? new Uint8Array(await f.arrayBuffer()) : null;
      },
    };
  }

  function callLoad(path, keepCamera) {
    const size = Module.lengthBytesUTF8(path) + 1, ptr = Module._malloc(size);
    Module.stringToUTF8(path, ptr, size);
    const ok = (keepCamera ? Module._pt_reload_scene(ptr) : Module._pt_load_scene(ptr)) !== 0;
    Module._free(ptr);
    return ok;
  }

  const state = { dev: false, reloads: 0, drops: 0, lastReloadMs: 0 };

  // A scene of the file system (its path absolute, "/scenes/..."): fetched fresh from the
  // page's server when it has it, else loaded from the packaged copy.
  async function openScene(path, keepCamera = false) {
    try {
      write(await collect(http(document.baseURI), path.replace(/^\/+/, "")), "");
    } catch { /* not served: the preloaded package has it, or the loader says why */ }
    return callLoad(path, keepCamera);
  }

  // Files as {file, path}: a FileList (picker, loose files) or what a drop held.
  const withPaths = (fileList) => [...fileList].map((file) => ({ file, path: file.webkitRelativePath || file.name }));

  // What a drop holds: loose files, or folders read recursively (each file with its path
  // from the dropped folder's name down). The entries must be taken from the event
  // before the first await: the browser empties the DataTransfer after the handler.
  async function droppedFiles(dt) {
    const entries = [...(dt.items || [])].map((i) => (i.webkitGetAsEntry ? i.webkitGetAsEntry() : null)).filter(Boolean);
    if (!entries.some((e) => e.isDirectory)) return withPaths(dt.files);
    const out = [];
    const walk = async (entry, prefix) => {
      if (entry.isFile) {
        out.push({ file: await new Promise((ok, fail) => entry.file(ok, fail)), path: prefix + entry.name });
        return;
      }
      const reader = entry.createReader();
      for (;;) {  // readEntries answers in batches until an empty one
        const batch = await new Promise((ok, fail) => reader.readEntries(ok, fail));
        if (!batch.length) break;
        for (const e of batch) await walk(e, `${prefix}${entry.name}/`);
      }
    };
    for (const e of entries) await walk(e, "");
    return out;
  }

  // The scene of a drop: its .xml file nearest the top (then by name), else its .gltf or
  // .glb nearest the top (a scene of its own), loaded with every file it references found
  // among the others.
  async function openLocal(entries) {
    const depth = (p) => p.split("/").length;
    const first = (re) => entries.filter((e) => re.test(e.path))
      .sort((a, b) => depth(a.path) - depth(b.path) || (a.path < b.path ? -1 : a.path > b.path ? 1 : 0))[0];
    const xml = first(/\.xml$/i) || first(/\.(gltf|glb)$/i);
    if (!xml) return notice("Drop a scene (.xml) or a glTF model (.gltf, .glb) together with the files it uses, or its folder.");
    const scenePath = normalize(xml.path);
    const root = `/drop/${++state.drops}`;
    write(await collect(local(entries), scenePath), root);
    callLoad(`${root}/${scenePath}`, false);
  }

  function notice(text) {
    const box = document.getElementById("notice");
    if (!box) return;
    box.textContent = text;
    box.hidden = !text;
    clearTimeout(notice.timer);
    notice.timer = setTimeout(() => { box.hidden = true; }, 4000);
  }

  // The scene named by the page's URL, fetched before the program starts (the packaged
  // copy may be older than the served one): a run dependency, written once the packaged
  // files are in place, before main() loads it.
  function stageAtStartup(scenePath) {
    let staged = null;
    Module.preRun = [].concat(Module.preRun || [], () => {
      Module.addRunDependency("pt-scene");
      collect(http(document.baseURI), scenePath).then((f) => { staged = f; }, () => {})
        .finally(() => Module.removeRunDependency("pt-scene"));
    });
    const previous = Module.onRuntimeInitialized;
    Module.onRuntimeInitialized = () => {
      if (staged) write(staged, "");
      if (previous) previous();
    };
  }

  // The dev server marks its responses; only then is there an event stream to follow.
  async function followDevServer() {
    try {
      const r = await fetch(location.pathname, { method: "HEAD", cache: "no-cache" });
      state.dev = r.headers.get("x-pathtracer-dev") === "1";
    } catch { return; }
    if (!state.dev) return;
    const changed = new Set();
    let timer = 0;
    const events = new EventSource("events");
    events.onmessage = (e) => {
      changed.add(e.data);
      clearTimeout(timer);
      timer = setTimeout(reloadIfUsed, 30);  // an editor's save may touch several files
    };
    async function reloadIfUsed() {
      if (!Module._pt_scene_files) return;
      const files = JSON.parse(Module.UTF8ToString(Module._pt_scene_files()));
      const used = [...changed].some((p) => files.includes("/" + p));
      changed.clear();
      if (!used || !files.length) return;
      const t0 = performance.now();
      const ok = await openScene(files[0], true);
      state.reloads++;
      state.lastReloadMs = performance.now() - t0;
      notice(ok ? `reloaded ${files[0]}` : "the edited scene has an error: see the panel");
    }
  }

  function installDropAndPicker(canvas) {
    for (const type of ["dragenter", "dragover"])
      window.addEventListener(type, (e) => { e.preventDefault(); e.dataTransfer.dropEffect = "copy"; });
    window.addEventListener("drop", (e) => {
      e.preventDefault();
      if (e.dataTransfer && (e.dataTransfer.files.length || e.dataTransfer.items.length))
        droppedFiles(e.dataTransfer).then(openLocal);
    });
    const picker = document.getElementById("picker");
    document.getElementById("open").addEventListener("click", () => picker.click());
    picker.addEventListener("change", () => {
      if (picker.files.length) openLocal(withPaths(picker.files));
      picker.value = "";
      canvas.focus();
    });
  }

  return { normalize, references, collect, write, http, local, droppedFiles, openScene, openLocal, stageAtStartup,
           followDevServer, installDropAndPicker, state };
})();
window.ptFiles = ptFiles;
window.ptOpenScene = (path, keepCamera) => ptFiles.openScene(path, keepCamera);
