#!/usr/bin/env python3
"""Replaces the generated tables in docs/scenes.md with the ones the native build wrote:
the shader-size table (build/native/scenes-table.md, by the test "docs/scenes.md lists
every shipped scene...") and the glTF extension-set table (build/native/lobes-table.md, by
"glTF lobes: each lobe is compiled in only where a material uses it"). Run after a change
of shader text: run those tests once (they fail and write the tables), then
python3 tools/update_scenes_table.py"""
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parent.parent
doc_path = root / "docs/scenes.md"
doc = doc_path.read_text().split("\n")
for name in ("scenes-table.md", "lobes-table.md"):
    path = root / "build/native" / name
    if not path.exists():
        continue
    table = path.read_text().strip("\n").split("\n")
    starts = [i for i, line in enumerate(doc) if line.strip() == table[0].strip()]
    if len(starts) != 1:
        sys.exit(f"docs/scenes.md: expected one table headed {table[0]!r}, found {len(starts)}")
    end = starts[0]
    while end < len(doc) and doc[end].startswith("|"):
        end += 1
    doc[starts[0]:end] = table
    print(f"docs/scenes.md: table of {len(table) - 2} rows from build/native/{name} updated")
doc_path.write_text("\n".join(doc))
