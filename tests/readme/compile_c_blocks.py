"""compile_c_blocks.py - the C integration examples in the README and docs/ compile.

Each file's ```c blocks, in order, make one translation unit (a later block may
use what an earlier one declared), which the C compiler checks as C99 with
every warning an error, against the public header.
usage: compile_c_blocks.py CC INCLUDE_DIR FILE.md...
"""
import os
import re
import subprocess
import sys
import tempfile


def main():
    cc, include, docs = sys.argv[1], sys.argv[2], sys.argv[3:]
    failed, checked = 0, 0
    for path in docs:
        blocks = re.findall(r"^```c\n(.*?)^```", open(path).read(), re.S | re.M)
        if not blocks:
            continue
        checked += 1
        with tempfile.NamedTemporaryFile("w", suffix=".c", delete=False) as f:
            f.write("\n".join(blocks))
            source = f.name
        cmd = [cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-I", include, source]
        r = subprocess.run(cmd, capture_output=True, text=True)
        os.unlink(source)
        if r.returncode != 0:
            failed += 1
            print("%s: its C blocks do not compile:\n%s" % (path, r.stderr))
        else:
            print("%s: %d C block(s) compile" % (path, len(blocks)))
    if checked == 0:
        sys.exit("no ```c block in " + " ".join(docs))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
