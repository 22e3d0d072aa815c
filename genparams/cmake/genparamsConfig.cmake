# genparams for CMake (3.17 or newer): generate typed ROS 2 parameter modules at build time.
#
#   find_package(genparams REQUIRED)   # with genparams_DIR or CMAKE_PREFIX_PATH
#                                      # set to the output of `genparams cmake-dir`
#   genparams_generate_python(<target> <schema.yaml>
#     [MODULE <name>]          # module file name without .py; default <schema stem>_params
#     [PACKAGE <python.pkg>]   # Python package it belongs to; default ${PROJECT_NAME}
#     [DESTINATION <dir>]      # Python install dir; default ${PYTHON_INSTALL_DIR} (set by
#                              # ament_cmake_python) or lib/pythonX.Y/site-packages
#     [OUTPUT_VARIABLE <var>]) # receives the path of the generated file in the build tree
#
# <target> is a custom target that is part of `all`; the module is regenerated whenever
# the schema changes, and `install` puts it at <DESTINATION>/<package path>/<MODULE>.py.
# The generator is the `genparams` command (GENPARAMS_EXECUTABLE), looked up next to the
# Python environment this file was installed into, then on PATH.

get_filename_component(_genparams_package_dir "${CMAKE_CURRENT_LIST_DIR}" DIRECTORY)
# <prefix>/lib/pythonX.Y/site-packages/genparams -> <prefix>/bin holds the console script.
get_filename_component(_genparams_prefix "${_genparams_package_dir}/../../../.." ABSOLUTE)

find_program(GENPARAMS_EXECUTABLE
  NAMES genparams
  HINTS "${_genparams_prefix}/bin"
  DOC "The genparams command that generates parameter modules")
if(NOT GENPARAMS_EXECUTABLE)
  set(genparams_FOUND FALSE)
  set(genparams_NOT_FOUND_MESSAGE
    "the 'genparams' command was found neither in ${_genparams_prefix}/bin nor on PATH; "
    "install genparams (pip install genparams) or set GENPARAMS_EXECUTABLE")
  return()
endif()

# The command must belong to this very installation, or generated code and the runtime
# it imports could come from two different versions.
execute_process(
  COMMAND "${GENPARAMS_EXECUTABLE}" cmake-dir
  OUTPUT_VARIABLE _genparams_reported_dir
  OUTPUT_STRIP_TRAILING_WHITESPACE
  RESULT_VARIABLE _genparams_result)
get_filename_component(_genparams_here "${CMAKE_CURRENT_LIST_DIR}" REALPATH)
if(_genparams_reported_dir)
  get_filename_component(_genparams_reported_dir "${_genparams_reported_dir}" REALPATH)
endif()
if(NOT _genparams_result EQUAL 0 OR NOT _genparams_reported_dir STREQUAL _genparams_here)
  set(genparams_FOUND FALSE)
  set(genparams_NOT_FOUND_MESSAGE
    "${GENPARAMS_EXECUTABLE} belongs to another genparams installation "
    "(its cmake-dir is '${_genparams_reported_dir}', this file is in '${_genparams_here}'); "
    "set GENPARAMS_EXECUTABLE or genparams_DIR so both match")
  return()
endif()

function(genparams_generate_python target schema)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "" "MODULE;PACKAGE;DESTINATION;OUTPUT_VARIABLE" "")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR
      "genparams_generate_python(${target}): unexpected arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()

  get_filename_component(schema_path "${schema}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT EXISTS "${schema_path}")
    message(FATAL_ERROR "genparams_generate_python(${target}): no schema at ${schema_path}")
  endif()

  if(ARG_MODULE)
    set(module "${ARG_MODULE}")
  else()
    get_filename_component(stem "${schema_path}" NAME_WE)
    set(module "${stem}_params")
  endif()
  if(NOT module MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR
      "genparams_generate_python(${target}): MODULE '${module}' is not a Python module name")
  endif()

  if(ARG_PACKAGE)
    set(package "${ARG_PACKAGE}")
  else()
    set(package "${PROJECT_NAME}")
  endif()
  if(NOT package MATCHES "^[A-Za-z_][A-Za-z0-9_]*(\\.[A-Za-z_][A-Za-z0-9_]*)*$")
    message(FATAL_ERROR
      "genparams_generate_python(${target}): PACKAGE '${package}' is not a Python package name")
  endif()
  string(REPLACE "." "/" package_path "${package}")

  if(ARG_DESTINATION)
    set(destination "${ARG_DESTINATION}")
  elseif(DEFINED PYTHON_INSTALL_DIR)
    set(destination "${PYTHON_INSTALL_DIR}")
  else()
    find_package(Python3 REQUIRED COMPONENTS Interpreter)
    set(destination "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/site-packages")
  endif()

  set(output "${CMAKE_CURRENT_BINARY_DIR}/genparams/${target}/${package_path}/${module}.py")
  add_custom_command(
    OUTPUT "${output}"
    COMMAND "${GENPARAMS_EXECUTABLE}" generate "${schema_path}" -o "${output}"
    # A new genparams version rewrites __init__.py, so modules follow upgrades.
    DEPENDS "${schema_path}" "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../__init__.py"
    COMMENT "genparams: generating ${package}.${module} from ${schema}"
    VERBATIM)
  add_custom_target(${target} ALL DEPENDS "${output}")
  install(FILES "${output}" DESTINATION "${destination}/${package_path}")

  if(ARG_OUTPUT_VARIABLE)
    set(${ARG_OUTPUT_VARIABLE} "${output}" PARENT_SCOPE)
  endif()
endfunction()
