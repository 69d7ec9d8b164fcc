# How impulse2d compiles its own targets. Set per target, never globally, so a project that adds
# impulse2d with add_subdirectory keeps its own flags and ours stay out of its targets.
#
# Warnings on and clean. Determinism: no fast-math, and no fused multiply-add contraction, so a
# scene gives the same bits on every run and every optimisation level of this compiler
# (docs/determinism.md). The hardening builds (docs/hardening.md) add the sanitizers.
function(impulse2d_target_options target)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_features(${target} PRIVATE cxx_std_17)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -ffp-contract=off
                                             -fno-fast-math)
  endif()
  if(IMPULSE2D_SANITIZE OR IMPULSE2D_FUZZ)
    set(sanitizers -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
    target_compile_options(${target} PRIVATE ${sanitizers})
    target_link_options(${target} PRIVATE ${sanitizers})
  endif()
  # The sanitized build links some sixty programs with debug information: lld, or else gold,
  # links each in a fraction of the time of the default linker.
  if(IMPULSE2D_SANITIZE AND IMPULSE2D_HAS_LLD)
    target_link_options(${target} PRIVATE -fuse-ld=lld)
  elseif(IMPULSE2D_SANITIZE AND IMPULSE2D_HAS_GOLD)
    target_link_options(${target} PRIVATE -fuse-ld=gold)
  endif()
  if(IMPULSE2D_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
