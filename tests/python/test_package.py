"""test_package.py SOURCE_DIR BUILD_PYTHON_DIR PLUGIN VERSION - the ssao Python
package as a user gets it, run with the interpreter the README names.

  - pip install --no-build-isolation --no-index (offline, Debian's setuptools)
    of python/ into a temporary --target: it installs, imports from anywhere,
    and states VERSION (project() in CMakeLists.txt) as __version__;
  - where Library() finds the library, in the documented order: beside the
    module, then the build tree (the build's copy of the module only), then the
    install prefix, then $SSAO_PLUGIN, then the dynamic loader's search;
  - the installed copy carries no build-tree path.
Each case runs in a fresh interpreter (subprocess), from a folder outside the
source tree, so nothing leaks in through sys.path or the current folder.
"""

import os
import shutil
import subprocess
import sys
import tempfile

failures = []
SONAME = "libssao.so.1"


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def run_python(code, pythonpath, cwd, env_extra=None):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SSAO_PLUGIN", "LD_LIBRARY_PATH")}
    env["PYTHONPATH"] = pythonpath
    env.update(env_extra or {})
    r = subprocess.run([sys.executable, "-c", code], cwd=cwd, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, universal_newlines=True)
    return r.returncode, r.stdout.strip(), r.stderr.strip()


LOAD = "import ssao; lib = ssao.Library(); print(lib.path)"


def main():
    source, build_python, plugin, version = sys.argv[1:5]
    plugin = os.path.realpath(plugin)
    work = tempfile.mkdtemp(prefix="ssao-python.")
    try:
        # pip builds in the project folder: build from a copy, so the source tree stays untouched.
        src = os.path.join(work, "src")
        shutil.copytree(os.path.join(source, "python"), os.path.join(src, "python"),
                        ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__", "examples"))
        shutil.copy(os.path.join(source, "CMakeLists.txt"), src)
        target = os.path.join(work, "site")
        r = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-index",
                            "--no-deps", "--disable-pip-version-check", "--target", target,
                            os.path.join(src, "python")], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           universal_newlines=True)
        check(r.returncode == 0, "pip install --no-build-isolation --no-index ./python works offline"
              + ("" if r.returncode == 0 else ":\n" + r.stdout[-2000:]))
        if r.returncode != 0:
            return 1
        package = os.path.join(target, "ssao")
        check(os.path.isfile(os.path.join(package, "py.typed")), "the package ships py.typed (type hints)")
        check(not os.path.exists(os.path.join(package, "_build_paths.py")), "the pip-installed package names no build tree")
        for name in os.listdir(package):
            if name.endswith(".py"):
                with open(os.path.join(package, name), encoding="utf-8") as f:
                    text = f.read()
                check(source not in text, "%s names no source or build path" % name)

        code, out, err = run_python("import ssao; print(ssao.__version__, ssao.__file__)", target, work)
        check(code == 0 and out.split()[0] == version and out.split()[1].startswith(package),
              "import ssao from the install: __version__ %s (got %r %s)" % (version, out, err))

        # Nothing beside it, no build tree, no prefix library, no SSAO_PLUGIN: a clear error naming the places.
        code, out, err = run_python(LOAD, target, work)
        check(code != 0 and "cannot load the SSAO plugin" in err and os.path.join(package, SONAME) in err,
              "no library anywhere: OSError naming where it looked: %s" % err.splitlines()[-1:])
        # 4. $SSAO_PLUGIN.
        code, out, err = run_python(LOAD, target, work, {"SSAO_PLUGIN": plugin})
        check(code == 0 and out == plugin, "found through SSAO_PLUGIN: %r %s" % (out, err))
        # 5. The dynamic loader's search (a system install).
        code, out, err = run_python(LOAD, target, work, {"LD_LIBRARY_PATH": os.path.dirname(plugin)})
        check(code == 0 and out == SONAME, "found by the dynamic loader's search: %r %s" % (out, err))

        # 3. The install prefix: a pip layout <prefix>/lib/python3.X/site-packages/ssao finds <prefix>/lib.
        prefix = os.path.join(work, "prefix")
        site = os.path.join(prefix, "lib", "python3.11", "site-packages")
        shutil.copytree(package, os.path.join(site, "ssao"))
        # A shared library there that is not the plugin (a Python extension module) does not end the search.
        import _ctypes
        shutil.copy(_ctypes.__file__, os.path.join(prefix, "lib", SONAME))
        code, out, err = run_python(LOAD, site, work, {"SSAO_PLUGIN": plugin})
        check(code == 0 and out == plugin, "a file that is not the plugin is passed over: %r %s" % (out, err))
        code, out, err = run_python(LOAD, site, work)
        check(code != 0 and "OSError" in err and "not the SSAO plugin" in err,
              "and named when nothing else is found: %s" % err.splitlines()[-1:])
        shutil.copy(plugin, os.path.join(prefix, "lib", SONAME))
        code, out, err = run_python(LOAD, site, work, {"SSAO_PLUGIN": plugin})
        check(code == 0 and out == os.path.join(prefix, "lib", SONAME),
              "found in the install prefix before SSAO_PLUGIN: %r %s" % (out, err))

        # 1. Beside the module (package data) comes first.
        shutil.copy(plugin, os.path.join(site, "ssao", SONAME))
        code, out, err = run_python(LOAD, site, work, {"SSAO_PLUGIN": plugin})
        check(code == 0 and out == os.path.join(site, "ssao", SONAME), "found beside the module first: %r %s" % (out, err))

        # 2. The build tree's copy of the module finds the build's library (and only it has _build_paths).
        code, out, err = run_python(LOAD + "; print(ssao.__version__)", build_python, work)
        check(code == 0 and out.splitlines() == [plugin, version],
              "the build tree's module finds the build's library and states %s: %r %s" % (version, out, err))
        # ... after a library beside it, before SSAO_PLUGIN.
        copy = os.path.join(work, "build_copy")
        shutil.copytree(build_python, copy, ignore=shutil.ignore_patterns("__pycache__"))
        code, out, err = run_python(LOAD, copy, work, {"SSAO_PLUGIN": "/nonexistent/libssao.so.1"})
        check(code == 0 and out == plugin, "the build tree comes before SSAO_PLUGIN: %r %s" % (out, err))
        shutil.copy(plugin, os.path.join(copy, "ssao", SONAME))
        code, out, err = run_python(LOAD, copy, work)
        check(code == 0 and out == os.path.join(copy, "ssao", SONAME), "beside comes before the build tree: %r %s" % (out, err))

        # An explicit path is the only one tried.
        code, out, err = run_python("import ssao; ssao.Library('/nonexistent/x.so')", copy, work)
        check(code != 0 and "/nonexistent/x.so" in err and SONAME not in err.splitlines()[-1],
              "Library(path) tries that path alone: %s" % err.splitlines()[-1:])
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("test_package: %s" % ("all checks passed" if not failures else "%d FAILED" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
