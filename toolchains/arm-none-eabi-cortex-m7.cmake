# Bare-metal build for Cortex-M7 with the double-precision FPU (fpv5-d16),
# hard-float ABI, newlib-nano, no exceptions and no RTTI.
#   cmake -S . -B build/m7 -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-none-eabi-cortex-m7.cmake
# Builds mptrack_core_static and a minimal image (tests/baremetal) that links
# with no OS and no semihosting, then checks with nm that core pulls in no
# heap or exception machinery.
set(MPTRACK_CPU_FLAGS_DEFAULT "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
set(MPTRACK_BAREMETAL_PROFILE M CACHE STRING "Arm profile of the bare-metal target (M or R)")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-common.cmake)
