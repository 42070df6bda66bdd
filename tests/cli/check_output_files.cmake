# What railmodal does with its output files (docs/input.md, "Output files"): it never writes over
# an input, never follows or removes what is planted beside the output, and writes all outputs of
# a run or none.
#   -DEXE=railmodal -DDATA=data folder -DOUT=scratch folder -DCASE=output_is_input|planted_symlink|
#                   planted_directory|one_of_two_fails|same_output_twice
set(dir ${OUT}/${CASE})
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})

# Runs railmodal with the arguments after CODE and checks its exit code and its message.
function(expect code message)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE got OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT got EQUAL code)
    message(FATAL_ERROR "railmodal ${ARGN}: exit code ${got}, expected ${code}\nstderr: ${err}")
  endif()
  if(NOT err MATCHES "${message}")
    message(FATAL_ERROR "railmodal ${ARGN}: stderr does not match '${message}':\n${err}")
  endif()
endfunction()

# The folder holds exactly these names (hidden ones too: no temporary is left behind).
function(expect_entries folder)
  file(GLOB entries LIST_DIRECTORIES true RELATIVE ${folder} "${folder}/*" "${folder}/.*")
  list(SORT entries)
  set(wanted ${ARGN})
  list(SORT wanted)
  if(NOT "${entries}" STREQUAL "${wanted}")
    message(FATAL_ERROR "${folder} holds '${entries}', expected '${wanted}'")
  endif()
endfunction()

function(expect_same a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b} RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${a} was changed")
  endif()
endfunction()

set(scene ${DATA}/scenes/resort_car_free_response.toml)
if(CASE STREQUAL "output_is_input")
  # modes: -o onto the vehicle file; simulate: onto the vehicle its scene names (another name
  # for it: a symlink); compare: onto a shard it merges. Each input is left as it was.
  file(COPY ${DATA}/vehicles/resort_car.toml ${scene} DESTINATION ${dir})
  file(RENAME ${dir}/resort_car_free_response.toml ${dir}/scene.toml)
  file(READ ${dir}/scene.toml text)
  string(REPLACE "../vehicles/resort_car.toml" "resort_car.toml" text "${text}")
  file(WRITE ${dir}/scene.toml "${text}")
  file(COPY ${dir}/resort_car.toml DESTINATION ${dir}/original)
  file(CREATE_LINK resort_car.toml ${dir}/link.toml SYMBOLIC)
  set(refused "railmodal: error: the output '[^']*' is the input file '[^']*resort_car.toml'")
  expect(2 "${refused}" modes ${dir}/resort_car.toml -o ${dir}/resort_car.toml)
  expect(2 "${refused}" simulate ${dir}/scene.toml -o ${dir}/link.toml)
  expect(2 "${refused}" simulate ${dir}/scene.toml -o ${dir}/h.csv --spectra ${dir}/resort_car.toml)
  expect_same(${dir}/resort_car.toml ${dir}/original/resort_car.toml)
  set(study ${DATA}/studies/resort_against_fette.toml)
  expect(0 "^$" compare ${study} --shard 1/1 -q -o ${dir}/shard.json)
  file(COPY ${dir}/shard.json DESTINATION ${dir}/original)
  expect(2 "the output '[^']*shard.json' is the input file '[^']*shard.json'"
         compare ${study} --merge ${dir}/shard.json -o ${dir}/shard.json)
  expect_same(${dir}/shard.json ${dir}/original/shard.json)
  # compare --shard: onto the vehicle of a variant that only another shard evaluates.
  file(COPY ${study} DESTINATION ${dir}/data/studies)
  file(COPY ${DATA}/vehicles/resort_car.toml ${DATA}/vehicles/fette_car.toml DESTINATION ${dir}/data/vehicles)
  file(COPY ${DATA}/scenes/fette_car_10m_rails.toml DESTINATION ${dir}/data/scenes)
  file(COPY ${dir}/data/vehicles/fette_car.toml DESTINATION ${dir}/original)
  expect(2 "the output '[^']*fette_car.toml' is the input file '[^']*fette_car.toml'"
         compare ${dir}/data/studies/resort_against_fette.toml --shard 1/4 -q -o ${dir}/data/vehicles/fette_car.toml)
  expect_same(${dir}/data/vehicles/fette_car.toml ${dir}/original/fette_car.toml)
  expect_entries(${dir} data link.toml original resort_car.toml scene.toml shard.json)
elseif(CASE STREQUAL "planted_symlink")
  # A symlink planted where the output's temporary used to be (a fixed name), and one beside
  # it: neither target is written, the output is a file of its own, and no temporary is left.
  file(WRITE ${dir}/victim.txt "not railmodal's\n")
  file(MAKE_DIRECTORY ${dir}/out)
  file(CREATE_LINK ../victim.txt ${dir}/out/.modes.txt.tmp SYMBOLIC)
  file(CREATE_LINK ../victim.txt ${dir}/out/.modes.txt.tmp.1 SYMBOLIC)
  expect(0 "^$" modes ${DATA}/vehicles/resort_car.toml -o ${dir}/out/modes.txt)
  file(READ ${dir}/victim.txt victim)
  if(NOT victim STREQUAL "not railmodal's\n")
    message(FATAL_ERROR "railmodal wrote through a symlink planted in the output's folder")
  endif()
  if(IS_SYMLINK ${dir}/out/modes.txt)
    message(FATAL_ERROR "the output is the planted symlink")
  endif()
  file(READ ${dir}/out/modes.txt written)
  if(NOT written MATCHES "body bounce")
    message(FATAL_ERROR "modes.txt does not hold the modes:\n${written}")
  endif()
  expect_entries(${dir}/out .modes.txt.tmp .modes.txt.tmp.1 modes.txt)
elseif(CASE STREQUAL "planted_directory")
  # An empty directory of the temporary's old name is neither in the way nor removed.
  file(MAKE_DIRECTORY ${dir}/.modes.txt.tmp)
  expect(0 "^$" modes ${DATA}/vehicles/resort_car.toml -o ${dir}/modes.txt)
  expect_entries(${dir} .modes.txt.tmp modes.txt)
elseif(CASE STREQUAL "one_of_two_fails")
  # The histories cannot be written: the spectra are not written either. Up front (no folder)
  # and while writing (/dev/full takes nothing: a full disk).
  expect(5 "nodir/h.csv: error: cannot write the output file: cannot create a file in '[^']*nodir': No such file"
         simulate ${scene} -o ${dir}/nodir/h.csv --spectra ${dir}/spectra.csv)
  if(EXISTS /dev/full)
    expect(5 "/dev/full: error: cannot write the output file: No space left on device"
           simulate ${scene} -o /dev/full --spectra ${dir}/spectra.csv)
  endif()
  expect_entries(${dir})
elseif(CASE STREQUAL "same_output_twice")
  expect(2 "railmodal: error: two outputs of this run are one file \\('[^']*same.csv' and '[^']*same.csv'\\)"
         simulate ${scene} -o ${dir}/same.csv --spectra ${dir}/./same.csv)
  expect_entries(${dir})
  expect(0 "^$" simulate ${scene} -o /dev/null --spectra /dev/null)  # a device may take several
else()
  message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
