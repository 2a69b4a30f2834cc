# What every firmware image is built of: the compile options, the runtime (the monitor and its
# helpers) and bvb_image. firmware/CMakeLists.txt builds this tree's images with it, and
# firmware/family/ the image of one kernel family from outside this tree.
set(BVB_FIRMWARE_ROOT ${CMAKE_CURRENT_LIST_DIR})

set(CMAKE_C_STANDARD 99)
add_compile_options(-O2 -Wall -Wextra)
# Line information for bfbench profile, for the assembly only: there it adds debug sections
# and nothing else, where GCC 12's -g changes the C code this target generates (a few
# functions come out 2 to 4 bytes different), so its cycles would change with it. The C is
# profiled per instruction and function, without source lines.
add_compile_options($<$<COMPILE_LANGUAGE:ASM>:-g>)

set(BVB_RUNTIME_SOURCES
    runtime/crt0.S runtime/call.S runtime/dma.S runtime/udiv.S runtime/main.c runtime/stream.c
    runtime/string.c)
list(TRANSFORM BVB_RUNTIME_SOURCES PREPEND ${BVB_FIRMWARE_ROOT}/)
add_library(bvb_runtime OBJECT ${BVB_RUNTIME_SOURCES})
target_include_directories(bvb_runtime PUBLIC ${BVB_FIRMWARE_ROOT}/include ${BVB_FIRMWARE_ROOT}/runtime)

# bvb_image(NAME LIST KERNELS LIBRARY [SOURCES...]): NAME.elf, its registry expanded from the
# kernel list file LIST (kernels.def's format), linked with the runtime and the kernels of
# LIBRARY (a static library: only what the list names is pulled in).
function(bvb_image name list kernels)
  add_executable(${name} ${BVB_FIRMWARE_ROOT}/runtime/registry.c ${ARGN})
  set_target_properties(${name} PROPERTIES SUFFIX ".elf")
  target_include_directories(${name} PRIVATE ${BVB_FIRMWARE_ROOT}/include ${BVB_FIRMWARE_ROOT}/runtime
                             ${BVB_FIRMWARE_ROOT})
  target_compile_definitions(${name} PRIVATE BVB_KERNEL_LIST="${list}")
  target_link_libraries(${name} PRIVATE bvb_runtime ${kernels} gcc)
  target_link_options(${name} PRIVATE -T ${BVB_FIRMWARE_ROOT}/runtime/link.ld
                      -Wl,-Map=${CMAKE_CURRENT_BINARY_DIR}/${name}.map -Wl,--gc-sections
                      -Wl,--no-warn-rwx-segments)
  set_target_properties(${name} PROPERTIES LINK_DEPENDS ${BVB_FIRMWARE_ROOT}/runtime/link.ld)
endfunction()
