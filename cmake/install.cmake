# What `cmake --install` puts where (included from the top-level CMakeLists.txt):
#   include/granular/…           the public headers (every lib/granular/**/*.hpp outside detail/)
#   lib/libgranular.so            with its components lib/libgranular_{slepc,hdf5}.so (loaded when
#                                 a run needs them), and the CMake package lib/cmake/granular/, lib/pkgconfig/granular.pc
#   bin/                          the tools
#   share/granular/plot/          the figure scripts
#   share/man/man1/               a man page per tool, from its --help (man_pages.cmake)
#   share/doc/granular/           README.md, physics.md, LICENSE, CITATION.cff, and docs/ (every page,
#                                 figure, result and the tutorial the README links, at the same paths)
include(CMakePackageConfigHelpers)

set(GRANULAR_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/granular)

install(DIRECTORY ${CMAKE_SOURCE_DIR}/lib/granular DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "detail" EXCLUDE)
# Keep the link directories of private dependencies that live outside the system paths (PETSc
# and SLEPc do on Debian) in the installed library's RUNPATH.
set_target_properties(granular PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)
install(TARGETS granular EXPORT granularTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ${GRANULAR_TOOL_TARGETS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Not exported: no program links a component; libgranular finds them beside itself.
if(GRANULAR_COMPONENT_TARGETS)
  install(TARGETS ${GRANULAR_COMPONENT_TARGETS} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
file(GLOB GRANULAR_PLOT_SCRIPTS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tools/plot/*.py)
install(PROGRAMS ${GRANULAR_PLOT_SCRIPTS} DESTINATION ${CMAKE_INSTALL_DATADIR}/granular/plot)
install(FILES ${CMAKE_SOURCE_DIR}/docs/physics.md ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/LICENSE
              ${CMAKE_SOURCE_DIR}/CITATION.cff DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs PATTERN site EXCLUDE)
include(${CMAKE_CURRENT_LIST_DIR}/man_pages.cmake)

# The CMake package: find_package(granular) gives the target granular::granular.
install(EXPORT granularTargets NAMESPACE granular:: DESTINATION ${GRANULAR_CMAKE_DIR})
get_target_property(GRANULAR_LIBRARY_TYPE granular TYPE)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/granularConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/granularConfig.cmake
                              INSTALL_DESTINATION ${GRANULAR_CMAKE_DIR})
# 0.x: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/granularConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/granularConfig.cmake ${CMAKE_BINARY_DIR}/granularConfigVersion.cmake
        DESTINATION ${GRANULAR_CMAKE_DIR})

# The pkg-config file, relocatable (paths relative to where the .pc file lies). Cflags carry the
# same interface as the CMake target: the Eigen alignment and the no-contraction rule.
set(GRANULAR_PC_CFLAGS "-DEIGEN_MAX_ALIGN_BYTES=${GRANULAR_EIGEN_ALIGN} -DEIGEN_MAX_STATIC_ALIGN_BYTES=${GRANULAR_EIGEN_ALIGN} -ffp-contract=off")
if(NOT RANDOM123_INCLUDE_DIR IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
  string(APPEND GRANULAR_PC_CFLAGS " -I${RANDOM123_INCLUDE_DIR}")
endif()
# A static libgranular needs its private dependencies at the final link (a shared one has them):
# the exact libraries this build linked, by path (PETSc's own .pc asks for an HDF5 that Debian
# keeps elsewhere, so Requires.private would not link).
set(GRANULAR_PC_LIBS_PRIVATE "")
if(GRANULAR_LIBRARY_TYPE STREQUAL "STATIC_LIBRARY")
  set(libs "${OpenMP_CXX_FLAGS}")
  foreach(lib ${SLEPC_LINK_LIBRARIES} ${PETSC_LINK_LIBRARIES} ${ARPACK_LINK_LIBRARIES} ${FFTW3_LINK_LIBRARIES} ${CHOLMOD_LIBRARY}
              ${LAPACK_LIBRARIES} ${HDF5_C_LIBRARIES} ${MPI_CXX_LIBRARIES} ${MPI_C_LIBRARIES})
    string(APPEND libs " ${lib}")
  endforeach()
  set(GRANULAR_PC_LIBS_PRIVATE "Libs.private: ${libs}\n")
endif()
file(RELATIVE_PATH GRANULAR_PC_TO_PREFIX ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" GRANULAR_PC_TO_PREFIX "${GRANULAR_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/granular.pc.in ${CMAKE_BINARY_DIR}/granular.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/granular.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
