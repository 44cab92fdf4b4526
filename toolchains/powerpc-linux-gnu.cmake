# Cross build for 32-bit big-endian PowerPC Linux with the classic hard-float
# FPU (the byte order and FPU class of NXP's e200 radar MCUs; GCC no longer
# targets their SPE/VLE variants, so this is the closest Debian toolchain).
#   cmake -S . -B build/ppc -DCMAKE_TOOLCHAIN_FILE=toolchains/powerpc-linux-gnu.cmake
# Tests run under qemu-ppc, so `ctest` compares the same golden files as on
# the little-endian targets: the big-endian proof of bit-exactness.
# -ffp-contract=off (mptrack_deterministic) keeps fmadd/fmsub out.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR ppc)

set(MPTRACK_TRIPLE powerpc-linux-gnu)
find_program(MPTRACK_CXX ${MPTRACK_TRIPLE}-g++ NO_CACHE)
if(NOT MPTRACK_CXX)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-g++ not found: apt-get install g++-powerpc-linux-gnu")
endif()
set(CMAKE_CXX_COMPILER ${MPTRACK_CXX})
# C: the C API's test and example (mptrack_c.h; tests/CMakeLists.txt).
find_program(MPTRACK_CC ${MPTRACK_TRIPLE}-gcc NO_CACHE)
if(NOT MPTRACK_CC)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-gcc not found: apt-get install gcc-${MPTRACK_TRIPLE}")
endif()
set(CMAKE_C_COMPILER ${MPTRACK_CC})

# Hard float, big-endian (the triple's defaults, spelled out).
set(MPTRACK_CPU_FLAGS_DEFAULT "-mbig-endian -mhard-float")

set(CMAKE_FIND_ROOT_PATH /usr/${MPTRACK_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

find_program(MPTRACK_QEMU qemu-ppc NO_CACHE)
if(MPTRACK_QEMU)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${MPTRACK_QEMU};-L;/usr/${MPTRACK_TRIPLE}")
endif()

# QEMU 7.2's qemu-ppc raises SIGILL on an FPU instruction glibc's libm uses
# (docs/targets.md): tests that compare against libm (LIBM_REFERENCE in
# tests/CMakeLists.txt) are not built for this target.
set(MPTRACK_EMULATOR_LIBM_BROKEN ON)
