# The version comes from the genparams package itself, so it can never disagree with it.
file(STRINGS "${CMAKE_CURRENT_LIST_DIR}/../_version.py" _genparams_version_line
  REGEX "^__version__ = \"[^\"]+\"$")
string(REGEX REPLACE "^__version__ = \"([^\"]+)\"$" "\\1" PACKAGE_VERSION
  "${_genparams_version_line}")

# Compatible: at least the requested version, with the same major version.
string(REGEX MATCH "^[0-9]+" _genparams_major "${PACKAGE_VERSION}")
if(PACKAGE_FIND_VERSION AND (PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION
    OR NOT PACKAGE_FIND_VERSION_MAJOR STREQUAL _genparams_major))
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
endif()
