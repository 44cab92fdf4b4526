# Cross build for 64-bit Arm Linux (Cortex-A53/A72 class).
#   cmake -S . -B build/aarch64 -DCMAKE_TOOLCHAIN_FILE=toolchains/aarch64-linux-gnu.cmake
# Tests run under qemu-user through CMAKE_CROSSCOMPILING_EMULATOR, so `ctest`
# in the build directory executes the same golden tests as on the host.
# Only compilers, sysroot and emulator are set here; flags live on targets.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(MPTRACK_TRIPLE aarch64-linux-gnu)
find_program(MPTRACK_CXX ${MPTRACK_TRIPLE}-g++ NO_CACHE)
if(NOT MPTRACK_CXX)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-g++ not found: apt-get install g++-aarch64-linux-gnu")
endif()
set(CMAKE_CXX_COMPILER ${MPTRACK_CXX})
# C: the C API's test and example (mptrack_c.h; tests/CMakeLists.txt).
find_program(MPTRACK_CC ${MPTRACK_TRIPLE}-gcc NO_CACHE)
if(NOT MPTRACK_CC)
  message(FATAL_ERROR "${MPTRACK_TRIPLE}-gcc not found: apt-get install gcc-${MPTRACK_TRIPLE}")
endif()
set(CMAKE_C_COMPILER ${MPTRACK_CC})

set(CMAKE_FIND_ROOT_PATH /usr/${MPTRACK_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

find_program(MPTRACK_QEMU qemu-aarch64 NO_CACHE)
if(MPTRACK_QEMU)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${MPTRACK_QEMU};-L;/usr/${MPTRACK_TRIPLE}")
endif()
