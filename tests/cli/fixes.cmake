# Audit fixes on the command line: writing through links and to standard
# output, a bad case found before any is scored, -q after the command, unknown
# commands named, defaults shown in --help.
set(annotated ${PROJECT_SOURCE_DIR}/tests/data/annotated)
set(hair25d $<TARGET_FILE:hair25d>)

# --json - is standard output: the JSON report only, no table after it.
add_test(NAME cli.eval_layering_json_to_stdout
  COMMAND bash -c "${hair25d} -q eval-layering ${annotated} --json - > json_stdout.out &&
    python3 -c 'import json,sys; d=json.load(open(\"json_stdout.out\")); sys.exit(0 if len(d[\"cases\"]) == 6 else 1)'"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# --json and --overlays through links: the links stay, their targets are
# written; /dev/stdout to a pipe gets the JSON and the table.
add_test(NAME cli.eval_layering_writes_through_links
  COMMAND bash -c "rm -rf links && mkdir links && cd links && touch real.json && ln -s real.json link.json &&
    mkdir ovl && ln -s ovl ovl_link &&
    ${hair25d} -q eval-layering ${annotated} --json link.json --overlays ovl_link > /dev/null &&
    test -L link.json && test -s real.json && test -L ovl_link && test -s ovl/case0.png &&
    ${hair25d} -q eval-layering ${annotated} --json /dev/stdout | cat > both.out &&
    grep -q '\"cases\"' both.out && grep -q '^total' both.out && test -z \"$(ls -A | grep tmp)\""
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# A truncated layering.json in the last case: refused before any case is
# scored (no progress line), the message naming the file.
add_test(NAME cli.eval_layering_checks_every_case_first
  COMMAND bash -c "rm -rf bad_cases && mkdir bad_cases && cp -r ${annotated}/case0 bad_cases/a &&
    cp -r ${annotated}/case1 bad_cases/b && head -c 100 ${annotated}/case1/layering.json > bad_cases/b/layering.json &&
    ${hair25d} eval-layering bad_cases > bad_cases.out 2> bad_cases.err; status=$?; cat bad_cases.err;
    test $status = 1 && grep -q 'b/layering.json' bad_cases.err && ! grep -q 'eval-layering:' bad_cases.err &&
    test ! -s bad_cases.out"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# -q after the command is the same as before it, and each command's --help
# lists it; a word naming no command is called unknown, the commands listed.
set(case5 ${PROJECT_SOURCE_DIR}/tests/data/annotated/case5)
add_test(NAME cli.quiet_after_the_command
  COMMAND bash -c "out=$(${hair25d} segment -q ${case5}/image.png --strokes ${case5}/strokes.json -o quiet_after 2>&1 >/dev/null); status=$?;
    test $status = 0 && test -z \"$out\" && test -s quiet_after/regions.png || { echo \"status $status stderr: $out\"; exit 1; }"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
foreach(command version segment eval-layering model)
  hair25d_cli_test(help_${command}_lists_quiet 0 STDOUT "-q,--quiet" ARGS ${command} --help)
endforeach()
hair25d_cli_test(unknown_command_is_named 2
  STDERR "unknown command 'studio'; the commands are: version, segment, eval-layering, model"
  ARGS studio)
hair25d_cli_test(unknown_command_after_quiet_is_named 2 STDERR "unknown command 'studio'"
  ARGS -q studio --help)

# --help shows the defaults; the tolerance is printed as given, not 40.000000.
hair25d_cli_test(help_shows_defaults 0 STDOUT "--colour-tolerance FLOAT:0-442=40 "
  ARGS segment --help)
add_test(NAME cli.generate_help_shows_defaults
  COMMAND bash -c "$<TARGET_FILE:hair25d-generate> --help | grep -q -- '--width INT=640'")
hair25d_cli_test(colour_tolerance_range_plain 1 STDERR "must be a number from 0 to 442, not 500$"
  ARGS segment ${case5}/image.png --hair-colour "#000000" --colour-tolerance 500 -o never)
hair25d_cli_test(colour_match_message_plain 1 STDERR "within 1 of #000001;"
  ARGS -q segment ${case5}/image.png --hair-colour "#000001" --colour-tolerance 1 -o never)
