# Interface targets that carry the project's compile options, so no global flags are set.

add_library(facet_warnings INTERFACE)
add_library(facet::warnings ALIAS facet_warnings)
target_compile_options(facet_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual -Wnull-dereference
  # GCC 12 reports std::optional<std::string-holding struct> as maybe-uninitialized: a known
  # false positive (GCC bug 105562) that would bury real warnings.
  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>
  # C++20 designated initializers leave the other members at their defaults on purpose
  # (DrawInput{.clip = ..., .indices = ...}); GCC 12 still warns about each one.
  -Wno-missing-field-initializers
  $<$<BOOL:${FACET_WERROR}>:-Werror>)

add_library(facet_options INTERFACE)
add_library(facet::options ALIAS facet_options)
target_compile_features(facet_options INTERFACE cxx_std_20)
if(FACET_SANITIZE)
  string(REPLACE "," ";" _facet_sanitizers "${FACET_SANITIZE}")
  foreach(_s IN LISTS _facet_sanitizers)
    target_compile_options(facet_options INTERFACE -fsanitize=${_s})
    target_link_options(facet_options INTERFACE -fsanitize=${_s})
  endforeach()
  target_compile_options(facet_options INTERFACE -fno-omit-frame-pointer -fno-sanitize-recover=all)
endif()
# Fuzzing: the engine and everything linked with it get libFuzzer's coverage instrumentation; the
# fuzz targets themselves link libFuzzer's main (fuzz/CMakeLists.txt).
if(FACET_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "FACET_FUZZ needs Clang's libFuzzer: configure with "
                        "-DCMAKE_CXX_COMPILER=clang++")
  endif()
  target_compile_options(facet_options INTERFACE -fsanitize=fuzzer-no-link)
endif()
