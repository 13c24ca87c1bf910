"""Builds the ssao package with the version of the source tree it sits in.

The one version is project(ssao VERSION ...) in ../CMakeLists.txt (also the
library's, the CMake package's and pkg-config's); it is written into the built
package as ssao/_version.py, so an installed ssao.__version__ needs no source tree.
"""

import os
import re

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))


def project_version():
    top = os.path.join(HERE, "..", "CMakeLists.txt")
    try:
        with open(top, encoding="utf-8") as f:
            m = re.search(r"project\(ssao VERSION ([0-9]+\.[0-9]+\.[0-9]+)", f.read())
    except OSError as e:
        raise SystemExit("ssao: cannot read the version from %s (%s); build from the source tree" % (top, e))
    if not m:
        raise SystemExit("ssao: no 'project(ssao VERSION X.Y.Z' line in %s" % top)
    return m.group(1)


VERSION = project_version()


class BuildWithVersion(build_py):
    def run(self):
        super().run()
        target = os.path.join(self.build_lib, "ssao", "_version.py")
        with open(target, "w", encoding="utf-8") as f:
            f.write('"""Written when the package was built: do not edit."""\n__version__ = "%s"\n' % VERSION)


setup(version=VERSION, cmdclass={"build_py": BuildWithVersion})
