# Install rules: the two libraries, their headers, the CMake package (find_package(facet) gives
# facet::engine and facet::evaluation) and a pkg-config file for each (pkg-config --cflags --libs
# facet, or facet-evaluation for both).
# docs/library.md shows each way of using them; scripts/check-install.sh tries each.
include(CMakePackageConfigHelpers)

set(FACET_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/facet)

# The libraries are static, so what they link privately travels with them: the interface targets
# of third_party/ are exported too (as facet::detail_*), and facetConfig.cmake finds the packages
# behind them again.
foreach(_dep glm options warnings stb png jpeg tinyobj hwy)
  set_target_properties(facet_${_dep} PROPERTIES EXPORT_NAME detail_${_dep})
endforeach()

install(TARGETS facet_engine facet_evaluation facet_glm facet_options facet_warnings facet_stb
                facet_png facet_jpeg facet_tinyobj facet_hwy
        EXPORT facetTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Both libraries' headers under one include/facet/: the engine's, the generated version.hpp, and
# the evaluation library's facet/evaluation/. The advanced headers (facet/advanced/) are installed
# with the engine's: the unstable API the accuracy tools use (docs/library.md).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/include/facet
                  ${PROJECT_BINARY_DIR}/generated/include/facet
                  ${PROJECT_SOURCE_DIR}/evaluation/include/facet
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT facetTargets NAMESPACE facet:: DESTINATION ${FACET_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/facetConfig.cmake.in
  ${PROJECT_BINARY_DIR}/generated/facetConfig.cmake INSTALL_DESTINATION ${FACET_CMAKE_DIR})
# While the major version is 0, a minor version may break the API (docs/library.md).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/generated/facetConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/generated/facetConfig.cmake
              ${PROJECT_BINARY_DIR}/generated/facetConfigVersion.cmake
        DESTINATION ${FACET_CMAKE_DIR})

# pkg-config: static libraries, so every library they need is in Libs/Requires (not .private),
# and `pkg-config --libs facet` alone links a program.
set(FACET_PC_OPENMP_LIBS "${OpenMP_CXX_FLAGS}")
# Relocatable: the prefix is found from where facet.pc lies, so `cmake --install --prefix P`
# works for any P.
file(RELATIVE_PATH FACET_PC_TO_PREFIX "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
string(REGEX REPLACE "/$" "" FACET_PC_TO_PREFIX "${FACET_PC_TO_PREFIX}")
# facet.pc is the engine; facet-evaluation.pc the evaluation library, which requires it.
configure_file(${PROJECT_SOURCE_DIR}/cmake/facet.pc.in ${PROJECT_BINARY_DIR}/generated/facet.pc
               @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/facet-evaluation.pc.in
               ${PROJECT_BINARY_DIR}/generated/facet-evaluation.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/generated/facet.pc
              ${PROJECT_BINARY_DIR}/generated/facet-evaluation.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/THIRD_PARTY_NOTICES
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/facet)

# The command-line tool, when built (its chart scripts are found in the source tree it was
# built from, or in scripts/ beside it).
if(FACET_BUILD_APP)
  install(TARGETS facet RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
