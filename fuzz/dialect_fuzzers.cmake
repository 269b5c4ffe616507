# uprog_dialect_fuzzers(DEF REGISTRY MAKER PREFIX): for every dialect the registry list DEF names
# (src/dialects/registry.def's form), the targets PREFIXfuzz_compile_NAME, …fuzz_command_line_NAME
# and …fuzz_download_NAME, from the one source of each (fuzz/fuzz_dialect_<kind>.cpp) built for
# that dialect. uprog_dialect_own_fuzzers(DEF MAKER): each listed dialect's own targets,
# fuzz/fuzz_NAME_*.cpp, over its library uprog_dialect_NAME. MAKER(TARGET SOURCES … DEPS …)
# makes each: a libFuzzer executable (fuzz/CMakeLists.txt) or a replay of inputs
# (tests/dialect/CMakeLists.txt). No dialect is named here or by the callers.
set(UPROG_FUZZ_DIR ${CMAKE_CURRENT_LIST_DIR})
function(uprog_dialect_fuzzers def registry maker prefix)
  uprog_registry_dialects(names ${def})
  foreach(name ${names})
    foreach(kind compile command_line download)
      set(target ${prefix}fuzz_${kind}_${name})
      cmake_language(CALL ${maker} ${target}
        SOURCES ${UPROG_FUZZ_DIR}/fuzz_dialect_${kind}.cpp DEPS ${registry} uprog_controller)
      target_compile_definitions(${target} PRIVATE UPROG_FUZZ_DIALECT="${name}")
      target_include_directories(${target} PRIVATE ${UPROG_FUZZ_DIR})
    endforeach()
  endforeach()
endfunction()

function(uprog_dialect_own_fuzzers def maker)
  uprog_registry_dialects(names ${def})
  foreach(name ${names})
    file(GLOB own ${UPROG_FUZZ_DIR}/fuzz_${name}_*.cpp)
    foreach(source ${own})
      get_filename_component(target ${source} NAME_WE)
      cmake_language(CALL ${maker} ${target} SOURCES ${source}
        DEPS uprog_dialect_${name} uprog_controller uprog_vm)
      target_include_directories(${target} PRIVATE ${UPROG_FUZZ_DIR})
    endforeach()
  endforeach()
endfunction()
