# Fails if an object file or archive needs heap or exception machinery.
#   cmake -DNM=<nm> -DFILE=<lib.a|image> [-DMODE=undefined|all] -P check_no_heap.cmake
# MODE=undefined (default) inspects the undefined symbols: what core asks the
# rest of the program for. MODE=all inspects every symbol of a linked image.
if(NOT NM OR NOT FILE)
  message(FATAL_ERROR "usage: cmake -DNM=<nm> -DFILE=<file> -P check_no_heap.cmake")
endif()
if(NOT MODE)
  set(MODE undefined)
endif()
if(MODE STREQUAL "undefined")
  set(nm_args -u)
else()
  set(nm_args)
endif()
execute_process(COMMAND ${NM} ${nm_args} ${FILE}
  OUTPUT_VARIABLE symbols RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${FILE}: ${err}")
endif()
# operator new/delete (all mangled forms start _Znw/_Zna/_Zdl/_Zda), C heap,
# and the C++ exception runtime.
set(forbidden "_Znw[jm]|_Zna[jm]|_ZdlPv|_ZdaPv|[^_a-z]malloc$|[^_a-z]calloc$|[^_a-z]realloc$|[^_a-z]free$|__cxa_throw|__cxa_allocate_exception|__cxa_begin_catch|__gxx_personality")
string(REPLACE "\n" ";" lines "${symbols}")
set(bad "")
foreach(line IN LISTS lines)
  if(line MATCHES "(${forbidden})")
    list(APPEND bad "${line}")
  endif()
endforeach()
if(bad)
  list(JOIN bad "\n  " bad_text)
  message(FATAL_ERROR "heap/exception symbols in ${FILE}:\n  ${bad_text}")
endif()
list(LENGTH lines n)
message(STATUS "no heap or exception symbols in ${FILE} (${n} ${MODE} symbol lines checked)")
