# Exit status, the same in hair25d and hair25d-generate (docs/cli.md): 1 and
# one line naming the option, the value and the rule for a value that breaks
# its option's rule; 2 for wrong usage (an unknown or missing option); and
# nothing written either way.
set(case5 ${PROJECT_SOURCE_DIR}/tests/data/annotated/case5)

# name CODE STDERR-regex ARGS...: runs hair25d-generate -o <name> ..., checks
# the status, stderr and that no <name> folder was made.
function(generate_status_test name code stderr)
  list(JOIN ARGN " " args)
  set(one_line "")
  if(code EQUAL 1)
    set(one_line "&& test $(wc -l < ${name}.err) = 1")
  endif()
  add_test(NAME cli.generate_${name}
    COMMAND bash -c "rm -rf ${name}; $<TARGET_FILE:hair25d-generate> ${args} > /dev/null 2> ${name}.err; status=$?; cat ${name}.err;
      test $status = ${code} && grep -Eq -- '${stderr}' ${name}.err ${one_line} && test ! -e ${name}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()

if(TARGET hair25d-generate)
  generate_status_test(count_zero 1
    "^hair25d-generate: --count: must be a whole number from 1 to 100000, not 0$"
    --count 0 -o count_zero)
  generate_status_test(count_not_a_number 1 "--count: .*not abc$" --count abc -o count_not_a_number)
  generate_status_test(shading_nine 1
    "^hair25d-generate: --shading: must be flat, two-tone, gradient, screentone or mixed, not 9$"
    --shading 9 -o shading_nine)
  generate_status_test(width_out_of_range 1 "^hair25d-generate: --width 10: must be in \\[64, 8192\\]$"
    --width 10 -o width_out_of_range)
  generate_status_test(width_beyond_int 1
    "^hair25d-generate: --width: must be a whole number \\(of at most 9 digits\\), not 99999999999$"
    --width 99999999999 -o width_beyond_int)
  generate_status_test(noise_not_a_number 1 "^hair25d-generate: --noise: must be a number, not x$"
    --noise x -o noise_not_a_number)
  generate_status_test(strands_negative 1 "^hair25d-generate: --strands -3: must be in \\[1, 400\\]$"
    --strands -3 -o strands_negative)
  generate_status_test(negative_seed 1 "--seed: must be a whole number .*not -1$"
    --seed -1 -o negative_seed)
  generate_status_test(unknown_option 2 "^hair25d-generate: The following argument was not expected: --bogus$"
    --bogus -o unknown_option)
  generate_status_test(missing_output 2 "^hair25d-generate: --output is required$" --count 1)
  # Shading names in any case, and mixed, are taken.
  add_test(NAME cli.generate_shading_names
    COMMAND bash -c "rm -rf shading_names && $<TARGET_FILE:hair25d-generate> --shading Two-Tone --width 96 --height 80 --strands 2 --line-width 2 -o shading_names > /dev/null &&
      $<TARGET_FILE:hair25d-generate> --shading mixed --width 96 --height 80 --strands 2 --line-width 2 --count 2 -o shading_names > /dev/null && test -s shading_names/case001/image.png"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endif()

# The same kinds of error in hair25d.
hair25d_cli_test(colour_tolerance_out_of_range_is_bad_input 1
  STDERR "^hair25d: --colour-tolerance: must be a number from 0 to 442, not 500$"
  ARGS segment ${case5}/image.png --hair-colour "#000000" --colour-tolerance 500 -o never)
hair25d_cli_test(head_not_a_number_is_bad_input 1
  STDERR "^hair25d: --head: X and Y must be numbers \\(pixels\\), not b$"
  ARGS model ${case5}/image.png --strokes ${case5}/strokes.json --head 3 b -o never)
hair25d_cli_test(unknown_option_of_a_command_is_usage 2
  STDERR "^hair25d: The following argument was not expected: --bogus$"
  ARGS segment ${case5}/image.png --bogus -o never)
hair25d_cli_test(missing_output_is_usage 2 STDERR "^hair25d: --output is required$"
  ARGS segment ${case5}/image.png)
hair25d_cli_test(model_without_hair_source_is_usage 2 STDERR "say which regions are hair"
  ARGS model ${case5}/image.png -o never)
