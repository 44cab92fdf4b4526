# Cross build for 32-bit Arm Linux, Cortex-A7/A9 class with NEON-VFPv4,
# hard-float ABI.
#   cmake -S . -B build/armhf -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-linux-gnueabihf.cmake
# CPU flags go through MPTRACK_CPU_FLAGS (override on the command line with
# -DMPTRACK_CPU_FLAGS="..." for another core); tests run under qemu-arm.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(MPTRACK_TRIPLE arm-linux-gnueabihf)
find_program(MPTRACK_CXX ${MPTRACK_TRIPLE}-g++ NO_CACHE)
if(NOT MPTRACK_CXX)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-g++ not found: apt-get install g++-arm-linux-gnueabihf")
endif()
set(CMAKE_CXX_COMPILER ${MPTRACK_CXX})
# C: the C API's test and example (mptrack_c.h; tests/CMakeLists.txt).
find_program(MPTRACK_CC ${MPTRACK_TRIPLE}-gcc NO_CACHE)
if(NOT MPTRACK_CC)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-gcc not found: apt-get install gcc-${MPTRACK_TRIPLE}")
endif()
set(CMAKE_C_COMPILER ${MPTRACK_CC})

# Default CPU flags; the top-level CMakeLists applies them to mptrack targets.
set(MPTRACK_CPU_FLAGS_DEFAULT "-mcpu=cortex-a7 -mfpu=neon-vfpv4 -mfloat-abi=hard")

set(CMAKE_FIND_ROOT_PATH /usr/${MPTRACK_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

find_program(MPTRACK_QEMU qemu-arm NO_CACHE)
if(MPTRACK_QEMU)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${MPTRACK_QEMU};-L;/usr/${MPTRACK_TRIPLE}")
endif()
