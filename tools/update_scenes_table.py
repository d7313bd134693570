#!/usr/bin/env python3
"""Replaces the shader-size table in docs/scenes.md with the one the native build wrote
(build/native/scenes-table.md, by the test "docs/scenes.md lists every shipped scene...").
Run after a change of shader text: run that test once (it fails and writes the table),
then python3 tools/update_scenes_table.py"""
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parent.parent
table = (root / "build/native/scenes-table.md").read_text().strip("\n").split("\n")
doc_path = root / "docs/scenes.md"
doc = doc_path.read_text().split("\n")
starts = [i for i, line in enumerate(doc) if line.strip() == table[0].strip()]
if len(starts) != 1:
    sys.exit(f"docs/scenes.md: expected one table headed {table[0]!r}, found {len(starts)}")
end = starts[0]
while end < len(doc) and doc[end].startswith("|"):
    end += 1
doc[starts[0]:end] = table
doc_path.write_text("\n".join(doc))
print(f"docs/scenes.md: table of {len(table) - 2} scenes updated")
