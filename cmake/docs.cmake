# The documentation site (Sphinx + MyST + Breathe/Doxygen + nbsphinx, all Debian packages):
#   cmake --build build --target docs      -> build/docs-site/html/index.html
# tools/build-docs.sh assembles and builds it with warnings as errors; the test `docs_site`
# (label docs) builds it and opens it in headless Chromium (tests/docs/check_site.py), after the
# tutorial test so that the site shows the executed tutorial. `cmake --install` puts the HTML in
# share/doc/granular/html when it has been built.
if(GRANULAR_SANITIZE OR GRANULAR_TSAN OR NOT GRANULAR_PYTHON)
  return()
endif()
set(GRANULAR_SITE_BUILD ${CMAKE_SOURCE_DIR}/tools/build-docs.sh ${CMAKE_BINARY_DIR})
add_custom_target(docs COMMAND bash ${GRANULAR_SITE_BUILD} DEPENDS ${GRANULAR_TOOL_TARGETS} granular_python
                  COMMENT "documentation site: build/docs-site/html" VERBATIM)
install(DIRECTORY ${CMAKE_BINARY_DIR}/docs-site/html/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/html OPTIONAL)
if(BUILD_TESTING)
  add_test(NAME docs_site
           COMMAND bash -c "bash \"$0\" \"$1\" && /usr/bin/python3 \"$2\" \"$1/docs-site/html\" \"$1/docs-site/screenshots\""
                   ${CMAKE_SOURCE_DIR}/tools/build-docs.sh ${CMAKE_BINARY_DIR}
                   ${CMAKE_SOURCE_DIR}/tests/docs/check_site.py)
  set_tests_properties(docs_site PROPERTIES LABELS docs TIMEOUT 600 DEPENDS python_pip_install_tutorial COST 85)
  # Every Markdown table renders as a table: as many cells per row as its delimiter row.
  add_test(NAME docs_tables COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/docs/check_tables.py ${CMAKE_SOURCE_DIR})
  set_tests_properties(docs_tables PROPERTIES LABELS docs)
  # A page that names another page's file in prose links it (on the site a bare name is dead text).
  add_test(NAME docs_page_links
           COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/docs/check_page_links.py ${CMAKE_SOURCE_DIR})
  set_tests_properties(docs_page_links PROPERTIES LABELS docs)
  # Every shell and Python block of the README and the docs pages, run as a reader would.
  add_test(NAME docs_examples
           COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/docs/run_examples.py ${CMAKE_SOURCE_DIR}
                   ${CMAKE_BINARY_DIR} ${CMAKE_BINARY_DIR}/tests/docs-examples)
  set_tests_properties(docs_examples PROPERTIES LABELS docs TIMEOUT 1200 COST 90)
  # Its extractor and runner on a synthetic page: a command block in a list item (fenced, indented)
  # or an indented block runs, a failing one fails, a formula does not run (a second).
  add_test(NAME docs_examples_self_test
           COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tests/docs/run_examples.py --self-test)
  set_tests_properties(docs_examples_self_test PROPERTIES LABELS docs)
endif()
