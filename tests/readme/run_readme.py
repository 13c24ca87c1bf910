"""run_readme.py SOURCE_DIR BUILD_DIR DOC... - runs every command block of the
README and the docs that is marked runnable, as a reader would type it.

The marker is an HTML comment on the line right before a ```sh block; it may
name a regular expression that the block's output (stdout and stderr) must
match, so a block that runs but prints the wrong thing fails:

    <!-- runnable expect="ssao-host 1\.2\.0" -->
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

MARKER = re.compile(r'^<!-- runnable(?: expect="(.*)")? -->$')


def blocks(name, text):
    """(file, line number, code, expected output regex or None) of every marked ```sh block."""
    lines = text.split("\n")
    found = []
    for i, line in enumerate(lines):
        m = MARKER.match(line.strip())
        if not m:
            continue
        if i + 1 >= len(lines) or lines[i + 1].strip() not in ("```sh", "```bash"):
            raise SystemExit("%s line %d: the runnable marker must be followed by a ```sh block" % (name, i + 1))
        end = i + 2
        while end < len(lines) and lines[end].strip() != "```":
            end += 1
        if end >= len(lines):
            raise SystemExit("%s line %d: the ```sh block never closes" % (name, i + 2))
        found.append((name, i + 3, "\n".join(lines[i + 2:end]), m.group(1)))
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
    if len(sys.argv) < 4:
        sys.exit("usage: run_readme.py SOURCE_DIR BUILD_DIR DOC...")
    source, build = (os.path.abspath(a) for a in sys.argv[1:3])
    found = []
    for doc in sys.argv[3:]:
        with open(doc) as f:
            found += blocks(os.path.relpath(doc, source), f.read())
    if not found:
        print("no block of %s is marked runnable" % " ".join(sys.argv[3:]))
        return 1
    env = dict(os.environ)
    for var in ("SSAO_PLUGIN", "SSAO_DATA_DIR"):
        env.pop(var, None)  # the README's commands must work without them
    failed = 0
    for doc, line, code, expect in found:
        root = scratch(source, build)
        start = time.time()
        try:
            run = subprocess.run(["bash", "-euo", "pipefail", "-c", code], cwd=root, env=env, timeout=120,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
            ok, output = run.returncode == 0, run.stdout
            if ok and expect and not re.search(expect, output):
                ok, output = False, output + "\n(the output does not match %r)" % expect
        except subprocess.TimeoutExpired as e:
            ok, output = False, (e.stdout or "") + "\n(timed out after 120 s)"
        finally:
            shutil.rmtree(root, ignore_errors=True)
        print("%s %s line %d (%.1f s): %s" % ("ok     " if ok else "FAILED ", doc, line, time.time() - start,
                                             code.strip().split("\n")[0]))
        if not ok:
            failed += 1
            print("  the block:\n" + "\n".join("    " + c for c in code.split("\n")))
            print("  its output:\n" + "\n".join("    " + o for o in output.rstrip().split("\n")[-30:]))
    print("%d of %d runnable blocks passed" % (len(found) - failed, len(found)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
