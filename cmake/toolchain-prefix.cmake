# Where the bfin-elf toolchain lives: -DBFIN_TOOLCHAIN_DIR, else $BFIN_TOOLCHAIN_DIR, else the
# bootstrap's cache (emu/bootstrap.sh --print-prefix). Nothing is built here: run the bootstrap.
if(NOT BFIN_TOOLCHAIN_DIR AND DEFINED ENV{BFIN_TOOLCHAIN_DIR})
  set(BFIN_TOOLCHAIN_DIR "$ENV{BFIN_TOOLCHAIN_DIR}")
endif()
if(NOT BFIN_TOOLCHAIN_DIR)
  get_filename_component(_bvb_root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
  execute_process(COMMAND "${_bvb_root}/emu/bootstrap.sh" --print-prefix
                  OUTPUT_VARIABLE BFIN_TOOLCHAIN_DIR OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE _bvb_rc)
  if(NOT _bvb_rc EQUAL 0)
    message(FATAL_ERROR "emu/bootstrap.sh --print-prefix failed")
  endif()
endif()
if(NOT EXISTS "${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-gcc")
  message(FATAL_ERROR "no bfin-elf toolchain in ${BFIN_TOOLCHAIN_DIR}: run emu/bootstrap.sh first")
endif()
