# ssao_version: a generated header with the project version (from project()
# in the top-level CMakeLists.txt), the one source every tool's --version reads.
set(SSAO_VERSION_DIR ${PROJECT_BINARY_DIR}/generated/version)
configure_file(${CMAKE_CURRENT_LIST_DIR}/ssao_project_version.h.in ${SSAO_VERSION_DIR}/ssao_project_version.h @ONLY)
add_library(ssao_version INTERFACE)
target_include_directories(ssao_version INTERFACE ${SSAO_VERSION_DIR})
