# Bad input on the command line: exit status 1, one line naming the file,
# the value and the rule, and no output left behind. The inputs are a few
# hundred bytes written at test time by bad_inputs.sh.
set(bad ${CMAKE_CURRENT_BINARY_DIR}/bad_inputs)
set(case5 ${PROJECT_SOURCE_DIR}/tests/data/annotated/case5)
add_test(NAME cli.input_limits_setup
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/bad_inputs.sh ${bad})
set_tests_properties(cli.input_limits_setup PROPERTIES FIXTURES_SETUP bad_inputs)

# hair25d_cli_test with the fixture, and a check that OUT was not written.
function(input_limits_test name out stderr)
  list(JOIN ARGN " " args)
  add_test(NAME cli.${name}
    COMMAND bash -c "rm -rf ${out}; bash ${CMAKE_CURRENT_SOURCE_DIR}/expect.sh 1 --stderr '${stderr}' -- $<TARGET_FILE:hair25d> ${args} && test ! -e ${out} && test -z \"$(ls -A | grep '^\\.${out}')\""
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(cli.${name} PROPERTIES FIXTURES_REQUIRED bad_inputs)
endfunction()

# 68 bytes claiming 16000x3000 RGBA: refused from the header and the file's
# size, before 190 MB are allocated for pixels that are not there.
input_limits_test(model_tiny_png_claiming_many_pixels m_claim
  "claim.png: truncated: the header says 16000x3000 RGBA"
  -q model ${bad}/claim.png --regions ${bad}/claim.png -o m_claim)
input_limits_test(model_regions_of_scattered_pieces m_checker
  "checker.png: more than 16384 separate pieces"
  -q model ${bad}/grey.png --regions ${bad}/checker.png -o m_checker)
input_limits_test(eval_layering_regions_of_scattered_pieces ev_checker.json
  "regions.png: more than 16384 separate pieces"
  -q eval-layering ${bad}/cases --json ev_checker.json)
input_limits_test(segment_deeply_nested_strokes s_deep
  "deep.json: arrays and objects nested more than 64 levels"
  -q segment ${case5}/image.png --strokes ${bad}/deep.json -o s_deep)
input_limits_test(segment_strokes_that_never_end s_zero
  "/dev/zero: more than 268435456 bytes"
  -q segment ${case5}/image.png --strokes /dev/zero -o s_zero)
