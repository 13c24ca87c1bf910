"""run_readme.py README SOURCE_DIR BUILD_DIR - runs every command block of the
README that is marked runnable, as a reader would type it.

The marker is an HTML comment on the line right before a ```sh block:

    <!-- runnable -->
    ```sh
    build/host/ssao-host --version
    ```

Each block runs under `bash -euo pipefail` (so every command must succeed) in
a fresh scratch directory that looks like the repository root: a symlink to
every top-level entry of SOURCE_DIR, and `build` pointing at BUILD_DIR. What a
block writes (out/, a staged install) lands in the scratch directory, which is
removed afterwards. Mark only blocks that are safe and quick (seconds): no
apt-get, no full rebuild, no whole test suite.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

MARKER = "<!-- runnable -->"


def blocks(text):
    """(line number, code) of every marked ```sh block."""
    lines = text.split("\n")
    found = []
    for i, line in enumerate(lines):
        if line.strip() != MARKER:
            continue
        if i + 1 >= len(lines) or lines[i + 1].strip() not in ("```sh", "```bash"):
            raise SystemExit("README line %d: %s must be followed by a ```sh block" % (i + 1, MARKER))
        end = i + 2
        while end < len(lines) and lines[end].strip() != "```":
            end += 1
        if end >= len(lines):
            raise SystemExit("README line %d: the ```sh block never closes" % (i + 2))
        found.append((i + 3, "\n".join(lines[i + 2:end])))
    return found


def scratch(source, build):
    root = tempfile.mkdtemp(prefix="ssao-readme.")
    for entry in os.listdir(source):
        if entry in ("build", ".git"):
            continue
        os.symlink(os.path.join(source, entry), os.path.join(root, entry))
    os.symlink(build, os.path.join(root, "build"))
    return root


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: run_readme.py README SOURCE_DIR BUILD_DIR")
    readme, source, build = (os.path.abspath(a) for a in sys.argv[1:])
    with open(readme) as f:
        found = blocks(f.read())
    if not found:
        print("no block of %s is marked %s" % (readme, MARKER))
        return 1
    env = dict(os.environ)
    for var in ("SSAO_PLUGIN", "SSAO_DATA_DIR"):
        env.pop(var, None)  # the README's commands must work without them
    failed = 0
    for line, code in found:
        root = scratch(source, build)
        start = time.time()
        try:
            run = subprocess.run(["bash", "-euo", "pipefail", "-c", code], cwd=root, env=env, timeout=120,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
            ok, output = run.returncode == 0, run.stdout
        except subprocess.TimeoutExpired as e:
            ok, output = False, (e.stdout or "") + "\n(timed out after 120 s)"
        finally:
            shutil.rmtree(root, ignore_errors=True)
        print("%s README line %d (%.1f s): %s" % ("ok     " if ok else "FAILED ", line, time.time() - start,
                                                 code.strip().split("\n")[0]))
        if not ok:
            failed += 1
            print("  the block:\n" + "\n".join("    " + c for c in code.split("\n")))
            print("  its output:\n" + "\n".join("    " + o for o in output.rstrip().split("\n")[-30:]))
    print("%d of %d runnable README blocks passed" % (len(found) - failed, len(found)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
