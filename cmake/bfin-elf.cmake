# CMake toolchain file for bare-metal Blackfin (bfin-elf, ADSP-BF537), freestanding C and assembly.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR bfin)
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-prefix.cmake)
# CMake re-reads this file for its compiler checks; they must see the same toolchain.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES BFIN_TOOLCHAIN_DIR)

set(CMAKE_C_COMPILER ${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-gcc)
set(CMAKE_ASM_COMPILER ${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-gcc)
set(CMAKE_AR ${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-ar CACHE FILEPATH "")
set(CMAKE_RANLIB ${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-ranlib CACHE FILEPATH "")
set(CMAKE_OBJDUMP ${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-objdump CACHE FILEPATH "")
set(BFIN_RUN ${BFIN_TOOLCHAIN_DIR}/bin/bfin-elf-run)
# No C library: compiler checks must not try to link an executable.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "-mcpu=bf537 -ffreestanding")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=bf537 -ffreestanding")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-mcpu=bf537 -nostdlib -nostartfiles")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
