# ssao-host: the program. Sees the plugin only through include/ssao/ssao.h and
# dlopen (ssao_egl's plugin::Library); loads scenes through ssao_scene.
find_package(tinyexr REQUIRED)

# The G-buffer pass and the GL helpers, also used by ssao-bench and the tests.
add_library(ssao_host_gl STATIC
  ${CMAKE_CURRENT_LIST_DIR}/gl_util.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gbuffer.cpp)
target_include_directories(ssao_host_gl PUBLIC ${CMAKE_CURRENT_LIST_DIR} ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(ssao_host_gl PUBLIC ssao_glad ssao_scene glm::glm PRIVATE ssao_fullscreen_vert)
target_compile_options(ssao_host_gl PRIVATE ${SSAO_WARNINGS})

# The rest of ssao-host except main(): its flags, the settings and camera a run
# starts from, the lighting pass and the picture files; ssao-viewer uses them too.
add_library(ssao_host_app STATIC
  ${CMAKE_CURRENT_LIST_DIR}/cli.cpp
  ${CMAKE_CURRENT_LIST_DIR}/preset_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/debug_view_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/run_setup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/composite.cpp
  ${CMAKE_CURRENT_LIST_DIR}/image_io.cpp)
target_include_directories(ssao_host_app PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(ssao_host_app PUBLIC ssao_host_gl ssao_scene ssao_locate glm::glm PRIVATE tinyexr::tinyexr)
target_compile_options(ssao_host_app PRIVATE ${SSAO_WARNINGS})

add_executable(ssao-host ${CMAKE_CURRENT_LIST_DIR}/main.cpp)
target_link_libraries(ssao-host PRIVATE ssao_host_app ssao_egl)
target_compile_options(ssao-host PRIVATE ${SSAO_WARNINGS})
# Building the program builds the plugin it loads (never linked: dlopen only).
add_dependencies(ssao-host ssao)

# ssao-viewer: the same scene, G-buffer and plugin in a GLFW window.
include(${CMAKE_CURRENT_LIST_DIR}/viewer/viewer.cmake OPTIONAL)
