# Bare-metal build for Cortex-R5F (the master subsystem core of TI's
# xWR radar SoCs) with VFPv3-D16 (single and double precision), hard-float
# ABI, Arm state, newlib-nano, no exceptions and no RTTI.
#   cmake -S . -B build/r5f -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-none-eabi-cortex-r5f.cmake
# Builds mptrack_core_static and the footprint image (tests/baremetal,
# start-up startup_cortex_r.cpp, memory map cortex_r5.ld) and checks with nm
# that neither pulls in heap or exception machinery; ctest also prints the
# image's section sizes. Nothing runs on it here: QEMU 7.2's only Cortex-R5F
# model is the ZynqMP RPU inside the xlnx-zcu102 machine (a different memory
# map, cores released by the A53 boot flow), not tried; the golden runner
# runs on the Cortex-M7 (tests/baremetal/golden_runner.cpp).
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
find_program(CMAKE_AR ${MPTRACK_TRIPLE}-gcc-ar NO_CACHE)
find_program(CMAKE_RANLIB ${MPTRACK_TRIPLE}-gcc-ranlib NO_CACHE)
find_program(MPTRACK_NM ${MPTRACK_TRIPLE}-nm NO_CACHE)
find_program(MPTRACK_SIZE ${MPTRACK_TRIPLE}-size NO_CACHE)

# newlib's multilib for these flags is thumb/v7+fp/hard (interworking).
set(MPTRACK_CPU_FLAGS_DEFAULT "-mcpu=cortex-r5 -mfpu=vfpv3-d16 -mfloat-abi=hard")
set(MPTRACK_BAREMETAL ON CACHE BOOL "Bare-metal build: core library + minimal image only")
set(MPTRACK_BAREMETAL_PROFILE R CACHE STRING "Arm profile of the bare-metal target (M or R)")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
