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
# newlib's multilib for these flags is thumb/v7+fp/hard (interworking).
set(MPTRACK_CPU_FLAGS_DEFAULT "-mcpu=cortex-r5 -mfpu=vfpv3-d16 -mfloat-abi=hard")
set(MPTRACK_BAREMETAL_PROFILE R CACHE STRING "Arm profile of the bare-metal target (M or R)")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-common.cmake)
