# ssao-viewer: the plugin on a glTF scene in a GLFW window (X11), keys as the
# reference demo. Built only where GLFW 3.3 is installed (libglfw3-dev).
# Included from host/host_app.cmake.
find_package(glfw3 3.3 QUIET)
if(NOT glfw3_FOUND)
  message(STATUS "ssao-viewer: GLFW 3.3 not found (apt-get install libglfw3-dev); the viewer is not built")
  return()
endif()

# Everything but the window and main() (script, options, keys, frame, overlay), also linked by the tests.
add_library(ssao_viewer_core STATIC
  ${CMAKE_CURRENT_LIST_DIR}/script.cpp
  ${CMAKE_CURRENT_LIST_DIR}/options.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controls.cpp
  ${CMAKE_CURRENT_LIST_DIR}/overlay.cpp
  ${CMAKE_CURRENT_LIST_DIR}/renderer.cpp)
target_include_directories(ssao_viewer_core PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(ssao_viewer_core PUBLIC ssao_host_app glfw)
target_compile_options(ssao_viewer_core PRIVATE ${SSAO_WARNINGS})

add_executable(ssao-viewer
  ${CMAKE_CURRENT_LIST_DIR}/main.cpp
  ${CMAKE_CURRENT_LIST_DIR}/window.cpp)
target_link_libraries(ssao-viewer PRIVATE ssao_viewer_core ssao_egl)
target_compile_options(ssao-viewer PRIVATE ${SSAO_WARNINGS})
# Building the program builds the plugin it loads (never linked: dlopen only).
add_dependencies(ssao-viewer ssao)
