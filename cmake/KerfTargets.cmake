# Compile options shared by every Kerf target, and a helper that declares one library per module.

add_library(kerf_options INTERFACE)
target_include_directories(kerf_options INTERFACE ${PROJECT_SOURCE_DIR})
target_compile_options(kerf_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wconversion -Wsign-conversion -Wdouble-promotion
  -Wimplicit-fallthrough)
if(KERF_WERROR)
  target_compile_options(kerf_options INTERFACE -Werror)
endif()
if(KERF_FUZZ)
  # Coverage for libFuzzer plus the sanitizers that turn silent corruption into crashes.
  target_compile_options(kerf_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined
    -fno-omit-frame-pointer)
  target_link_options(kerf_options INTERFACE -fsanitize=address,undefined)
endif()
if(KERF_SANITIZE)
  target_compile_options(kerf_options INTERFACE -fsanitize=${KERF_SANITIZE} -fno-omit-frame-pointer)
  target_link_options(kerf_options INTERFACE -fsanitize=${KERF_SANITIZE})
endif()

# kerf_module(NAME <name> SOURCES ... DEPS ...): static library kerf_<name>, alias kerf::<name>.
function(kerf_module)
  cmake_parse_arguments(M "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(kerf_${M_NAME} STATIC ${M_SOURCES})
  add_library(kerf::${M_NAME} ALIAS kerf_${M_NAME})
  target_link_libraries(kerf_${M_NAME} PUBLIC kerf_options ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
endfunction()
