# ssao_scene: glTF loading (tinygltf), the camera and the checks of its
# command-line flags (camera_flags) and the record of what an image was made
# with (provenance), shared by ssao-host and ssao-reference.
# Included from host/CMakeLists.txt.
find_package(nlohmann_json QUIET)
find_path(SSAO_TINYGLTF_INCLUDE_DIR tiny_gltf.h REQUIRED)
find_library(SSAO_TINYGLTF_LIBRARY tinygltf REQUIRED)
add_library(ssao_scene STATIC
  ${CMAKE_CURRENT_LIST_DIR}/scene.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_limits.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_files.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camera.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camera_flags.cpp
  ${CMAKE_CURRENT_LIST_DIR}/provenance.cpp)
target_include_directories(ssao_scene PUBLIC ${CMAKE_CURRENT_LIST_DIR})
# tiny_gltf.h is third-party: include it as a system header so -Werror stays on our code.
target_include_directories(ssao_scene SYSTEM PRIVATE ${SSAO_TINYGLTF_INCLUDE_DIR})
target_link_libraries(ssao_scene PUBLIC glm::glm ssao_flags ssao_locate ssao_input_file PRIVATE ${SSAO_TINYGLTF_LIBRARY})
if(TARGET nlohmann_json::nlohmann_json)
  target_link_libraries(ssao_scene PRIVATE nlohmann_json::nlohmann_json)
endif()
target_compile_options(ssao_scene PRIVATE ${SSAO_WARNINGS})
