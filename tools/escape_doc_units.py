"""Escapes the unit brackets rustdoc takes for links (``x [m]`` → ``x \\[m\\]``) where
``cargo doc -D warnings`` (run by ``make lint``) reports them as unresolved links: it runs
``cargo doc --workspace --no-deps --message-format=json`` and edits exactly the reported spans,
leaving real intra-doc links alone. Run it, then ``make lint`` again. Usage:
``python tools/escape_doc_units.py``.
"""

from __future__ import annotations

import collections
import json
import os
import subprocess
import sys


def spans(messages: list[str]) -> dict[str, set[tuple[int, int]]]:
    """File → byte spans of the unresolved links rustdoc reports (single-line spans only)."""
    out: dict[str, set[tuple[int, int]]] = collections.defaultdict(set)
    for line in messages:
        try:
            d = json.loads(line)
        except json.JSONDecodeError:
            continue
        if d.get("reason") != "compiler-message":
            continue
        m = d["message"]
        if not m["message"].startswith("unresolved link"):
            continue
        for s in m["spans"]:
            if s["is_primary"] and s["line_start"] == s["line_end"]:
                out[s["file_name"]].add((s["byte_start"], s["byte_end"]))
    return out


def escape(data: bytes, start: int, end: int) -> bytes | None:
    """``[x]`` around or at the span → ``\\[x\\]``; None when the span is not such a bracket."""
    if data[start - 1 : start] == b"[" and data[end : end + 1] == b"]":
        return data[: start - 1] + b"\\[" + data[start:end] + b"\\]" + data[end + 1 :]
    if data[start : start + 1] == b"[" and data[end - 1 : end] == b"]":
        return data[:start] + b"\\[" + data[start + 1 : end - 1] + b"\\]" + data[end:]
    return None


def main() -> int:
    env = {**os.environ, "RUSTDOCFLAGS": "-D warnings"}
    cmd = ["cargo", "doc", "--workspace", "--no-deps", "--message-format=json"]
    run = subprocess.run(cmd, capture_output=True, text=True, env=env, check=False)
    found = spans(run.stdout.splitlines())
    for path, pairs in sorted(found.items()):
        with open(path, "rb") as f:
            data = f.read()
        done = 0
        for start, end in sorted(pairs, reverse=True):
            new = escape(data, start, end)
            if new is not None:
                data, done = new, done + 1
        with open(path, "wb") as f:
            f.write(data)
        print(f"{path}: {done} of {len(pairs)} escaped")
    if not found:
        print("no unresolved unit brackets")
    return 0


if __name__ == "__main__":
    sys.exit(main())
