# Man pages: each tool's --help as share/man/man1/<tool>.1 (help2man), so that `man spectrum`
# works after `cmake --install`. Included from install.cmake; skipped, with a note, when help2man
# is missing (tools/install-deps.sh installs it) and in the sanitizer builds.
set(GRANULAR_MAN_SUMMARY_spectrum "linear spectrum (modes, frequencies, IPR) of one granular chain")
set(GRANULAR_MAN_SUMMARY_ipr-map "mean mode frequency and IPR of disordered granular chains on a (q, xi) grid")
set(GRANULAR_MAN_SUMMARY_correlations "correlations of the bead types along disordered granular chains")
set(GRANULAR_MAN_SUMMARY_localization "transfer-matrix localization length and density of states of a granular chain")
set(GRANULAR_MAN_SUMMARY_spreading "energy spreading after a kick in a granular chain (Hertzian dynamics)")
set(GRANULAR_MAN_SUMMARY_exponents "the transport exponents gamma and eta of kicked disordered granular chains")
set(GRANULAR_MAN_SUMMARY_restitution "coefficient of restitution of a two-bead collision")
set(GRANULAR_MAN_SUMMARY_breathers "breathers of a granular chain: periodic orbits by shooting, continuation, Floquet stability")
set(GRANULAR_MAN_SUMMARY_crystal "modes of a 2D granular crystal: every mode or those nearest a frequency, vector IPR, <r>")
set(GRANULAR_MAN_SUMMARY_crystal-ipr-map "IPR map of disordered 2D granular crystals: mean IPR and <r> against frequency and disorder")
set(GRANULAR_MAN_SUMMARY_klein-gordon "spreading and weak chaos (m2, P, finite-time mLE) in the disordered Klein-Gordon chain")
set(GRANULAR_MAN_SUMMARY_butterfly "Hofstadter butterfly and box-counting dimension of quasiperiodic granular chains")

find_program(GRANULAR_HELP2MAN help2man)
if(NOT GRANULAR_HELP2MAN)
  message(STATUS "help2man not found: no man pages (tools/install-deps.sh installs it)")
elseif(GRANULAR_TOOL_TARGETS AND NOT GRANULAR_SANITIZE)
  set(man_pages)
  foreach(tool ${GRANULAR_TOOL_TARGETS})
    set(summary "${GRANULAR_MAN_SUMMARY_${tool}}")
    if(NOT summary)
      set(summary "a tool of granular, the disordered granular chains toolkit")
    endif()
    set(page ${CMAKE_BINARY_DIR}/man/${tool}.1)
    add_custom_command(OUTPUT ${page}
                       COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
                       COMMAND ${GRANULAR_HELP2MAN} --no-info --section=1 "--name=${summary}"
                               "--version-string=${tool} (granular) ${PROJECT_VERSION}"
                               "--manual=granular ${PROJECT_VERSION}" --output=${page} $<TARGET_FILE:${tool}>
                       DEPENDS ${tool} COMMENT "man page ${tool}.1" VERBATIM)
    list(APPEND man_pages ${page})
  endforeach()
  add_custom_target(granular_man_pages ALL DEPENDS ${man_pages})
  install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()
