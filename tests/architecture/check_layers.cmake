# Data flows one way: input -> model -> analyses -> reports. A file of src/<stage>/ may include
# the private headers (src/<stage>/...) of its own stage and of the stages listed for it below,
# and any public header (railmodal/..., the types the stages exchange). A public header
# includes public headers only. Fails listing every include that breaks the rule.
#
#   cmake -DSOURCE_DIR=<project root> -P check_layers.cmake
#
# The order of the analyses: model < gear (the driving gear's forces: a model of its own, whose
# forces the excitation will take) < {excitation, solve, spectrum} < {response, simulate} <
# stability (hunting: eigenvalues against speed, limit cycles) < ride (random track: response
# spectra, comfort, realisations) < study < report. The reader (input) fills the model's vehicle and scene with the help of its
# spring formulas, and fills the study's plan type (study/study_plan.hpp, types only); nothing
# includes input: an analysis or a report that read files would be a back-edge. Files at the
# top of src/ belong to no stage, each a unit of its own: errors.cpp (InputError and the
# like, which every stage throws); load_study.cpp/.hpp, where the study reader (input) and the
# study plan (study) meet; comparison_curves.cpp, which reads and studies the designs a
# comparison report draws (public calls only), so that the report reads no file;
# compare_study.cpp, which joins the streamed ranking (study), its writer (report) and, for a
# merge, the shard reader (input) that hands it the results one at a time. Foundations
# below every stage, which include nothing of the stages: require_valid.hpp (the one check of
# an options struct) and summary/ (the stage clock of an AnalysisSummary), which any analysis
# and report may include, shortest_text.hpp (round-trip number text) edit_distance.hpp (how far a misspelt name is
# from the one meant) and xoshiro256.hpp (the portable random sequence of samples and track
# realisations), which any stage may. version.cpp defines
# railmodal::version() and includes nothing of the stages.
cmake_minimum_required(VERSION 3.16)

set(foundations "require_valid;summary;shortest_text;edit_distance;xoshiro256")
set(may_include_model "shortest_text")
set(may_include_input "model;shortest_text;edit_distance")
set(may_include_gear "model;${foundations}")
set(may_include_excitation "model;gear;${foundations}")
set(may_include_solve "model;gear;${foundations}")
set(may_include_spectrum "${foundations}")
set(may_include_response "model;gear;excitation;solve;spectrum;${foundations}")
set(may_include_simulate "model;gear;excitation;solve;spectrum;response;${foundations}")
set(may_include_stability "model;gear;excitation;solve;spectrum;response;simulate;${foundations}")
set(may_include_ride "model;gear;excitation;solve;spectrum;response;simulate;stability;${foundations}")
set(may_include_study "model;gear;excitation;solve;spectrum;response;simulate;stability;ride;${foundations}")
set(may_include_report "model;gear;excitation;solve;spectrum;response;simulate;stability;ride;study;${foundations}")
set(may_include_errors "")
set(may_include_load_study "input;study")
set(may_include_comparison_curves "")
set(may_include_compare_study "input;study;report")
set(may_include_require_valid "")
set(may_include_summary "")
set(may_include_shortest_text "")
set(may_include_edit_distance "")
set(may_include_xoshiro256 "")
set(may_include_version "")
# Single headers of another stage a stage may include: plan types a reader fills; the study's
# workers read each variant into kept storage and send an analysis's input error back to the
# variant's line (load_study.hpp's detail::read_variant_into and detail::variant_input_error,
# declarations only: the reader stays behind load_study.cpp).
set(may_include_headers_input "study/study_plan.hpp")
set(may_include_headers_study "load_study.hpp")

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "pass -DSOURCE_DIR=<project root>")
endif()

set(violations "")
file(GLOB_RECURSE sources RELATIVE "${SOURCE_DIR}/src" "${SOURCE_DIR}/src/*.cpp" "${SOURCE_DIR}/src/*.hpp")
file(GLOB_RECURSE public_headers RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/include/railmodal/*.hpp")
list(LENGTH sources source_count)
if(source_count EQUAL 0)
  message(FATAL_ERROR "no sources under ${SOURCE_DIR}/src")
endif()

foreach(file IN LISTS sources)
  if(file MATCHES "^([^/]+)/")
    set(stage "${CMAKE_MATCH_1}")
  else()
    get_filename_component(stage "${file}" NAME_WE)  # a file at the top of src/: errors, load_study
  endif()
  if(NOT DEFINED may_include_${stage})
    list(APPEND violations "src/${file}: in no known stage (add it to tests/architecture/check_layers.cmake)")
    continue()
  endif()
  file(STRINGS "${SOURCE_DIR}/src/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" header "${line}")
    if(header MATCHES "^railmodal/")
      continue()
    endif()
    if(header MATCHES "^([^/]+)/")
      set(target "${CMAKE_MATCH_1}")
    else()
      get_filename_component(target "${header}" NAME_WE)  # a header at the top of src/
    endif()
    if(target STREQUAL stage)
      continue()
    endif()
    list(FIND may_include_${stage} "${target}" allowed)
    list(FIND may_include_headers_${stage} "${header}" allowed_header)
    if(allowed EQUAL -1 AND allowed_header EQUAL -1)
      list(APPEND violations "src/${file}: ${stage} includes \"${header}\" of ${target}")
    endif()
  endforeach()
endforeach()

foreach(file IN LISTS public_headers)
  file(STRINGS "${SOURCE_DIR}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" header "${line}")
    if(NOT header MATCHES "^railmodal/")
      list(APPEND violations "${file}: a public header includes the private \"${header}\"")
    endif()
  endforeach()
endforeach()

if(violations)
  list(LENGTH violations count)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "${count} include(s) against the layering (input -> model -> analyses -> reports):\n  ${text}")
endif()
message(STATUS "layers: ${source_count} files of src/ include only what their stage may")
