# Debian packages: cpack -G DEB (run in the build directory, or
# cpack -G DEB --config <build>/CPackConfig.cmake -B <out>) makes one package
# per install component, for the prefix /usr:
#   libssao1      runtime  lib/libssao.so.1*, the licence and README
#   libssao-dev   dev      the header, lib/libssao.so, the CMake package, ssao.pc
#   ssao-tools    tools    ssao-host, -reference, -error, -bench, -viewer and their data
#   python3-ssao  python   the Python package (lib/python3/dist-packages/ssao)
# Dependencies: on each other as the components' DEPENDS say (same version),
# and on system libraries through dpkg-shlibdeps (dpkg-dev). The tools dlopen
# libssao.so.1, so their dependency on libssao1 is declared here, not found.
set(CPACK_PACKAGE_NAME ssao)
set(CPACK_PACKAGE_VENDOR "the ssao authors")
set(CPACK_PACKAGE_CONTACT "the ssao authors <ssao@localhost>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://localhost/ssao")

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME libssao1)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME libssao-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME ssao-tools)
set(CPACK_DEBIAN_TOOLS_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-ssao)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3")
set(CPACK_DEBIAN_PYTHON_PACKAGE_ARCHITECTURE all)
# The tools' GL comes through EGL (Mesa's drivers or a vendor's) and, for the
# viewer, GLX: name the driver packages the dynamic linker cannot see.
set(CPACK_DEBIAN_TOOLS_PACKAGE_RECOMMENDS "libgl1-mesa-dri, libegl-mesa0")

# First line: the summary apt shows; the rest: the long description
# (CPACK_PACKAGE_DESCRIPTION_SUMMARY is left unset: CPack would put it first in every package).
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION "Drop-in screen-space ambient occlusion for OpenGL 3.3+ (library)
libssao.so.1 with its C interface (include/ssao/ssao.h in libssao-dev). It
loads every GL function through the host, so it links neither libGL nor libEGL.")
set(CPACK_DEBIAN_DEV_DESCRIPTION "Drop-in screen-space ambient occlusion for OpenGL 3.3+ (development files)
The header ssao/ssao.h, the CMake package (find_package(ssao ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}))
and ssao.pc for pkg-config.")
set(CPACK_DEBIAN_TOOLS_DESCRIPTION "Drop-in screen-space ambient occlusion for OpenGL 3.3+ (tools)
ssao-host, ssao-reference, ssao-error, ssao-bench and ssao-viewer, with the
bundled scenes and the viewer's demo script in /usr/share/ssao.")
set(CPACK_DEBIAN_PYTHON_DESCRIPTION "Drop-in screen-space ambient occlusion for OpenGL 3.3+ (Python)
import ssao: the library from Python through ctypes.")

# Debian wants /usr/share/doc/<package>/copyright in every package
# (machine-readable format). Only the packages get it: these install rules are
# left out of a plain cmake --install, which has share/doc/ssao/LICENSE.
file(READ ${PROJECT_SOURCE_DIR}/LICENSE SSAO_LICENSE_TEXT)
string(STRIP "${SSAO_LICENSE_TEXT}" SSAO_LICENSE_TEXT)
string(REGEX REPLACE "\n\n" "\n.\n" SSAO_LICENSE_BODY "${SSAO_LICENSE_TEXT}")
string(REGEX REPLACE "\n" "\n " SSAO_LICENSE_BODY "${SSAO_LICENSE_BODY}")
set(SSAO_DEB_COPYRIGHT ${PROJECT_BINARY_DIR}/package/copyright)
file(WRITE ${SSAO_DEB_COPYRIGHT}
"Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/
Upstream-Name: ssao

Files: *
Copyright: 2026 the ssao authors
License: MIT

Files: assets/models/spot-on-ground.glb
Copyright: Keenan Crane (\"Spot\", Keenan's 3D Model Repository)
License: CC0-1.0

Files: assets/models/teapot-on-ground.glb
Copyright: none (the Utah teapot, Martin Newell, 1975)
License: public-domain

License: MIT
 ${SSAO_LICENSE_BODY}

License: CC0-1.0
 On Debian systems the full text is in /usr/share/common-licenses/CC0-1.0.

License: public-domain
 The Utah teapot's geometry is in the public domain.
")
foreach(pair runtime:libssao1 dev:libssao-dev tools:ssao-tools python:python3-ssao)
  string(REPLACE ":" ";" pair ${pair})
  list(GET pair 0 component)
  list(GET pair 1 package)
  install(FILES ${SSAO_DEB_COPYRIGHT} DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package}
          COMPONENT ${component} EXCLUDE_FROM_ALL)
endforeach()

set(CPACK_COMPONENTS_ALL runtime dev python)
if(SSAO_BUILD_TOOLS)
  list(APPEND CPACK_COMPONENTS_ALL tools)
endif()
include(CPack)
cpack_add_component(runtime DISPLAY_NAME "libssao.so.1" DESCRIPTION "The SSAO library")
cpack_add_component(dev DISPLAY_NAME "Development files" DEPENDS runtime
  DESCRIPTION "include/ssao/ssao.h, the CMake package (find_package(ssao)) and ssao.pc")
cpack_add_component(tools DISPLAY_NAME "Tools" DEPENDS runtime
  DESCRIPTION "ssao-host, ssao-reference, ssao-error, ssao-bench and ssao-viewer with the bundled scenes")
cpack_add_component(python DISPLAY_NAME "Python package" DEPENDS runtime
  DESCRIPTION "import ssao: the library from Python through ctypes")
