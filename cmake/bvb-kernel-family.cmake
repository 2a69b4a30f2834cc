# bvb_add_kernel_family: a kernel family of a project outside this tree, checked, benchmarked and
# budgeted by bfbench without a line of this tree edited. find_package(bvb) (bvbConfig.cmake in a
# build directory of this tree) includes this file; examples/out-of-tree uses it.
#
#   bvb_add_kernel_family(NAME
#     KERNELS kernel...       each has the C entry KERNEL_c and the assembly entry KERNEL_asm
#     [C_ONLY kernel...]      C only: the entry KERNEL_c
#     HEADER file...          the family's headers (their directories are its include path)
#     C file...               the C references: compiled for the host and for the Blackfin
#     [ASM file...]           the assembly, for the Blackfin
#     CHECK file...           the harness side (C++): its Family, registered with BVB_FAMILY
#     BUDGETS file            the family's budgets, in ci/budgets.json's format
#     [INCLUDE_DIRS dir...])  more include directories, for the C and the check
#
# It builds
#   NAME.elf       this tree's runtime and the family's kernels, nothing else (firmware/family);
#                  the registry lists KERNELS then C_ONLY, in the order given
#   bfbench-NAME   bfbench with every command, for the family's kernels alone: its firmware is
#                  NAME.elf and its budgets file BUDGETS (bfbench budgets --update writes there)
# and returns in NAME_BFBENCH the bfbench's target name. In a host-only build of this tree there
# is no toolchain: bfbench-NAME is built (list, run --impl host), NAME.elf is not.

function(bvb_add_kernel_family name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "BUDGETS" "KERNELS;C_ONLY;HEADER;C;ASM;CHECK;INCLUDE_DIRS")
  set(fn "bvb_add_kernel_family(${name})")
  if(NOT name MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "bvb_add_kernel_family: '${name}' is not a name (letters, digits, _)")
  endif()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${fn}: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  foreach(need HEADER C CHECK BUDGETS)
    if(NOT arg_${need})
      message(FATAL_ERROR "${fn}: ${need} is missing")
    endif()
  endforeach()
  if(NOT arg_KERNELS AND NOT arg_C_ONLY)
    message(FATAL_ERROR "${fn}: no KERNELS (or C_ONLY kernels)")
  endif()
  if(arg_KERNELS AND NOT arg_ASM)
    message(FATAL_ERROR "${fn}: KERNELS have assembly entries, and no ASM file is given")
  endif()

  # Every path absolute, relative to the calling directory; a missing file is an error here, not
  # a compiler's later. The budgets file may be missing: bfbench budgets --update writes it.
  foreach(part HEADER C ASM CHECK BUDGETS INCLUDE_DIRS)
    set(abs_${part} "")
    foreach(f IN LISTS arg_${part})
      get_filename_component(f "${f}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
      if(NOT part STREQUAL "BUDGETS" AND NOT EXISTS "${f}")
        message(FATAL_ERROR "${fn}: ${part} ${f} does not exist")
      endif()
      list(APPEND abs_${part} "${f}")
    endforeach()
  endforeach()
  set(includes "${abs_INCLUDE_DIRS}")
  foreach(h IN LISTS abs_HEADER)
    get_filename_component(d "${h}" DIRECTORY)
    list(APPEND includes "${d}")
  endforeach()
  list(REMOVE_DUPLICATES includes)

  # The kernel list, in kernels.def's format: the firmware's registry and the host's are both
  # expanded from this one file, and the firmware's hash of it is checked on every run.
  set(def "")
  set(names "")
  foreach(k IN LISTS arg_KERNELS arg_C_ONLY)
    if(NOT k MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
      message(FATAL_ERROR "${fn}: kernel '${k}' is not a C identifier")
    endif()
    if(k IN_LIST names)
      message(FATAL_ERROR "${fn}: kernel ${k} is listed twice")
    endif()
    list(APPEND names "${k}")
    if(k IN_LIST arg_KERNELS)
      string(APPEND def "BVB_KERNEL(${k}, ${k}_c, ${k}_asm)\n")
    else()
      string(APPEND def "BVB_KERNEL_C(${k}, ${k}_c)\n")
    endif()
  endforeach()
  set(dir "${CMAKE_CURRENT_BINARY_DIR}/bvb-${name}")
  set(list_file "${dir}/kernels.def")
  file(CONFIGURE OUTPUT "${list_file}" CONTENT "/* ${fn}'s kernels (generated) */\n${def}" @ONLY)

  # The firmware image, built by the Blackfin toolchain this tree was built with.
  set(elf "${dir}/firmware/${name}.elf")
  if(BVB_BFIN_TOOLCHAIN_DIR)
    include(ExternalProject)
    ExternalProject_Add(${name}_firmware
      SOURCE_DIR "${BVB_SOURCE_DIR}/firmware/family"
      BINARY_DIR "${dir}/firmware"
      CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${BVB_SOURCE_DIR}/cmake/bfin-elf.cmake
                 -DBFIN_TOOLCHAIN_DIR=${BVB_BFIN_TOOLCHAIN_DIR}
                 -DCMAKE_BUILD_TYPE=Release
      CMAKE_CACHE_ARGS -DBVB_FAMILY_NAME:STRING=${name}
                       -DBVB_FAMILY_LIST:FILEPATH=${list_file}
                       "-DBVB_FAMILY_SOURCES:STRING=${abs_C};${abs_ASM}"
                       "-DBVB_FAMILY_INCLUDE_DIRS:STRING=${includes}"
      INSTALL_COMMAND ""
      BUILD_ALWAYS ON
      BUILD_BYPRODUCTS "${elf}")
  endif()

  # The C references for the host: the same sources, compiled natively.
  add_library(${name}_ref STATIC ${abs_C} ${abs_HEADER})
  set_target_properties(${name}_ref PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON)
  target_include_directories(${name}_ref PUBLIC ${includes})
  target_link_libraries(${name}_ref PUBLIC bvb::ref)

  # bfbench for the family: a main() that names the family's kernels, image and budgets file,
  # then this tree's commands and the family's check.
  set(BVB_FAMILY_NAME "${name}")
  set(BVB_FAMILY_LIST "${list_file}")
  set(BVB_FAMILY_ELF "${elf}")
  set(BVB_FAMILY_BUDGETS "${abs_BUDGETS}")
  configure_file("${BVB_SOURCE_DIR}/cmake/bfbench-family-main.cpp.in" "${dir}/main.cpp" @ONLY)
  add_executable(bfbench-${name} "${dir}/main.cpp" ${abs_CHECK} $<TARGET_OBJECTS:bvb::cli>)
  target_link_libraries(bfbench-${name} PRIVATE ${name}_ref bvb::host)
  if(TARGET ${name}_firmware)
    add_dependencies(bfbench-${name} ${name}_firmware)
  endif()
  set(${name}_BFBENCH bfbench-${name} PARENT_SCOPE)
endfunction()
