# Flag sets shared by every mptrack target, as INTERFACE libraries.

# Bit-exactness (spec: developers' guide rule 2, style_anchors.md section 10):
# - -ffp-contract=off: no fused multiply-add, so a*b+c rounds twice on every
#   target (aarch64 and Cortex-M7 have FMA, baseline x86-64 does not).
# - EIGEN_DONT_VECTORIZE: Eigen's packet math uses FMA intrinsics and
#   ISA-dependent reduction orders; with it off, x86-64, aarch64 and armhf
#   produce identical bits (measured, see README).
# - never the fast-math flag family (it reorders and contracts freely).
add_library(mptrack_deterministic INTERFACE)
add_library(mptrack::deterministic ALIAS mptrack_deterministic)
target_compile_options(mptrack_deterministic INTERFACE -ffp-contract=off ${mptrack_cpu_flags})
target_compile_definitions(mptrack_deterministic INTERFACE EIGEN_DONT_VECTORIZE EIGEN_MPL2_ONLY)
target_link_options(mptrack_deterministic INTERFACE ${mptrack_cpu_flags})
target_compile_features(mptrack_deterministic INTERFACE cxx_std_17)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64" AND NOT CMAKE_CROSSCOMPILING)
  # SSE2 scalar math only; never x87 (excess precision breaks bit-exactness).
  target_compile_options(mptrack_deterministic INTERFACE -mfpmath=sse -msse2)
endif()

# Warnings: strict for our own code (PX4-Matrix / doctest set).
add_library(mptrack_warnings INTERFACE)
add_library(mptrack::warnings ALIAS mptrack_warnings)
target_compile_options(mptrack_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
  -Wold-style-cast -Wdouble-promotion -Wfloat-conversion -Wcast-align -Wundef
  -Wnon-virtual-dtor)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^arm$|armv7")
  # GCC's "parameter passing ... changed in GCC 7.1" ABI note on 32-bit Arm
  # concerns only code mixing GCC < 7 objects; we build everything ourselves.
  target_compile_options(mptrack_warnings INTERFACE -Wno-psabi)
endif()
option(MPTRACK_WERROR "Treat warnings as errors" ON)
if(MPTRACK_WERROR)
  target_compile_options(mptrack_warnings INTERFACE -Werror)
endif()

# Embedded discipline: what a target build uses (also applied to the host
# core objects, so the host build proves the same rules).
add_library(mptrack_embedded INTERFACE)
add_library(mptrack::embedded ALIAS mptrack_embedded)
target_compile_options(mptrack_embedded INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions -fno-rtti>
  -ffunction-sections -fdata-sections)

set(CMAKE_CXX_EXTENSIONS OFF)

# Sanitizer leg (reliability issue; style_anchors.md section 13: "host legs
# with -fsanitize=address,undefined"). Host only: ASan/UBSan runtimes are
# not available for the bare-metal or qemu targets. -fno-sanitize-recover
# turns every UBSan report into a failing exit, so ctest sees it.
# mptrack_deterministic links it, so every target built here gets it.
option(MPTRACK_SANITIZE "Build everything with -fsanitize=address,undefined" OFF)
add_library(mptrack_sanitize INTERFACE)
add_library(mptrack::sanitize ALIAS mptrack_sanitize)
if(MPTRACK_SANITIZE)
  set(mptrack_sanitize_flags -fsanitize=address,undefined -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  # -g1 (line tables): enough for the sanitizers' stack traces; full -g
  # made the sanitized tracker tests take 1.7x longer to compile.
  target_compile_options(mptrack_sanitize INTERFACE ${mptrack_sanitize_flags} -g1)
  target_link_options(mptrack_sanitize INTERFACE ${mptrack_sanitize_flags})
  # Tells tests/support/alloc_guard.cpp to count through the sanitizer's
  # malloc hooks instead of interposing malloc (which would bypass ASan).
  target_compile_definitions(mptrack_sanitize INTERFACE MPTRACK_SANITIZE=1)
  target_link_libraries(mptrack_deterministic INTERFACE mptrack_sanitize)
endif()
