# The package version is the C interface version: project()'s major.minor must
# be SSAO_API_VERSION's in include/ssao/ssao.h (a consumer that requires 1.2
# gets the 1.2 interface). Bumping one without the other stops the configure.
file(STRINGS ${PROJECT_SOURCE_DIR}/include/ssao/ssao.h SSAO_API_VERSION_LINE
     REGEX "^#define SSAO_API_VERSION SSAO_MAKE_VERSION\\([0-9]+, *[0-9]+\\)")
if(NOT SSAO_API_VERSION_LINE MATCHES "SSAO_MAKE_VERSION\\(([0-9]+), *([0-9]+)\\)")
  message(FATAL_ERROR "include/ssao/ssao.h: no '#define SSAO_API_VERSION SSAO_MAKE_VERSION(MAJOR, MINOR)' line")
endif()
set(SSAO_API_VERSION_TEXT "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")
if(NOT "${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}" STREQUAL SSAO_API_VERSION_TEXT)
  message(FATAL_ERROR "project(ssao VERSION ${PROJECT_VERSION}) does not match the C interface version "
          "${SSAO_API_VERSION_TEXT} of include/ssao/ssao.h: the package's major.minor is the interface's")
endif()

# ssao_version: a generated header with the project version (from project()
# in the top-level CMakeLists.txt), the one source every tool's --version reads.
set(SSAO_VERSION_DIR ${PROJECT_BINARY_DIR}/generated/version)
configure_file(${CMAKE_CURRENT_LIST_DIR}/ssao_project_version.h.in ${SSAO_VERSION_DIR}/ssao_project_version.h @ONLY)
add_library(ssao_version INTERFACE)
target_include_directories(ssao_version INTERFACE ${SSAO_VERSION_DIR})
