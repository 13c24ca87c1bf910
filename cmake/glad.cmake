# Generates the GL loader with glad 2 at build time (multi-context mode, so the
# plugin fills its own function table from the host's proc-address function).
# glad is imported from Debian's python3-glad, which lives in /usr/bin/python3's
# dist-packages (a pyenv python3 earlier on PATH would not see it).
find_program(SSAO_SYSTEM_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT SSAO_SYSTEM_PYTHON)
  set(SSAO_SYSTEM_PYTHON ${Python3_EXECUTABLE})
endif()
set(GLAD_DIR ${PROJECT_BINARY_DIR}/glad)
set(GLAD_EXTENSIONS GL_KHR_debug,GL_ARB_clip_control,GL_ARB_timer_query,GL_ARB_direct_state_access,GL_ARB_viewport_array,GL_ARB_draw_buffers_blend)
add_custom_command(
  OUTPUT ${GLAD_DIR}/src/gl.c ${GLAD_DIR}/include/glad/gl.h
  COMMAND ${SSAO_SYSTEM_PYTHON} -m glad --quiet --reproducible --api gl:core=4.5
          --extensions ${GLAD_EXTENSIONS} --out-path ${GLAD_DIR} c --mx
  DEPENDS ${CMAKE_CURRENT_LIST_FILE}
  COMMENT "Generating the GL loader with glad 2"
  VERBATIM)
add_library(ssao_glad STATIC ${GLAD_DIR}/src/gl.c)
target_include_directories(ssao_glad PUBLIC ${GLAD_DIR}/include)
# Hidden: linked into libssao.so, glad's symbols must not be exported.
set_target_properties(ssao_glad PROPERTIES C_VISIBILITY_PRESET hidden POSITION_INDEPENDENT_CODE ON)
