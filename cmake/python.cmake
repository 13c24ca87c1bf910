# The Python package (python/ssao) in the build tree and in the install.
#
# build/python/ssao: a copy of the package plus _version.py (from project())
# and _build_paths.py naming this build's libssao.so, so that
#   PYTHONPATH=build/python python3 -c 'import ssao; ssao.Library()'
# loads the library of this build. _build_paths.py is never installed.
#
# cmake --install: <prefix>/${SSAO_PYTHON_INSTALL_DIR}/ssao with _version.py
# and _install_paths.py (the way from the package to <prefix>/lib, relative,
# so a moved prefix still works). The default, lib/python3/dist-packages, is
# where Debian's python3 looks under /usr (also when the libdir is multiarch,
# lib/x86_64-linux-gnu); for another prefix put
# <prefix>/lib/python3/dist-packages on PYTHONPATH.
set(SSAO_PYTHON_INSTALL_DIR "lib/python3/dist-packages" CACHE STRING
    "Where cmake --install puts the ssao Python package, relative to the prefix")

set(SSAO_PYTHON_BUILD_DIR ${PROJECT_BINARY_DIR}/python/ssao)
set(SSAO_PYTHON_SOURCES __init__.py py.typed)
foreach(f IN LISTS SSAO_PYTHON_SOURCES)
  configure_file(${PROJECT_SOURCE_DIR}/python/ssao/${f} ${SSAO_PYTHON_BUILD_DIR}/${f} COPYONLY)
endforeach()
file(WRITE ${SSAO_PYTHON_BUILD_DIR}/_version.py
  "\"\"\"Written by CMake from project(ssao VERSION ...): do not edit.\"\"\"\n__version__ = \"${PROJECT_VERSION}\"\n")
file(GENERATE OUTPUT ${SSAO_PYTHON_BUILD_DIR}/_build_paths.py CONTENT
  "\"\"\"This build tree's library, for the build tree's copy of the module only (never installed).\"\"\"\nPLUGIN = \"$<TARGET_FILE:ssao>\"\n")

if(SSAO_INSTALL)
  file(RELATIVE_PATH SSAO_PACKAGE_TO_LIBDIR ${CMAKE_INSTALL_PREFIX}/${SSAO_PYTHON_INSTALL_DIR}/ssao
       ${CMAKE_INSTALL_FULL_LIBDIR})
  file(WRITE ${PROJECT_BINARY_DIR}/package/python/_install_paths.py
    "\"\"\"Written by CMake for the installed package: the library's folder, relative to this one.\"\"\"\nPACKAGE_TO_LIBDIR = \"${SSAO_PACKAGE_TO_LIBDIR}\"\n")
  install(FILES ${SSAO_PYTHON_BUILD_DIR}/__init__.py ${SSAO_PYTHON_BUILD_DIR}/py.typed
                ${SSAO_PYTHON_BUILD_DIR}/_version.py ${PROJECT_BINARY_DIR}/package/python/_install_paths.py
          DESTINATION ${SSAO_PYTHON_INSTALL_DIR}/ssao COMPONENT python)
endif()
