# Compiler flags for bit-for-bit reproducible floating point.
#
# - no fast-math of any kind (-fno-fast-math is explicit): it lets the
#   compiler reassociate and drop NaN checks, which changes results between builds;
# - -ffp-contract=off: no fused multiply-add contraction, so a*b+c rounds the
#   same whatever the optimiser decides;
# - baseline x86-64, never tuned to the build host's CPU: the same
#   instructions on every machine.
add_library(vahf_flags INTERFACE)
target_compile_options(vahf_flags INTERFACE
  -ffp-contract=off -fno-fast-math -Wall -Wextra -Wpedantic -Wshadow
  -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  target_compile_options(vahf_flags INTERFACE -march=x86-64 -mtune=generic)
endif()
if(VAHF_WERROR)
  target_compile_options(vahf_flags INTERFACE -Werror)
endif()
if(VAHF_SANITIZE)
  target_compile_options(vahf_flags INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(vahf_flags INTERFACE -fsanitize=address,undefined)
endif()
