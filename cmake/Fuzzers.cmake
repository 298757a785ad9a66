# libFuzzer targets over every reader of user files (tests/fuzz). Built by
# the "fuzz" preset with clang; `./dev.sh fuzz [SECONDS]` runs each one.
# The target eikon_fuzzers builds them all and nothing else.
add_custom_target(eikon_fuzzers)

function(eikon_fuzzer name source)
  add_executable(${name} ${source} tests/fuzz/FuzzScratchFile.cpp)
  target_link_libraries(${name} PRIVATE eikon_io)
  eikon_target_defaults(${name})
  target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  add_dependencies(eikon_fuzzers ${name})
endfunction()

eikon_fuzzer(fuzz_scene tests/fuzz/fuzz_scene.cpp)
eikon_fuzzer(fuzz_vdb tests/fuzz/fuzz_vdb.cpp)
eikon_fuzzer(fuzz_image tests/fuzz/fuzz_image.cpp)
foreach(format obj ply off stl)
  eikon_fuzzer(fuzz_mesh_${format} tests/fuzz/fuzz_mesh.cpp)
  target_compile_definitions(fuzz_mesh_${format} PRIVATE EIKON_FUZZ_MESH_EXTENSION=".${format}")
endforeach()
