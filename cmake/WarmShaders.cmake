# Run by the build (target eikon_shader_cache, after eikon):
#   cmake -DEIKON=<eikon> -DROOT=<source dir> -DSCENES=<scene;…> -DSTAMP=<file> -P WarmShaders.cmake
# `eikon warm-shaders` renders each scene's first frame, writing nothing, so
# that the driver's shader cache (Mesa's: MESA_SHADER_CACHE_DIR, else
# XDG_CACHE_HOME, else ~/.cache) holds the programs the first run would
# otherwise compile. A machine where it cannot run (no EGL, no OpenGL 4.5)
# gets a warning and no stamp, never a failed build: its first run compiles
# them, and the next build tries again.
execute_process(COMMAND ${EIKON} warm-shaders ${SCENES}
                WORKING_DIRECTORY ${ROOT}
                RESULT_VARIABLE result
                ERROR_VARIABLE messages)
if(result EQUAL 0)
  message(STATUS "${messages}")
  file(TOUCH ${STAMP})
else()
  message(WARNING "eikon warm-shaders did not fill the shader cache (${result}); "
                  "the first `eikon run` compiles its shaders instead:\n${messages}")
endif()
