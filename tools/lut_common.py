"""What the build-time table generators (tools/gen_sheen_lut.py, tools/gen_ggx_ms_lut.py)
share. Stdlib only."""


def write_if_changed(path, text):
    """Writes `text` to `path` unless it already holds it (the file's time then stays, so
    nothing that depends on it rebuilds)."""
    try:
        with open(path) as f:
            if f.read() == text:
                return
    except OSError:
        pass
    with open(path, "w") as f:
        f.write(text)
