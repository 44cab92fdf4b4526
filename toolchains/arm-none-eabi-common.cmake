# What every arm-none-eabi bare-metal toolchain file shares: the compiler and
# binutils, try_compile as a static library (no linker script there), the
# bare-metal switch and the find-root modes. Included by
# arm-none-eabi-cortex-m7.cmake and arm-none-eabi-cortex-r5f.cmake after they
# set MPTRACK_CPU_FLAGS_DEFAULT and MPTRACK_BAREMETAL_PROFILE.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
# try_compile cannot link a bare-metal executable without a linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(MPTRACK_TRIPLE arm-none-eabi)
find_program(MPTRACK_CXX ${MPTRACK_TRIPLE}-g++ NO_CACHE)
if(NOT MPTRACK_CXX)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-g++ not found: apt-get install gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib")
endif()
set(CMAKE_CXX_COMPILER ${MPTRACK_CXX})
# C: the C API's example and consumers (mptrack_c.h).
find_program(MPTRACK_CC ${MPTRACK_TRIPLE}-gcc NO_CACHE)
if(NOT MPTRACK_CC)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-gcc not found: apt-get install gcc-arm-none-eabi")
endif()
set(CMAKE_C_COMPILER ${MPTRACK_CC})
find_program(CMAKE_AR ${MPTRACK_TRIPLE}-gcc-ar NO_CACHE)
find_program(CMAKE_RANLIB ${MPTRACK_TRIPLE}-gcc-ranlib NO_CACHE)
find_program(MPTRACK_NM ${MPTRACK_TRIPLE}-nm NO_CACHE)
find_program(MPTRACK_SIZE ${MPTRACK_TRIPLE}-size NO_CACHE)

set(MPTRACK_BAREMETAL ON CACHE BOOL "Bare-metal build: core library + minimal image only")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
