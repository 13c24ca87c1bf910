# cmake --install build --prefix P installs:
#   P/lib/libssao.so.<version>, libssao.so.1 (SONAME), libssao.so (dev link)
#   P/include/ssao/ssao.h
#   P/lib/cmake/ssao/ssaoConfig.cmake, ssaoConfigVersion.cmake, ssaoTargets*.cmake
#     (ssao::ssao links the library, ssao::headers is the header alone)
#   P/lib/pkgconfig/ssao.pc
#   P/bin/ssao-host (with SSAO_BUILD_TOOLS), ssao-reference, ssao-error, ssao-bench
#     (also SSAO_BUILD_REFERENCE), ssao-viewer (where GLFW was found)
#   P/share/ssao/models, scenes (the bundled data the tools find beside bin/),
#     viewer/demo.txt (ssao-viewer --script: a tour of the main keys)
#   P/lib/python3/dist-packages/ssao (the Python package; cmake/python.cmake)
#   P/share/doc/ssao/README.md, LICENSE, assets-README.md, docs/*.md (the manuals)
# Every path inside is relative to P, so the tree may be moved after installing.
include(CMakePackageConfigHelpers)

set(SSAO_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ssao)

install(TARGETS ssao ssao_headers EXPORT ssaoTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT dev
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/ssao/ssao.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ssao COMPONENT dev)
install(EXPORT ssaoTargets NAMESPACE ssao:: DESTINATION ${SSAO_CMAKE_DIR} COMPONENT dev)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ssaoConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/ssaoConfig.cmake
  INSTALL_DESTINATION ${SSAO_CMAKE_DIR})
# Same major = compatible: the C ABI only grows within a major version.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/ssaoConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/ssaoConfig.cmake ${PROJECT_BINARY_DIR}/package/ssaoConfigVersion.cmake
  DESTINATION ${SSAO_CMAKE_DIR} COMPONENT dev)

# pkg-config: prefix relative to the .pc file itself, so a moved tree works.
file(RELATIVE_PATH SSAO_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SSAO_PC_TO_PREFIX "${SSAO_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/ssao.pc.in ${PROJECT_BINARY_DIR}/package/ssao.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/ssao.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

set(SSAO_DOC_DIR ${CMAKE_INSTALL_DATADIR}/doc/ssao)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${SSAO_DOC_DIR} COMPONENT runtime)
# The manuals the README links to (docs/api.md, ...), beside it as in the source tree.
file(GLOB SSAO_MANUALS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${SSAO_MANUALS} DESTINATION ${SSAO_DOC_DIR}/docs COMPONENT dev)

if(SSAO_BUILD_TOOLS)
  # ssao-reference, -error and -bench only with SSAO_BUILD_REFERENCE; ssao-viewer only where GLFW was found.
  foreach(tool ssao-host ssao-reference ssao-error ssao-bench ssao-viewer)
    if(TARGET ${tool})
      install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
    endif()
  endforeach()
  install(FILES ${PROJECT_SOURCE_DIR}/assets/viewer/demo.txt DESTINATION ${CMAKE_INSTALL_DATADIR}/ssao/viewer COMPONENT tools)
  # The data the tools find at <bin>/../share/ssao (host/locate.cpp), with the
  # models' own licences (assets/models/README.md).
  install(FILES
      ${PROJECT_SOURCE_DIR}/assets/models/spot-on-ground.glb
      ${PROJECT_SOURCE_DIR}/assets/models/teapot-on-ground.glb
      ${PROJECT_SOURCE_DIR}/assets/models/README.md
    DESTINATION ${CMAKE_INSTALL_DATADIR}/ssao/models COMPONENT tools)
  install(FILES ${PROJECT_SOURCE_DIR}/assets/scenes/corner.gltf ${PROJECT_SOURCE_DIR}/assets/scenes/overhang.gltf
      ${PROJECT_SOURCE_DIR}/assets/scenes/creases.gltf ${PROJECT_SOURCE_DIR}/assets/scenes/clutter.gltf
    DESTINATION ${CMAKE_INSTALL_DATADIR}/ssao/scenes COMPONENT tools)
endif()
